using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Issue #23: the transition a sweep ends with reaches the commit that reads it, and no other. Before the fix the commit's
/// collision response and shadow update read the sweep's shared "last transition", which the next sweep or placement of
/// any object replaced: a collision listener that placed another object made the reporter bounce by, and cast its shadows
/// into the cells of, the other object's placement; a client's <see cref="PhysicsObj.CommitTransition"/> reported the
/// collisions of whichever object swept last.
/// </summary>
public class TransitionHandOffTests
{
    private sealed class PlaceOnReport(PhysicsObj other, Position at) : ICollisionListener
    {
        public int Count;

        public void OnEnvironmentCollision(PhysicsObj obj, in EnvCollisionProfile profile)
        {
            Count++;
            Assert.Equal(SetPositionError.Ok, other.SetPosition(at, SetPositionFlags.Placement));
        }
    }

    private static List<uint> ShadowCells(PhysicsObj obj)
    {
        var ids = new List<uint>();
        foreach (ShadowObj s in obj.ShadowObjects)
        {
            ids.Add(s.CellId);
        }

        ids.Sort();
        return ids;
    }

    [Fact]
    public void ACollisionListener_ThatPlacesAnotherObject_LeavesTheReportersCommitAlone()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        PhysicsObj jumper = SweepScene.Walker(world, ObjectScene.At(100f, 100f), id: 1);
        PhysicsObj other = SweepScene.Walker(world, ObjectScene.At(20f, 170f), id: 2);
        var listener = new PlaceOnReport(other, ObjectScene.At(20f, 170f));
        sweep.CollisionListener = listener;

        // The jump of CollisionResponseTests.JumpLanding_ReportsEachLandingOnce: it lands at 5.47 m/s, bounces 0.273 m/s
        // (CollisionInfo's collision normal, read after the report), hops and lands again: two landings, two reports. Each
        // report places the other object (a placement, a transition of its own) in cell (0, 7), 110 m away.
        jumper.SetVelocity(new Vector3(0f, 0f, 5f));
        SweepScene.Run(world, 60);

        Assert.Equal(2, listener.Count);
        // The jumper (sphere r = 0.5 at x = y = 100, 4 m inside cell (4, 4)) is shadowed in its own cell only; the other
        // object in its cell (0, 7) only.
        Assert.Equal(new List<uint> { ObjectScene.Cell(100f, 100f) }, ShadowCells(jumper));
        Assert.Equal(new List<uint> { ObjectScene.Cell(20f, 170f) }, ShadowCells(other));
        Assert.Equal(ObjectScene.GroundZ, jumper.Position.Frame.Origin.Z);
    }

    private sealed class Recorder : ICollisionListener
    {
        public readonly List<uint> Reporters = new();

        public void OnEnvironmentCollision(PhysicsObj obj, in EnvCollisionProfile profile) => Reporters.Add(obj.Id);
    }

    [Fact]
    public void AClientCommit_InARetailSweepWorld_ReportsNoOtherObjectsCollisions_AndShadowsWhereItStands()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        var recorder = new Recorder();
        sweep.CollisionListener = recorder;
        PhysicsObj jumper = SweepScene.Walker(world, ObjectScene.At(100f, 100f), id: 1);
        PhysicsObj client = SweepScene.Walker(world, ObjectScene.At(20f, 170f), id: 2);
        recorder.Reporters.Clear();

        // The jumper's first landing: its sweep collided with the terrain (a report for object 1).
        jumper.SetVelocity(new Vector3(0f, 0f, 5f));
        while (recorder.Reporters.Count == 0)
        {
            SweepScene.Run(world, 1);
        }

        Assert.Equal(new List<uint> { 1u }, recorder.Reporters);

        // A client's own sweep result for object 2, falling at 3 m/s: 2 m east and 1 m up in free space (no contact plane,
        // no collision normal). It carries no collision, so nothing is reported for object 2 and its velocity is not
        // bounced (the jumper's landing normal (0, 0, 1) with elasticity 0.05 would turn -3 into -3 + 3 * 1.05 = 0.15 m/s);
        // its shadow follows it to (22, 170), still cell (0, 7).
        client.SetVelocity(new Vector3(0f, 0f, -3f));
        Position to = ObjectScene.At(22f, 170f, ObjectScene.GroundZ + 1f);
        client.CommitTransition(TransitionResult.FreeSpace(to));

        Assert.Equal(new List<uint> { 1u }, recorder.Reporters);
        Assert.Equal(new Vector3(0f, 0f, -3f), client.Velocity);
        Assert.Equal(new List<uint> { ObjectScene.Cell(22f, 170f) }, ShadowCells(client));
    }
}
