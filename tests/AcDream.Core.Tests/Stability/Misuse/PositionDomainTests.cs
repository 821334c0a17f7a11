using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using Xunit;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// Issue #15 items 8 and 10: huge finite origins (1e30, float.MaxValue), origins outside the position domain (±65,536 m;
/// outdoor x, y in [−192, 384]) and the all-zero rotation of default(Frame) are refused by every position entry point with
/// the state unchanged. Before the fix SetFrame, SetInitialFrame, StorePosition, CommitTransition, SetParent and the remote
/// path took them, and the next tick wrote ±∞ into the cached velocity.
/// </summary>
public class PositionDomainTests
{
    public static TheoryData<string, string> Cases()
    {
        var d = new TheoryData<string, string>();
        string[] entries =
        [
            "SetFrame", "SetInitialFrame", "StorePosition", "SetPosition", "SetPositionSimple", "EnterWorld", "CommitTransition",
            "GoToLostCell", "SetParent", "HandleReceivedPosition", "MoveOrTeleport", "InterpolateTo", "ConstrainTo",
        ];
        string[] values = ["x=1e30", "x=MaxValue", "z=-MaxValue", "x=384.0001", "y=-192.0001", "z=65536.01", "default(Frame)"];
        foreach (string e in entries)
        {
            foreach (string v in values)
            {
                d.Add(e, v);
            }
        }

        return d;
    }

    private static Frame Bad(Frame good, string v)
    {
        Frame f = good;
        Vector3 o = f.Origin;
        switch (v)
        {
            case "x=1e30": f.Origin = o with { X = 1e30f }; break;
            case "x=MaxValue": f.Origin = o with { X = float.MaxValue }; break;
            case "z=-MaxValue": f.Origin = o with { Z = float.MinValue }; break;
            case "x=384.0001": f.Origin = o with { X = 384.0001f }; break; // past the outdoor margin (192 + 192)
            case "y=-192.0001": f.Origin = o with { Y = -192.0001f }; break;
            case "z=65536.01": f.Origin = o with { Z = 65536.01f }; break; // past MaxCoordinate
            case "default(Frame)": f = default; break;
            default: throw new ArgumentException(v);
        }

        return f;
    }

    private static void Call(MisuseScene s, string entry, Frame f)
    {
        PhysicsObj o = s.Walker;
        var p = new Position(o.Position.ObjCellId, f);
        switch (entry)
        {
            case "SetFrame": o.SetFrame(f); break;
            case "SetInitialFrame": o.SetInitialFrame(f); break;
            case "StorePosition": o.StorePosition(p); break;
            case "SetPosition": o.SetPosition(p, SetPositionFlags.Teleport); break;
            case "SetPositionSimple": o.SetPositionSimple(p, true); break;
            case "EnterWorld": o.EnterWorld(p); break;
            case "CommitTransition": o.CommitTransition(TransitionResult.FreeSpace(p)); break;
            case "GoToLostCell": o.GoToLostCell(p); break;
            case "SetParent": o.SetParent(s.Other, 0u, BadChild(f)); break;
            case "HandleReceivedPosition": o.HandleReceivedPosition(p, 9, 0, true); break;
            case "MoveOrTeleport": o.MoveOrTeleport(p, 0, true); break;
            case "InterpolateTo": o.InterpolateTo(p, false); break;
            case "ConstrainTo": o.ConstrainTo(p, 10f, 50f); break;
            default: throw new ArgumentException(entry);
        }
    }

    // A child frame is an offset from the parent: the cell-local cases become the same offsets (the outdoor-margin ones are
    // beyond MaxChildOffset, 192 m, too).
    private static Frame BadChild(Frame f) => f;

    [Theory]
    [MemberData(nameof(Cases))]
    public void OutsideTheDomain_IsRefused_StateUnchanged_AndTicksStayFinite(string entry, string value)
    {
        var s = new MisuseScene();
        Frame bad = Bad(s.Walker.Position.Frame, value);
        PublicState before = PublicState.Capture(s);
        Assert.ThrowsAny<ArgumentException>(() => Call(s, entry, bad));
        List<string> diff = PublicState.Diff(before, PublicState.Capture(s));
        Assert.True(diff.Count == 0, string.Join("\n", diff));
        s.Tick(30);
        Assert.Empty(PublicState.Capture(s).NonFinite);
    }

    [Fact]
    public void OutdoorMarginEdges_AreAccepted_AndReHomed()
    {
        // x = 384 is the edge of the domain [−192, 384]: StorePosition re-homes it two blocks east, to x = 0 of landblock
        // 0x8280 (384 − 2 × 192 = 0; store_position's adjust_to_outside, acclient.c:467433).
        var s = new MisuseScene();
        Position p = s.Walker.Position;
        p.Frame.Origin = p.Frame.Origin with { X = 384f };
        s.Walker.StorePosition(p);
        Assert.Equal(0x82u, s.Walker.Position.ObjCellId >> 24);
        Assert.Equal(0f, s.Walker.Position.Frame.Origin.X);
    }

    [Theory]
    [InlineData(1e30f)]
    [InlineData(384.0001f)]
    [InlineData(float.NaN)]
    public void RetailSweep_SweepObject_OutsideTheDomain_IsRefused(float x)
    {
        // Before the check a sweep towards x = 1e30 took seconds and ended "in" a cell of an unloaded landblock.
        var s = new MisuseScene();
        Position from = s.Walker.Position;
        Position to = from;
        to.Frame.Origin = to.Frame.Origin with { X = x };
        var r = default(TransitionResult);
        PublicState before = PublicState.Capture(s);
        Assert.Throws<ArgumentException>(() => s.Sweep.SweepObject(s.Walker, from, to, false, ref r));
        Assert.Throws<ArgumentException>(() => s.Sweep.SweepObject(s.Walker, to, from, false, ref r));
        Assert.Throws<ArgumentException>(() => s.Sweep.SetPosition(s.Walker, to, SetPositionFlags.Placement));
        Assert.Empty(PublicState.Diff(before, PublicState.Capture(s)));
    }

    [Fact]
    public void RetailSweep_SweepObject_ToNoWorldCell_FailsAtOnce_AndALongSweepIsRefused()
    {
        // Cell 0xFFFFFFFF names landblock 0xFF (x = 255 > 254, outside the world): the sweep of the second object from the
        // walker's position there ran 24,384 m / 0.5 m ≈ 48,800 transition steps. It now fails at once (false). A sweep of
        // 192 m + 1 cm (MaxSweepDistance = 192 m) is refused.
        var s = new MisuseScene();
        Position from = s.Walker.Position;
        var r = default(TransitionResult);
        Assert.False(s.Sweep.SweepObject(s.Other, from, new Position(0xFFFFFFFFu, from.Frame), false, ref r));
        Assert.False(s.Sweep.SweepObject(s.Other, from, new Position(0u, from.Frame), false, ref r));
        Position far = from;
        far.Frame.Origin = far.Frame.Origin with { Y = from.Frame.Origin.Y + 192.01f };
        Assert.Throws<ArgumentException>(() => s.Sweep.SweepObject(s.Other, from, far, false, ref r));
    }
}
