using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// NaN and ±infinity given to any public setter of an object, its part array or its managers, or to any interpolation update,
/// are refused with an <see cref="ArgumentException"/> and leave every piece of state as it was (house rule: bad input at the
/// public API → ArgumentException, state unchanged, except where retail defines a recovery — set_frame's zeroed quaternion,
/// pinned elsewhere, is the one such recovery).
/// </summary>
public class NonFiniteInputsAreRefusedTests
{
    private static readonly float[] BadFloats = [float.NaN, float.PositiveInfinity, float.NegativeInfinity];

    /// <summary>A creature in the manager scene with every manager in use: queued interpolation, a constraint, a fade.</summary>
    private static ManagerScene Scene()
    {
        var s = new ManagerScene(new Vector3(50f, 50f, 0f));
        s.Creature.MakePositionManager();
        s.Creature.InterpolateTo(ManagerScene.At(new Vector3(50f, 53f, 0f)), false);
        s.Creature.ConstrainTo(s.Creature.Position, 10f, 50f);
        s.Creature.SetTranslucency(0.5f, 1.0);
        s.Creature.PositionManager!.StickTo(1u, 0.5f, 1.8f);
        s.CreatureParts.SequenceVelocity = new Vector3(0f, 1f, 0f);
        s.World.Tick(s.World.CurrentTime + 0.05);
        return s;
    }

    /// <summary>Every readable piece of the creature's state, its part array and its managers, bit for bit.</summary>
    private static ulong Snapshot(ManagerScene s)
    {
        PhysicsObj o = s.Creature;
        var h = new StateHasher();
        h.Add(SceneTestContext.Hash(o));
        h.Add(o.Friction);
        h.Add(o.Elasticity);
        h.Add(o.Scale);
        h.Add(o.TranslucencyOriginal);
        h.Add(o.ContactPlaneNormal);
        h.Add(o.SlidingNormal);
        h.Add((uint)(o.Hooks is null ? 0 : 1));
        SimplePartArray parts = s.CreatureParts;
        h.Add(parts.SequenceVelocity);
        h.Add(parts.SequenceOmega);
        h.Add(parts.Radius);
        h.Add(parts.Height);
        h.Add(parts.StepUpHeight);
        h.Add(parts.StepDownHeight);
        h.Add(parts.Scale);
        h.Add(parts.Translucency);
        h.Add(parts.Luminosity);
        h.Add(parts.Diffusion);
        h.Add(parts.Frame);
        h.Add(parts.GetPartTranslucency(0));
        h.Add(parts.GetPartLuminosity(0));
        h.Add(parts.GetPartDiffusion(0));
        h.Add(o.Parent is null ? 0u : 1u);
        InterpolationManager im = s.Interpolation!;
        h.Add((uint)im.Count);
        for (int i = 0; i < im.Count; i++)
        {
            h.Add(im.GetNode(i).Position);
        }

        h.Add((uint)im.NodeFailCounter);
        h.Add(im.ProgressQuantum);
        h.Add(im.OriginalDistance);
        ConstraintManager? cm = o.PositionManager!.ConstraintManager;
        h.Add(cm is null ? 0u : cm.IsConstrained ? 2u : 1u);
        h.Add(o.StickyObjectId);
        h.Add(o.GetUpdateTime(PhysicsTimeStamp.Position));
        h.Add(o.GetUpdateTime(PhysicsTimeStamp.Teleport));
        return h.Value;
    }

    private static Position WithOrigin(in Position p, Vector3 origin)
    {
        Position q = p;
        q.Frame.Origin = origin;
        return q;
    }

    private static Position WithQuaternion(in Position p, float w)
    {
        Position q = p;
        q.Frame.SetQuaternionRaw(w, 0f, 0f, 0f);
        return q;
    }

    /// <summary>Named public entry points, each called with the bad value <c>x</c>.</summary>
    public static IEnumerable<object[]> Setters()
    {
        string[] names =
        [
            "SetVelocity", "SetLocalVelocity", "SetOmega", "SetAcceleration", "Friction", "Elasticity", "TranslucencyOriginal",
            "SetHeading", "SetScale", "SetScaleDelta", "SetScaleStatic", "SetTranslucency", "SetTranslucency2",
            "SetTranslucencyInternal", "SetPartTranslucency", "SetLuminosity", "SetPartLuminosity", "SetDiffusion",
            "SetPartDiffusion", "CallPes", "ProcessFPHook", "SetFrameOrigin", "SetInitialFrameOrigin", "StorePositionOrigin",
            "SetPositionOrigin", "SetPositionSimpleOrigin", "EnterWorldOrigin", "MoveOrTeleportOrigin", "ConstrainToOrigin",
            "ConstrainToDistance", "StickToRadius", "SequenceVelocity", "SequenceOmega", "PartRadius", "PartHeight",
            "PartStepUpHeight", "PartStepDownHeight", "SetSpheres", "SetCylSpheres", "SetParentFrame", "PartSetFrame",
            "PartSetScale", "PartSetTranslucency", "PartSetPartTranslucency", "PartSetLuminosity", "PartSetPartLuminosity",
            "PartSetDiffusion", "PartSetPartDiffusion",
            // interpolation updates
            "InterpolateToOrigin", "InterpolateToQuaternion", "EnqueueOrigin", "EnqueueBody", "EnqueueNodeVelocity",
            "EnqueueNodeExtent", "HandleReceivedPositionOrigin", "HandleReceivedPositionQuaternion", "AdjustOffsetQuantum",
            "HandleUpdateTargetOrigin",
        ];
        foreach (string n in names)
        {
            yield return [n];
        }
    }

    private static void Call(ManagerScene s, string name, float x)
    {
        PhysicsObj o = s.Creature;
        var v = new Vector3(1f, x, 2f);
        Position p = o.Position;
        switch (name)
        {
            case "SetVelocity": o.SetVelocity(v); break;
            case "SetLocalVelocity": o.SetLocalVelocity(v); break;
            case "SetOmega": o.SetOmega(v); break;
            case "SetAcceleration": o.SetAcceleration(v); break;
            case "Friction": o.Friction = x; break;
            case "Elasticity": o.Elasticity = x; break;
            case "TranslucencyOriginal": o.TranslucencyOriginal = x; break;
            case "SetHeading": o.SetHeading(x); break;
            case "SetScale": o.SetScale(x, 1.0); break;
            case "SetScaleDelta": o.SetScale(1f, x); break;
            case "SetScaleStatic": o.SetScaleStatic(x); break;
            case "SetTranslucency": o.SetTranslucency(x, 0.0); break;
            case "SetTranslucency2": o.SetTranslucency2(0f, x, 1.0); break;
            case "SetTranslucencyInternal": o.SetTranslucencyInternal(x); break;
            case "SetPartTranslucency": o.SetPartTranslucency(0, x, 0.5f, 1.0); break;
            case "SetLuminosity": o.SetLuminosity(0f, x, 0.0); break;
            case "SetPartLuminosity": o.SetPartLuminosity(0, 0f, 1f, x); break;
            case "SetDiffusion": o.SetDiffusion(x, 1f, 1.0); break;
            case "SetPartDiffusion": o.SetPartDiffusion(0, 0f, x, 0.0); break;
            case "CallPes": o.CallPes(7u, x); break;
            case "ProcessFPHook": o.ProcessFPHook(PhysicsHookType.Scale, x, 0); break;
            case "SetFrameOrigin": o.SetFrame(WithOrigin(p, v).Frame); break;
            case "SetInitialFrameOrigin": o.SetInitialFrame(WithOrigin(p, v).Frame); break;
            case "StorePositionOrigin": o.StorePosition(WithOrigin(p, v)); break;
            case "SetPositionOrigin": o.SetPosition(WithOrigin(p, v), SetPositionFlags.Teleport); break;
            case "SetPositionSimpleOrigin": o.SetPositionSimple(WithOrigin(p, v), true); break;
            case "EnterWorldOrigin": o.EnterWorld(WithOrigin(p, v)); break;
            case "MoveOrTeleportOrigin": o.MoveOrTeleport(WithOrigin(p, v), 0, true); break;
            case "ConstrainToOrigin": o.ConstrainTo(WithOrigin(p, v), 10f, 50f); break;
            case "ConstrainToDistance": o.ConstrainTo(p, 10f, x); break;
            case "StickToRadius": o.PositionManager!.StickTo(1u, x, 1f); break;
            case "SequenceVelocity": s.CreatureParts.SequenceVelocity = v; break;
            case "SequenceOmega": s.CreatureParts.SequenceOmega = v; break;
            case "PartRadius": s.CreatureParts.Radius = x; break;
            case "PartHeight": s.CreatureParts.Height = x; break;
            case "PartStepUpHeight": s.CreatureParts.StepUpHeight = x; break;
            case "PartStepDownHeight": s.CreatureParts.StepDownHeight = x; break;
            case "SetSpheres": s.CreatureParts.SetSpheres([new Sphere(v, 0.5f)]); break;
            case "SetCylSpheres": s.CreatureParts.SetCylSpheres([new CylSphere(v, 0.5f, 1f)]); break;
            case "SetParentFrame": o.SetParent(s.Player, 0, WithOrigin(p, v).Frame); break;
            case "PartSetFrame": s.CreatureParts.SetFrame(WithOrigin(p, v).Frame); break;
            case "PartSetScale": s.CreatureParts.SetScale(x); break;
            case "PartSetTranslucency": s.CreatureParts.SetTranslucency(x); break;
            case "PartSetPartTranslucency": s.CreatureParts.SetPartTranslucency(0, x); break;
            case "PartSetLuminosity": s.CreatureParts.SetLuminosity(x); break;
            case "PartSetPartLuminosity": s.CreatureParts.SetPartLuminosity(0, x); break;
            case "PartSetDiffusion": s.CreatureParts.SetDiffusion(x); break;
            case "PartSetPartDiffusion": s.CreatureParts.SetPartDiffusion(0, x); break;
            case "InterpolateToOrigin": o.InterpolateTo(WithOrigin(p, v), false); break;
            case "InterpolateToQuaternion": o.InterpolateTo(WithQuaternion(p, x), false); break;
            case "EnqueueOrigin": s.Interpolation!.Enqueue(WithOrigin(p, v)); break;
            case "EnqueueBody": s.Interpolation!.Enqueue(p, false, WithOrigin(p, v)); break;
            case "EnqueueNodeVelocity": s.Interpolation!.EnqueueNode(InterpolationNodeType.Velocity, p, v); break;
            case "EnqueueNodeExtent": s.Interpolation!.EnqueueNode(InterpolationNodeType.Jump, p, Vector3.Zero, x); break;
            case "HandleReceivedPositionOrigin": o.HandleReceivedPosition(WithOrigin(p, v), 9, 0, true); break;
            case "HandleReceivedPositionQuaternion": o.HandleReceivedPosition(WithQuaternion(p, x), 9, 0, true); break;
            case "HandleUpdateTargetOrigin":
                o.HandleUpdateTarget(new TargetInfo { ContextId = 0, ObjectId = 1u, Status = TargetStatus.Ok, TargetPosition = WithOrigin(s.Player.Position, v) });
                break;
            case "AdjustOffsetQuantum":
                Frame f = Frame.Identity;
                s.Interpolation!.AdjustOffset(ref f, x);
                break;
            default: throw new InvalidOperationException(name);
        }
    }

    [Theory]
    [MemberData(nameof(Setters))]
    public void NonFiniteValue_IsRefused_AndNothingChanges(string setter)
    {
        foreach (float bad in BadFloats)
        {
            ManagerScene s = Scene();
            ulong before = Snapshot(s);
            Assert.ThrowsAny<ArgumentException>(() => Call(s, setter, bad));
            Assert.True(before == Snapshot(s), $"{setter}({bad}) changed the state");

            // The object still ticks normally afterwards.
            s.World.Tick(s.World.CurrentTime + 0.05);
            Assert.True(VectorMath.IsFinite(s.Creature.Position.Frame.Origin));
        }
    }

    [Fact]
    public void FiniteValues_AreAccepted_SoTheRefusalsAboveAreAboutTheValue()
    {
        // Control: the same calls with a finite x (where the call is meaningful) do not throw.
        foreach (object[] row in Setters())
        {
            var name = (string)row[0];
            ManagerScene s = Scene();
            float x = name is "Friction" ? 0.5f : name is "InterpolateToQuaternion" or "HandleReceivedPositionQuaternion" ? 1f : 0.25f;
            Call(s, name, x);
        }
    }
}
