using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>The render-pose API (PhysicsObj.PreviousPose / CurrentPose / GetRenderPose, PhysicsWorld.RenderTime): what it
/// records, the snap on a teleport, and misuse.</summary>
public sealed class RenderPoseApiTests
{
    [Theory]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    [InlineData(double.NegativeInfinity)]
    public void GetRenderPose_NonFiniteTime_Throws(double t)
    {
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var e = Assert.Throws<ArgumentException>(() => s.Player.GetRenderPose(t));
        Assert.Equal("renderTime", e.ParamName);
    }

    [Fact]
    public void RenderTime_IsTheClientClockOneGatePeriodBack()
    {
        // CurrentTime - MinQuantum, MinQuantum = 1/30 s (PhysicsGlobals.MinQuantum, acclient.c:311334's gate).
        var world = new PhysicsWorld(5.0);
        Assert.Equal(5.0 - 1.0 / 30.0, world.RenderTime);
        world.Tick(7.25);
        Assert.Equal(7.25 - 1.0 / 30.0, world.RenderTime);
    }

    [Fact]
    public void Poses_AreTheUpdatesStartAndEnd_WithTheirTimes()
    {
        // Walking at 3.12 m/s, ticks at 1/30 s multiples: the update at t = 0.1 starts from the pose of t = 1/15 and moves
        // 3.12 / 30 = 0.104 m. Each time is the object's UpdateTime before and after its update.
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        s.Walk();
        s.World.Tick(1.0 / 30.0);
        s.World.Tick(2.0 / 30.0);
        Position before = s.Player.Position;
        s.World.Tick(3.0 / 30.0);
        Assert.Equal(before, s.Player.PreviousPose);
        Assert.Equal(s.Player.Position, s.Player.Position);
        Assert.Equal(2.0 / 30.0, s.Player.PreviousPoseTime);
        Assert.Equal(3.0 / 30.0, s.Player.CurrentPoseTime);
        Assert.Equal(3.12f / 30f, s.Player.Position.Frame.Origin.Y - s.Player.PreviousPose.Frame.Origin.Y, 4);

        // Half way in time: half way in space; before and after the pair: its ends (no extrapolation).
        double mid = (2.0 / 30.0 + 3.0 / 30.0) / 2.0;
        float midY = (s.Player.PreviousPose.Frame.Origin.Y + s.Player.Position.Frame.Origin.Y) / 2f;
        Assert.Equal(midY, s.Player.GetRenderPose(mid).Frame.Origin.Y, 5);
        Assert.Equal(s.Player.PreviousPose, s.Player.GetRenderPose(0.0));
        Assert.Equal(s.Player.Position, s.Player.GetRenderPose(1.0));
        Assert.Equal(s.Player.Position, s.Player.GetRenderPose(3.0 / 30.0));
    }

    [Fact]
    public void Rotation_IsBlendedSpherically_HalfWayInTime_HalfTheTurn()
    {
        // Turning right in place (TurnRight): over one update the heading goes from h0 to h1 (a few degrees); half way in time
        // the drawn heading is half way, (h0 + h1) / 2 (a slerp about one axis moves the angle linearly), the origin unchanged.
        var s = new WalkingPlayerScene(new Vector3(100f, 100f, 0f));
        s.Movement.DoMotion(AcDream.Core.Physics.Motion.MotionCommand.TurnRight, new AcDream.Core.Physics.Motion.MovementParameters());
        for (int i = 1; i <= 10; i++)
        {
            s.World.Tick(i / 30.0);
        }

        double h0 = s.Player.PreviousPose.Frame.Heading, h1 = s.Player.Position.Frame.Heading;
        Assert.True(h1 - h0 > 1.0, $"the player turned ({h0} -> {h1})");
        Position mid = s.Player.GetRenderPose((s.Player.PreviousPoseTime + s.Player.CurrentPoseTime) / 2.0);
        Assert.Equal((h0 + h1) / 2.0, mid.Frame.Heading, 3);
        Assert.Equal(s.Player.Position.Frame.Origin.X, mid.Frame.Origin.X, 4);
    }

    [Fact]
    public void Teleport_BetweenTicks_IsDrawnAtOnce_AndNeverBlendedFromTheOldPlace()
    {
        // Walking north from (100, 20); after 1 s the client teleports the player 100 m east. From that frame on the drawn pose
        // is at the destination (answered from Position until the next update records it), and every later blend lies
        // between the destination and the walk onwards from it: within 3.12 m/s · (1 s) of it, never back near x = 100.
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        s.Walk();
        for (int i = 1; i <= 60; i++)
        {
            s.World.Tick(i / 60.0);
        }

        var dest = new Position(LandDefs.OutdoorCellId(0xA9B4FFFF, 180f, 60f), Frame.FromHeading(new Vector3(180f, 60f, 0f), 0.0));
        Assert.Equal(SetPositionError.Ok, s.Player.SetPositionSimple(dest, true));
        Position atOnce = s.Player.GetRenderPose(s.World.RenderTime);
        Assert.True(s.Player.IsPlacedSinceLastUpdate);
        Assert.Equal(s.Player.Position, atOnce);
        Assert.Equal(180f, atOnce.Frame.Origin.X, 3);
        for (int i = 61; i <= 120; i++)
        {
            s.World.Tick(i / 60.0);
            Position drawn = s.Player.GetRenderPose(s.World.RenderTime);
            Assert.Equal(180f, drawn.Frame.Origin.X, 3);
            Assert.InRange(drawn.Frame.Origin.Y, 60f - 0.01f, 60f + 3.13f);
        }
    }

    [Fact]
    public void Teleport_DuringTheObjectsUpdate_IsNotBlended()
    {
        // A placement inside the object's own update (here from the step observer; in play a blip of the interpolation
        // manager or a teleport hook): the update's pose pair is both the end pose, drawn as is at any render time.
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        s.Walk();
        s.World.Tick(1.0 / 30.0);
        s.World.Tick(2.0 / 30.0);
        var dest = new Position(LandDefs.OutdoorCellId(0xA9B4FFFF, 20f, 150f), Frame.FromHeading(new Vector3(20f, 150f, 0f), 0.0));
        s.World.StepObserver = new TeleportOnce(dest);
        s.World.Tick(3.0 / 30.0);
        s.World.StepObserver = null;
        Assert.Equal(s.Player.Position, s.Player.PreviousPose);
        Assert.Equal(s.Player.Position, s.Player.GetRenderPose(2.5 / 30.0));
        Assert.InRange(s.Player.GetRenderPose(2.5 / 30.0).Frame.Origin.X, 19.9f, 20.1f);
    }

    [Fact]
    public void NewObject_BeforeAnyUpdate_IsDrawnWhereItStands()
    {
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        Assert.True(s.Player.IsPlacedSinceLastUpdate);
        Assert.Equal(s.Player.Position, s.Player.GetRenderPose(0.0));
        Assert.Equal(s.Player.Position, s.Player.GetRenderPose(-100.0));
    }

    private sealed class TeleportOnce(Position dest) : IStepObserver
    {
        private bool _done;

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            if (!_done)
            {
                _done = true;
                obj.SetPositionSimple(dest, true);
            }
        }
    }
}
