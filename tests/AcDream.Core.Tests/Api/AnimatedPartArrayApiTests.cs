using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary><see cref="AnimatedPartArray"/> and <see cref="MotionTablePlayer"/>: argument checks before anything changes, and
/// the parts' frames a client draws with.</summary>
public class AnimatedPartArrayApiTests
{
    private const uint NonCombat = 0x8000003Du, Ready = 0x41000003u;

    private static SetupPhysics Setup() => new(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) },
        ReadOnlySpan<CylSphere>.Empty, 0.5f, 2f, 0.6f, 0.6f);

    // A two-part Ready cycle of one frame: part 0 at (0, 0, 1), part 1 at (0.5, 0, 1) turned 90° about z.
    private static (MotionTable, AnimationLibrary) TwoParts()
    {
        MotionTable table = MotionTable.UnPack(new MotionTableBytes { DefaultStyle = NonCombat }
            .StyleDefault(NonCombat, Ready)
            .Cycle(NonCombat, Ready, MotionDataSpec.One(0x03000001, 0, -1, 30f))
            .ToArray());
        var lib = new AnimationLibrary();
        float h = MathF.Sqrt(0.5f);
        lib.Add(AnimClip.UnPack(new AnimationBytes(0x03000001, 2).Frame()
            .Part(0, new Vector3(0f, 0f, 1f), Quaternion.Identity)
            .Part(1, new Vector3(0.5f, 0f, 1f), new Quaternion(0f, 0f, h, h))
            .ToArray()));
        return (table, lib);
    }

    [Fact]
    public void Constructor_RefusesBadArguments()
    {
        Assert.Throws<ArgumentNullException>(() => new AnimatedPartArray(null!, 1, null, null));
        Assert.Throws<ArgumentOutOfRangeException>(() => new AnimatedPartArray(Setup(), 0, null, null));
        var ex = Assert.Throws<ArgumentException>(() => new AnimatedPartArray(Setup(), 2, null, null, new[] { AFrame.Identity }));
        Assert.Equal("placementFrames", ex.ParamName);
        Assert.Throws<ArgumentNullException>(() => new MotionTablePlayer(null!));
    }

    [Fact]
    public void WithoutATable_MotionsFailWithNoMotionTable_7()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject(1);
        var parts = new AnimatedPartArray(Setup(), 1, null, null);
        obj.PartArray = parts;
        Assert.Null(parts.MotionPlayer);
        // CPartArray::DoInterpretedMotion without a motion-table manager: 7 (acclient.c:326017).
        Assert.Equal(MotionError.NoMotionTable, obj.DoInterpretedMotion(MotionCommand.WalkForward, new MovementParameters()));
    }

    [Fact]
    public void OnePartArrayBelongsToOneObject()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj a = world.CreateObject(1), b = world.CreateObject(2);
        var parts = new AnimatedPartArray(Setup(), 1, null, null);
        a.PartArray = parts;
        Assert.Throws<ArgumentException>(() => b.PartArray = parts);
        Assert.Null(b.PartArray);
        a.PartArray = null;
        b.PartArray = parts;   // released by its first object
        Assert.Same(parts, b.PartArray);
    }

    [Fact]
    public void PartFrames_AreThePlayingAnimationFrames_PlacedOnTheObject()
    {
        (MotionTable table, AnimationLibrary lib) = TwoParts();
        var parts = new AnimatedPartArray(Setup(), 2, table, lib);
        parts.Player!.InitializeMotionTables();   // SetDefaultState: the Ready cycle plays
        Assert.Equal(new Vector3(0.5f, 0f, 1f), parts.GetPartLocalFrame(1).Origin);

        // The object at (10, 20, 30) facing 90° (rotated +90° about z: its local +x is world +y): part 1's origin
        // (0.5, 0, 1) lands at (10, 20.5, 31), and the part's heading is the object's turned 90° more.
        var frame = Frame.FromHeading(new Vector3(10f, 20f, 30f), 0.0);
        frame.Rotate(new Vector3(0f, 0f, MathF.PI / 2f));
        parts.SetFrame(frame);
        Span<Frame> frames = stackalloc Frame[2];
        parts.CopyPartFrames(frames);
        Assert.Equal(new Vector3(10f, 20f, 31f), frames[0].Origin);
        Assert.Equal(10f, frames[1].Origin.X, 5);
        Assert.Equal(20.5f, frames[1].Origin.Y, 5);
        Assert.Equal(31f, frames[1].Origin.Z, 5);
        Assert.Equal(frames[1].Origin, parts.GetPartFrame(1).Origin);
        // Scale 2 scales the part's offset from the object (CPartArray::UpdateParts with scale): (1, 0, 2) in the object.
        // SetScaleInternal (acclient.c:326181) only stores the scale: the parts move at the next SetFrame.
        parts.SetScale(2f);
        Assert.Equal(20.5f, parts.GetPartFrame(1).Origin.Y, 5);
        parts.SetFrame(frame);
        Assert.Equal(10f, parts.GetPartFrame(1).Origin.X, 5);
        Assert.Equal(21f, parts.GetPartFrame(1).Origin.Y, 5);
        Assert.Equal(32f, parts.GetPartFrame(1).Origin.Z, 5);
        Assert.Equal(1f, parts.Radius);   // 0.5 × scale.z
        Assert.Equal(4f, parts.Height);   // 2 × scale.z

        Assert.Throws<ArgumentOutOfRangeException>(() => parts.GetPartFrame(2));
        Assert.Throws<ArgumentOutOfRangeException>(() => parts.GetPartLocalFrame(-1));
        Assert.Throws<ArgumentException>(() => parts.CopyPartFrames(new Frame[1]));
    }

    [Fact]
    public void WithoutAnimations_ThePartsAreWhereThePlacementFramePutsThem()
    {
        var placement = new[] { new AFrame(new Vector3(0f, 0f, 1f), Quaternion.Identity) };
        var parts = new AnimatedPartArray(Setup(), 1, null, null, placement);
        Assert.Equal(new Vector3(0f, 0f, 1f), parts.GetPartLocalFrame(0).Origin);
        parts.SetFrame(Frame.FromHeading(new Vector3(5f, 5f, 5f), 0.0));
        Assert.Equal(new Vector3(5f, 5f, 6f), parts.GetPartFrame(0).Origin);
    }
    [Fact]
    public void Update_RefusesANonFiniteOrHugeQuantum_AndChangesNothing()
    {
        // Issue #34 item 6: Update(NaN) was accepted and left the sequence's frame number NaN for good.
        (MotionTable table, AnimationLibrary lib) = TwoParts();
        var parts = new AnimatedPartArray(Setup(), 2, table, lib);
        parts.Player!.InitializeMotionTables();
        Frame f = Frame.Identity;
        parts.Update(0.05f, ref f);   // 1.5 frames of the one-frame cycle at 30 fps: frame number 0.5
        double before = parts.Sequence.FrameNumber;
        Assert.Equal(0.5, before, 6);
        foreach (float bad in new[] { float.NaN, float.PositiveInfinity, float.NegativeInfinity, 2.0000002f, -2.0000002f, 1e30f })
        {
            Frame g = Frame.Identity;
            var ex = Assert.Throws<ArgumentException>(() => parts.Update(bad, ref g));
            Assert.Equal("quantum", ex.ParamName);
            Assert.Equal(BitConverter.DoubleToInt64Bits(before), BitConverter.DoubleToInt64Bits(parts.Sequence.FrameNumber));
            Assert.Equal(Frame.Identity.Origin, g.Origin);
        }

        // The bound itself (2 s, PhysicsGlobals.HugeQuantum) is accepted: 60 frames of the one-frame cycle.
        parts.Update(2f, ref f);
        Assert.True(double.IsFinite(parts.Sequence.FrameNumber));
    }

    [Fact]
    public void PartsTheAnimationFrameDoesNotCover_StayWhereTheyWere()
    {
        // CPartArray::UpdateParts (acclient.c:326600) combines the parts the current animation frame covers (the fewer of
        // the part array's and the frame's part counts) and leaves the others' frames as they were. Two-part object: a
        // two-part clip places part 1 at the object's (10, 0, 0) + (1, 0, 0); then a one-part clip plays and the object
        // moves to (20, 0, 0): part 0 follows it, part 1 stays at (11, 0, 0) (it was reported at the object's frame).
        const uint twoPart = 0x03000021, onePart = 0x03000022;
        var lib = new AnimationLibrary();
        lib.Add(new AnimationBytes(twoPart, 2).Frame().Build());   // parts at (0, 0, 0) and (1, 0, 0)
        lib.Add(new AnimationBytes(onePart, 1).Frame().Build());   // part 0 at (0, 0, 0)
        var parts = new AnimatedPartArray(Setup(), 2, null, lib);
        parts.Sequence.AppendAnimation(new AnimData(twoPart, 0, -1, 30f));
        parts.SetFrame(Frame.FromHeading(new Vector3(10f, 0f, 0f), 0.0));
        Assert.Equal(new Vector3(11f, 0f, 0f), parts.GetPartFrame(1).Origin);

        parts.Sequence.ClearAnimations();
        parts.Sequence.AppendAnimation(new AnimData(onePart, 0, -1, 30f));
        parts.SetFrame(Frame.FromHeading(new Vector3(20f, 0f, 0f), 0.0));
        Assert.Equal(new Vector3(20f, 0f, 0f), parts.GetPartFrame(0).Origin);
        Assert.Equal(new Vector3(11f, 0f, 0f), parts.GetPartFrame(1).Origin);
        Span<Frame> frames = stackalloc Frame[2];
        parts.CopyPartFrames(frames);
        Assert.Equal(new Vector3(20f, 0f, 0f), frames[0].Origin);
        Assert.Equal(new Vector3(11f, 0f, 0f), frames[1].Origin);

        // Before any SetFrame covered it, a part is at the identity (retail's CPhysicsPart frame as made).
        var fresh = new AnimatedPartArray(Setup(), 2, null, lib);
        fresh.Sequence.AppendAnimation(new AnimData(onePart, 0, -1, 30f));
        fresh.SetFrame(Frame.FromHeading(new Vector3(20f, 0f, 0f), 0.0));
        Assert.Equal(Vector3.Zero, fresh.GetPartFrame(1).Origin);
    }

    [Fact]
    public void ThePlacementFrame_IsLabelledEntry0_UnlessTheCallerNamesIt()
    {
        // CPartArray::CreateSetup asks SetPlacementFrame for entry 0x65 (Resting); a setup without one falls back to entry 0
        // (Default) and the sequence records id 0 (acclient.c:326817). The constructor's frames are labelled 0 by default.
        var placement = new[] { new AFrame(new Vector3(0f, 0f, 1f), Quaternion.Identity) };
        var parts = new AnimatedPartArray(Setup(), 1, null, null, placement);
        Assert.Equal(0u, parts.Sequence.PlacementFrameId);
        var resting = new AnimatedPartArray(Setup(), 1, null, null, placement, placementId: 0x65);
        Assert.Equal(0x65u, resting.Sequence.PlacementFrameId);
    }
}
