using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using Xunit;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// Issue #15 item 11: an animation velocity (SimplePartArray.SequenceVelocity) above 50 m/s is refused (retail's max velocity,
/// the clamp of set_velocity and UpdatePhysicsInternal, acclient.c:318577 and 319988's callee); the physics velocity is
/// clamped to 50 m/s as retail. Before the fix an 8,000 km-per-tick sequence velocity moved a walker out of its landblock
/// while it kept its land cell id. An object's outdoor cell always contains its origin.
/// </summary>
public class VelocityBoundTests
{
    // 8,000 km in one 0.05 s tick: 1.6e8 m/s.
    private static readonly Vector3 Absurd = new(0f, 1.6e8f, 0f);

    /// <summary>True when outdoor cell <paramref name="id"/> contains landblock-local origin <paramref name="o"/>:
    /// x, y in [0, 192) and cell = column × 8 + row + 1 with column = ⌊x / 24⌋, row = ⌊y / 24⌋ (LandDefs).</summary>
    private static bool CellContains(uint id, Vector3 o)
    {
        if (!(o.X >= 0f && o.X < 192f && o.Y >= 0f && o.Y < 192f))
        {
            return false;
        }

        uint cell = (uint)((int)Math.Floor(o.X / 24.0) * 8 + (int)Math.Floor(o.Y / 24.0) + 1);
        return (id & 0xFFFFu) == cell;
    }

    [Fact]
    public void SequenceVelocity_8000KmPerTick_IsRefused_StateUnchanged()
    {
        var s = new MisuseScene();
        PublicState before = PublicState.Capture(s);
        Assert.Throws<ArgumentException>(() => s.WalkerParts.SequenceVelocity = Absurd);
        Assert.Empty(PublicState.Diff(before, PublicState.Capture(s)));
        s.Tick(1);
        Assert.True(CellContains(s.Walker.CellId, s.Walker.Position.Frame.Origin));
    }

    [Fact]
    public void SequenceVelocity_Bound_Is50MetresPerSecond()
    {
        // 50 m/s is accepted; the next float above (50 + 2^-18 · 2 = 50.000004) is refused. A diagonal of speed 50: 30, 40.
        var s = new MisuseScene();
        s.WalkerParts.SequenceVelocity = new Vector3(0f, 50f, 0f);
        s.WalkerParts.SequenceVelocity = new Vector3(30f, 40f, 0f);
        Assert.Throws<ArgumentException>(() => s.WalkerParts.SequenceVelocity = new Vector3(0f, BitIncrement(50f), 0f));
        Assert.Equal(PhysicsGlobals.MaxVelocity, InputLimits.MaxSequenceSpeed);
    }

    [Fact]
    public void WalkerAtTheBound_KeepsItsCellContainingItsOrigin_EveryTick()
    {
        // 50 m/s north for 30 ticks of 0.05 s: 2.5 m per tick, 75 m in all, from y = 10 to y = 85 of the same landblock,
        // crossing cell rows at y = 24, 48 and 72; after every tick the cell id is the cell under the origin.
        var s = new MisuseScene();
        PhysicsObj w = s.Walker;
        w.SetPositionSimple(MisuseScene.At(100f, 10f), true);
        w.StopInterpolating();
        w.PositionManager!.StopConstraining();
        w.StopSticking();
        s.WalkerParts.SequenceVelocity = new Vector3(0f, 50f, 0f);
        for (int i = 0; i < 30; i++)
        {
            s.Tick(1);
            Assert.True(CellContains(w.CellId, w.Position.Frame.Origin), $"tick {i}: cell {w.CellId:X8} at {w.Position.Frame.Origin}");
        }

        Assert.True(w.Position.Frame.Origin.Y > 72f, $"walked to {w.Position.Frame.Origin}");
    }

    [Fact]
    public void SetVelocity_8000KmPerTick_IsClampedTo50_AsRetail()
    {
        // retail: CPhysicsObj::set_velocity (acclient.c:318577) scales a velocity above 50 m/s to 50 m/s.
        var s = new MisuseScene();
        s.Other.SetVelocity(Absurd);
        Assert.Equal(new Vector3(0f, 50f, 0f), s.Other.Velocity);
        s.Tick(1);
        Assert.True(CellContains(s.Other.CellId, s.Other.Position.Frame.Origin));
    }

    private static float BitIncrement(float f) => MathF.BitIncrement(f);

    [Fact]
    public void Acceleration_AboveTheBound_IsRefused_AtTheBound_KeepsTheVelocityBounded()
    {
        // InputLimits.MaxAcceleration = 1,000 m/s². 1e30 m/s² swept an object 1e28 m in one step (into the lost cell).
        var s = new MisuseScene();
        PhysicsObj o = s.Other;
        PublicState before = PublicState.Capture(s);
        Assert.Throws<ArgumentException>(() => o.SetAcceleration(new Vector3(1e30f, 0f, 0f)));
        Assert.Throws<ArgumentException>(() => o.SetAcceleration(new Vector3(0f, MathF.BitIncrement(1000f), 0f)));
        Assert.Empty(PublicState.Diff(before, PublicState.Capture(s)));

        // Airborne at 5 m above the ground with 1,000 m/s² east: every step starts with the velocity clamped to 50 m/s
        // (UpdatePhysicsInternal) and adds a × q = 1,000 × 0.05 = 50 m/s, so |v| ≤ 100 m/s (plus float rounding, 1e-3) and
        // one tick moves it at most 50 × 0.05 + 1,000 × 0.05² / 2 = 3.75 m; 10 ticks stay inside the landblock.
        Position p = MisuseScene.At(103f, 100f);
        p.Frame.Origin = p.Frame.Origin with { Z = 15f };
        o.SetPositionSimple(p, true);
        o.SetAcceleration(new Vector3(1000f, 0f, 0f));
        for (int i = 0; i < 10; i++)
        {
            Vector3 from = o.Position.Frame.Origin;
            s.Tick(1);
            Assert.True(o.Velocity.Length() <= 100f + 1e-3f, $"tick {i}: |v| = {o.Velocity.Length()}");
            Assert.True((o.Position.Frame.Origin - from).Length() <= 3.75f + 1e-3f, $"tick {i}: moved {o.Position.Frame.Origin - from}");
            Assert.True(CellContains(o.CellId, o.Position.Frame.Origin), $"tick {i}: cell {o.CellId:X8} at {o.Position.Frame.Origin}");
        }
    }
}
