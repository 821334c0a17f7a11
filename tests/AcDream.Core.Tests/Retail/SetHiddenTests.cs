using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CPhysicsObj::set_state</c> (acclient.c:322171) runs <c>set_hidden</c> (322077) when HIDDEN (0x4000) changes: hidden,
/// the object gains IGNORE_COLLISIONS (0x10) and loses REPORT_COLLISIONS (0x8) after ending the collisions in progress, and
/// its children gain NODRAW (0x20); shown, it loses IGNORE_COLLISIONS, gains REPORT_COLLISIONS again (reporting what it still
/// touches) and the children lose NODRAW.
/// </summary>
public class SetHiddenTests
{
    [Fact]
    public void HidingAndShowing_SetsRetailsStateBits_OnTheObjectAndItsChildren()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        PhysicsObj a = ObjectScene.Creature(world, 1, ObjectScene.At(10f, 10f));
        PhysicsObj child = ObjectScene.Creature(world, 2, ObjectScene.At(20f, 10f));
        Assert.True(child.SetParent(a, 0, Frame.Identity));
        a.SetState(a.State | PhysicsState.ReportCollisions);
        PhysicsState before = a.State;

        a.SetState(a.State | PhysicsState.Hidden);
        Assert.Equal((before | PhysicsState.Hidden | PhysicsState.IgnoreCollisions) & ~PhysicsState.ReportCollisions, a.State);
        Assert.Equal(PhysicsState.NoDraw, child.State & PhysicsState.NoDraw);

        a.SetState(a.State & ~PhysicsState.Hidden);
        Assert.Equal(before, a.State);
        Assert.Equal((PhysicsState)0, child.State & PhysicsState.NoDraw);
    }

    [Fact]
    public void ShowingAnObjectThatDidNotReportCollisions_MakesItReportThem()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        PhysicsObj a = ObjectScene.Creature(world, 1, ObjectScene.At(10f, 10f));
        a.SetState((a.State | PhysicsState.Hidden) & ~PhysicsState.ReportCollisions);
        Assert.Equal(PhysicsState.IgnoreCollisions, a.State & PhysicsState.IgnoreCollisions);
        a.SetState(a.State & ~PhysicsState.Hidden);
        Assert.Equal(PhysicsState.ReportCollisions, a.State & (PhysicsState.ReportCollisions | PhysicsState.IgnoreCollisions));
    }

    [Fact]
    public void ASetStateThatDoesNotChangeHidden_ChangesOnlyTheBitsGiven()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        PhysicsObj a = ObjectScene.Creature(world, 1, ObjectScene.At(10f, 10f));
        PhysicsState s = (a.State | PhysicsState.Ethereal) & ~PhysicsState.ReportCollisions;
        a.SetState(s);
        Assert.Equal(s, a.State);
    }
}
