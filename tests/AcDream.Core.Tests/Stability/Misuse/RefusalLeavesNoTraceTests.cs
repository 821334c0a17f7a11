using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using Xunit;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// Issue #15 item 9: CommitTransition refuses NaN / ±∞ (and, when flagged valid, non-unit) contact and sliding normals;
/// GoToLostCell with a NaN origin refuses before the object leaves its cell; a refused call creates no manager. Before the
/// fix the normals were stored, GoToLostCell left the cell and then threw, and ConstrainTo / InterpolateTo / StickTo created
/// their managers before checking.
/// </summary>
public class RefusalLeavesNoTraceTests
{
    public static TheoryData<string, float> Normals()
    {
        var d = new TheoryData<string, float>();
        foreach (string which in new[] { "contact", "sliding" })
        {
            foreach (float f in new[] { float.NaN, float.PositiveInfinity, float.NegativeInfinity, 1e30f, 2f })
            {
                d.Add(which, f);
            }
        }

        return d;
    }

    [Theory]
    [MemberData(nameof(Normals))]
    public void CommitTransition_BadNormal_IsRefused_StateUnchanged(string which, float z)
    {
        var s = new MisuseScene();
        TransitionResult t = TransitionResult.FreeSpace(s.Walker.Position);
        t.CurrentCellId = s.Walker.CellId;
        // (0, 0, 2) is finite but not unit length: refused when flagged valid.
        if (which == "contact")
        {
            t.ContactPlaneValid = true;
            t.ContactPlaneNormal = new Vector3(0f, 0f, z);
        }
        else
        {
            t.SlidingNormalValid = true;
            t.SlidingNormal = new Vector3(0f, 0f, z);
        }

        PublicState before = PublicState.Capture(s);
        Assert.Throws<ArgumentException>(() => s.Walker.CommitTransition(t));
        Assert.Empty(PublicState.Diff(before, PublicState.Capture(s)));
    }

    [Fact]
    public void CommitTransition_UnitNormals_AreAccepted()
    {
        var s = new MisuseScene();
        TransitionResult t = TransitionResult.FreeSpace(s.Walker.Position);
        t.CurrentCellId = s.Walker.CellId;
        t.ContactPlaneValid = true;
        t.ContactPlaneNormal = Vector3.UnitZ;
        t.ContactPlaneD = -10f;
        t.SlidingNormalValid = true;
        t.SlidingNormal = Vector3.UnitX;
        s.Walker.CommitTransition(t);
        Assert.Equal(Vector3.UnitX, s.Walker.SlidingNormal);
    }

    [Fact]
    public void GoToLostCell_NaNOrigin_IsRefusedBeforeTheObjectLeavesItsCell()
    {
        var s = new MisuseScene();
        uint cell = s.Walker.CellId;
        Assert.NotEqual(0u, cell);
        Position p = s.Walker.Position;
        p.Frame.Origin = new Vector3(float.NaN, 1f, 1f);
        PublicState before = PublicState.Capture(s);
        Assert.Throws<ArgumentException>(() => s.Walker.GoToLostCell(p));
        Assert.Equal(cell, s.Walker.CellId);
        Assert.Empty(PublicState.Diff(before, PublicState.Capture(s)));
    }

    [Fact]
    public void RefusedCalls_CreateNoManager()
    {
        var s = new MisuseScene();
        PhysicsObj o = s.Other; // no position manager yet
        Assert.Null(o.PositionManager);
        Position bad = o.Position;
        bad.Frame.Origin = new Vector3(1e30f, 0f, 0f);
        Assert.Throws<ArgumentException>(() => o.ConstrainTo(o.Position, 10f, float.NaN));
        Assert.Throws<ArgumentException>(() => o.ConstrainTo(bad, 10f, 50f));
        Assert.Throws<ArgumentException>(() => o.InterpolateTo(bad, false));
        Assert.Null(o.PositionManager);

        // The position manager's own lazily created managers, too.
        PhysicsObj w = s.Walker;
        var pm = new Physics.Managers.PositionManager(w);
        Assert.Throws<ArgumentException>(() => pm.ConstrainTo(bad, 10f, 50f));
        Assert.Throws<ArgumentException>(() => pm.ConstrainTo(w.Position, float.NaN, 50f));
        Assert.Throws<ArgumentException>(() => pm.InterpolateTo(bad, false));
        Assert.Throws<ArgumentException>(() => pm.StickTo(2u, float.NaN, 1f));
        Assert.Null(pm.ConstraintManager);
        Assert.Null(pm.InterpolationManager);
        Assert.Null(pm.StickyManager);
    }
}
