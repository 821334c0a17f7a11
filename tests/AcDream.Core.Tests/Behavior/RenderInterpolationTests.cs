using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Render interpolation (issue #24): the world gate moves objects at most 30 times a second, at a cadence set by the gate's
/// phase against the frame clock; drawing <c>GetRenderPose(world.RenderTime)</c> gives evenly spaced poses at any frame rate.
/// </summary>
public sealed class RenderInterpolationTests
{
    /// <summary>The frame clocks of the issue's table: frame i at i / fps seconds (as a client computing time from a frame
    /// count), and 60 fps with a deterministic ±0.3 ms jitter, 0.3 ms · sin(i).</summary>
    public static TheoryData<string> FrameClocks => new() { "30", "59.94", "60", "60 jitter", "144" };

    private static double FrameTime(string clock, int i) => clock switch
    {
        "30" => i / 30.0,
        "59.94" => i / 59.94,
        "60" => i / 60.0,
        "60 jitter" => i / 60.0 + 0.0003 * Math.Sin(i),
        "144" => i / 144.0,
        _ => throw new ArgumentOutOfRangeException(nameof(clock)),
    };

    private static double Fps(string clock) => clock switch
    {
        "30" => 30.0,
        "59.94" => 59.94,
        "144" => 144.0,
        _ => 60.0,
    };

    [Theory]
    [InlineData("30", 16.0)]
    [InlineData("59.94", 29.9)]
    [InlineData("60", 20.9)]
    [InlineData("60 jitter", 24.5)]
    [InlineData("144", 28.8)]
    public void Cadence_PositionChangesPerSecondOfWalking_AreTheIssuesTable(string clock, double perSecond)
    {
        // The issue's table. The world updates at the first frame whose client time is at least MinQuantum = 1/30 s past the
        // last update (CPhysics::UseTime, acclient.c:311334), the difference taken in double:
        //  - 30 fps: i/30 - (i-1)/30 rounds below 1/30 for some i, so gaps are 1 or 2 frames: 16.0 updates/s, not 30;
        //  - 59.94 fps: 2 frames = 33.37 ms > 1/30 always: 29.97 -> 29.9 in 10 s (299 updates);
        //  - 60 fps: 2/60 rounds below 1/30 about as often as not, gaps 2 or 3 frames: 20.9/s;
        //  - 144 fps: 4 frames = 27.8 ms < 1/30 < 5 frames = 34.7 ms: 144 / 5 = 28.8/s;
        //  - 60 fps ± 0.3 ms: whether 2 frames reach 1/30 s depends on the jitter's sign, gaps 2 or 3 frames; with this
        //    test's jitter 0.3 ms · sin(i) 24.5/s (the issue's 23.9 came from its own, unstated jitter sequence).
        // The speed is right in every case; only the cadence differs.
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        s.Walk();
        int frames = (int)Math.Round(10.0 * Fps(clock));
        int changes = 0;
        Position last = s.Player.Position;
        for (int i = 1; i <= frames; i++)
        {
            s.World.Tick(FrameTime(clock, i));
            if (s.Player.Position != last)
            {
                changes++;
                last = s.Player.Position;
            }
        }

        Assert.Equal(perSecond, changes / 10.0, 3);
    }

    [Theory]
    [MemberData(nameof(FrameClocks))]
    public void BlendedPose_OfAWalkingPlayer_AdvancesInEqualStepsPerFrame_PhysicsUnchanged(string clock)
    {
        // A player walks north at v = 3.12 m/s on flat ground. Its physics pose moves at each world update t_k by v (t_k -
        // t_k-1) (one whole step per update, dt <= MaxQuantum), so the physics path y(t) is linear: y_k = y_0 + v (t_k - t_0).
        // The blend is the straight line through the two last poses, evaluated at RenderTime = now - 1/30, which always lies
        // between their times (PhysicsWorld.RenderTime): the drawn y is y_0 + v (now_i - 1/30 - t_0), and its step per frame
        // is v (now_i - now_i-1) exactly: v / fps at a steady clock (0.104 m at 30 fps, 0.052 m at 60, 0.0217 m at 144), and
        // v (1/60 ± 0.6 ms) under the ±0.3 ms jitter (the drawn step follows the clock the client passes).
        // Tolerance: the physics poses are floats near y = 20..60 m, each update adding one rounded offset: consecutive
        // poses err by at most ulp(64) / 2 = 3.8e-6 m from the straight line plus the offset's own rounding (3.12 f dt in
        // float: < 1e-8 m), and a drawn step is a difference of two blends of such poses: |error| <= 2 · 2 · 3.8e-6 =
        // 1.5e-5 m. Bound used: 2e-5 m (0.04 % of the 60 fps step), against unblended steps of 0 and 2 or 3 frames' travel.
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var reference = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        s.Walk();
        reference.Walk();
        double fps = Fps(clock);
        int frames = (int)Math.Round(10.0 * fps);
        int warmUp = (int)Math.Round(fps);      // the first second: the walk starts, the first update pair forms
        double previousY = double.NaN, previousNow = double.NaN;
        double minStep = double.MaxValue, maxStep = double.MinValue, worst = 0.0;
        int rawStills = 0;
        Position rawLast = s.Player.Position;
        for (int i = 1; i <= frames; i++)
        {
            double now = FrameTime(clock, i);
            s.World.Tick(now);
            reference.World.Tick(now);
            Position drawn = s.Player.GetRenderPose(s.World.RenderTime);
            Assert.Equal(reference.Player.Position, s.Player.Position);       // reading the blend changes no physics
            if (s.Player.Position == rawLast)
            {
                rawStills++;
            }

            rawLast = s.Player.Position;
            double y = WalkingPlayerScene.GlobalY(drawn);
            if (i > warmUp)
            {
                double step = y - previousY;
                double expected = WalkingPlayerScene.WalkSpeed * (now - previousNow);
                worst = Math.Max(worst, Math.Abs(step - expected));
                minStep = Math.Min(minStep, step);
                maxStep = Math.Max(maxStep, step);
            }

            previousY = y;
            previousNow = now;
        }

        Assert.True(worst <= 2e-5, $"{clock}: a drawn step differs from v * frame time by {worst:E2} m");
        double nominal = WalkingPlayerScene.WalkSpeed / fps;
        double jitter = clock == "60 jitter" ? WalkingPlayerScene.WalkSpeed * 0.0006 : 0.0;   // |Δ(0.3 ms sin i)| <= 0.6 ms
        Assert.InRange(minStep, nominal - jitter - 2e-5, nominal + 2e-5);
        Assert.InRange(maxStep, nominal - 2e-5, nominal + jitter + 2e-5);
        if (clock != "59.94")
        {
            Assert.True(rawStills > 0, "the unblended physics pose stands still on some frames (the judder the blend removes)");
        }
    }

    [Fact]
    public void BlendedPose_AcrossALandblockEdge_StaysEvenlySpaced_AndNamesTheCellUnderIt()
    {
        // Walking north from y = 185 in 0xA9B4 crosses into 0xA9B5 (its y restarts at 0) after 7 / 3.12 = 2.24 s. The blend is
        // taken in the current pose's landblock frame, so the drawn global y keeps stepping v / 60 = 0.052 m per frame, and the
        // drawn cell is the outdoor cell under the drawn point (column 4, row 7 in 0xA9B4: 0xA9B40025 + 3 = 0xA9B40028; then
        // row 0 in 0xA9B5: 0xA9B50021).
        var s = new WalkingPlayerScene(new Vector3(100f, 185f, 0f));
        s.Walk();
        double previousY = double.NaN;
        var cells = new List<uint>();
        for (int i = 1; i <= 240; i++)
        {
            s.World.Tick(i / 60.0);
            Position drawn = s.Player.GetRenderPose(s.World.RenderTime);
            Assert.Equal(LandDefs.OutdoorCellId(drawn.ObjCellId, drawn.Frame.Origin.X, drawn.Frame.Origin.Y), drawn.ObjCellId);
            if (cells.Count == 0 || cells[^1] != drawn.ObjCellId)
            {
                cells.Add(drawn.ObjCellId);
            }

            double y = WalkingPlayerScene.GlobalY(drawn);
            if (i > 60)
            {
                Assert.Equal(WalkingPlayerScene.WalkSpeed / 60.0, y - previousY, 4);
            }

            previousY = y;
        }

        Assert.Equal(new uint[] { 0xA9B40028u, 0xA9B50021u }, cells);
    }

    [Fact]
    public void BlendedPose_AcrossACellEdge_SwitchesCellWhereTheDrawnPointCrosses()
    {
        // From y = 40 (column 4, row 1: 4 · 8 + 1 + 1 = 0x22) the walker crosses y = 48 into row 2 (0xA9B40023) after 8 / 3.12 = 2.56 s of
        // walking. The drawn pose, 1/30 s behind, crosses when its own y does: each frame's cell is the cell of its own point.
        var s = new WalkingPlayerScene(new Vector3(100f, 40f, 0f));
        s.Walk();
        bool crossed = false;
        for (int i = 1; i <= 240; i++)
        {
            s.World.Tick(i / 60.0);
            Position drawn = s.Player.GetRenderPose(s.World.RenderTime);
            uint expected = drawn.Frame.Origin.Y < 48f ? 0xA9B40022u : 0xA9B40023u;
            Assert.Equal(expected, drawn.ObjCellId);
            crossed |= drawn.ObjCellId == 0xA9B40023u && s.Player.PreviousPose.ObjCellId == 0xA9B40022u;
        }

        Assert.True(crossed, "some frame blends a pose pair that straddles the cell edge");
    }
}
