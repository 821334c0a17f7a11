using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Motion.Wire;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// The classes of bad value each parameter type allows, and a good value for the other parameters of a call. Every bad value
/// carries a label for the failure message.
/// </summary>
internal static class BadValues
{
    private const float Subnormal = 1e-45f;

    /// <summary>The bad floats: NaN, ±∞, ±MaxValue, ±1e30 (huge finite), the smallest subnormal, −0, −1 (a negative size).</summary>
    private static readonly (string, float)[] Floats =
    [
        ("NaN", float.NaN), ("+Inf", float.PositiveInfinity), ("-Inf", float.NegativeInfinity), ("MaxValue", float.MaxValue),
        ("-MaxValue", float.MinValue), ("1e30", 1e30f), ("-1e30", -1e30f), ("subnormal", Subnormal), ("-0", -0f), ("-1", -1f),
    ];

    /// <summary>The bad doubles: as <see cref="Floats"/>, plus 1e15 s (a clock the 1/30 s gate cannot resolve).</summary>
    private static readonly (string, double)[] Doubles =
    [
        ("NaN", double.NaN), ("+Inf", double.PositiveInfinity), ("-Inf", double.NegativeInfinity), ("MaxValue", double.MaxValue),
        ("-MaxValue", double.MinValue), ("1e30", 1e30), ("-1e30", -1e30), ("subnormal", double.Epsilon), ("-0", -0.0),
        ("-1", -1.0), ("1e15", 1e15),
    ];

    /// <summary>Cell ids: none, all ones, an indoor id with no env cell, an outdoor id of an unloaded landblock.</summary>
    private static readonly (string, uint)[] CellIds =
    [
        ("0", 0u), ("0xFFFFFFFF", 0xFFFFFFFFu), ("indoor-no-envcell", 0x80800105u), ("unloaded-block", 0x12340001u),
    ];

    /// <summary>Bad values for a parameter of type <paramref name="t"/> (empty when the type has none), given the scene's good
    /// value <paramref name="good"/>.</summary>
    public static IEnumerable<(string Label, object? Value)> For(Type t, object? good)
    {
        if (Nullable.GetUnderlyingType(t) is { } inner)
        {
            // An optional value: each bad value of the underlying type (null is the good value, "keep").
            foreach ((string l, object? v) in For(inner, TryGood(inner, null, out object? g) ? g : null))
            {
                yield return (l, v);
            }

            yield break;
        }

        if (!t.IsValueType)
        {
            // null: accepted where the signature allows it; refused (ArgumentNullException) where it does not.
            yield return ("null", null);
            yield break;
        }

        if (t == typeof(float))
        {
            foreach ((string l, float f) in Floats)
            {
                yield return (l, f);
            }
        }
        else if (t == typeof(double))
        {
            foreach ((string l, double d) in Doubles)
            {
                yield return (l, d);
            }
        }
        else if (t == typeof(int))
        {
            yield return ("-1", -1);
            yield return ("int.MinValue", int.MinValue);
            yield return ("int.MaxValue", int.MaxValue);
        }
        else if (t == typeof(uint))
        {
            foreach ((string l, uint u) in CellIds)
            {
                yield return (l, u);
            }
        }
        else if (t == typeof(ushort))
        {
            yield return ("0", (ushort)0);
            yield return ("0xFFFF", (ushort)0xFFFF);
        }
        else if (t == typeof(long))
        {
            yield return ("-1", -1L);
            yield return ("long.MinValue", long.MinValue);
        }
        else if (t.IsEnum)
        {
            yield return ("undefined", Enum.ToObject(t, 0x7FFF_FFFF));
        }
        else if (t == typeof(Vector3))
        {
            foreach ((string l, Vector3 v) in Vectors())
            {
                yield return (l, v);
            }
        }
        else if (t == typeof(Frame))
        {
            foreach ((string l, Frame f) in Frames((Frame)good!))
            {
                yield return (l, f);
            }
        }
        else if (t == typeof(Position))
        {
            foreach ((string l, Position p) in Positions((Position)good!))
            {
                yield return (l, p);
            }
        }
        else if (t == typeof(TransitionResult))
        {
            var g = (TransitionResult)good!;
            foreach ((string l, Position p) in Positions(g.CurrentPosition))
            {
                TransitionResult r = g;
                r.CurrentPosition = p;
                r.CurrentCellId = p.ObjCellId;
                yield return ("position " + l, r);
            }

            foreach ((string l, Vector3 v) in Vectors())
            {
                TransitionResult a = g;
                a.ContactPlaneNormal = v;
                a.ContactPlaneValid = true;
                yield return ("contact normal " + l, a);
                TransitionResult b = g;
                b.SlidingNormal = v;
                b.SlidingNormalValid = true;
                yield return ("sliding normal " + l, b);
            }

            foreach ((string l, float f) in Floats)
            {
                TransitionResult c = g;
                c.ContactPlaneD = f;
                c.ContactPlaneValid = true;
                yield return ("contact d " + l, c);
            }
        }
        else if (t == typeof(Sphere))
        {
            foreach ((string l, Vector3 v) in Vectors())
            {
                yield return ("centre " + l, new Sphere(v, 0.5f));
            }

            foreach ((string l, float f) in Floats)
            {
                yield return ("radius " + l, new Sphere(new Vector3(0f, 0f, 0.5f), f));
            }

            yield return ("radius 0", new Sphere(new Vector3(0f, 0f, 0.5f), 0f));
        }
        else if (t == typeof(MovementParameters))
        {
            yield return ("default(MovementParameters)", default(MovementParameters));
            foreach ((string l, float f) in Floats)
            {
                var g = new MovementParameters();
                yield return ("speed " + l, g with { Speed = f });
                yield return ("distance_to_object " + l, g with { DistanceToObject = f });
                yield return ("min_distance " + l, g with { MinDistance = f });
                yield return ("fail_distance " + l, g with { FailDistance = f });
                yield return ("walk_run_threshhold " + l, g with { WalkRunThreshold = f });
                yield return ("desired_heading " + l, g with { DesiredHeading = f });
            }

            yield return ("every flag", new MovementParameters { Flags = (MovementParameterFlags)0xFFFFFFFFu });
            yield return ("hold key 7", new MovementParameters { HoldKeyToApply = (HoldKey)7 });
        }
        else if (t == typeof(ActionNode))
        {
            foreach ((string l, float f) in Floats)
            {
                yield return ("speed " + l, new ActionNode(GoodAction, f, 1, false));
            }

            yield return ("speed 101", new ActionNode(GoodAction, 101f, 1, false));
        }
        else if (t == typeof(InterpretedMotionState))
        {
            foreach ((string l, InterpretedMotionState st) in States())
            {
                yield return (l, st);
            }
        }
        else if (t == typeof(MovementEventMessage))
        {
            foreach ((string l, MovementEventMessage m) in Messages(s: null))
            {
                yield return (l, m);
            }
        }
        else if (t == typeof(TargetInfo))
        {
            var g = (TargetInfo)good!;
            foreach ((string l, Position p) in Positions(g.TargetPosition))
            {
                TargetInfo i = g;
                i.TargetPosition = p;
                yield return ("target " + l, i);
            }
        }
    }

    /// <summary>An action command (0x10000057, a bow): its class bit 0x10000000 makes it an action.</summary>
    private const MotionCommand GoodAction = (MotionCommand)0x10000057u;

    /// <summary>Interpreted states a client can build (every speed within ±100, so each setter accepts it) that the motion
    /// entries must refuse: a run at a rate of zero, below zero or beyond 100 (the interpreter takes a run's speed as its run
    /// rate; at zero or below a standing object's state velocity is NaN).</summary>
    private static IEnumerable<(string, InterpretedMotionState)> States()
    {
        foreach (float v in new[] { -1f, 0f, -0f, Subnormal * -1f, 100f })
        {
            var st = new InterpretedMotionState { ForwardCommand = MotionCommand.RunForward };
            st.ForwardSpeed = v == 100f ? 100f : v;
            if (v == 100f)
            {
                // Every speed at the edge, a side-step and a turn: accepted, and the world ticks on.
                st.SidestepCommand = MotionCommand.SideStepRight;
                st.SidestepSpeed = -100f;
                st.TurnCommand = MotionCommand.TurnRight;
                st.TurnSpeed = 100f;
                st.AddAction(GoodAction, -100f, 1, false);
            }

            yield return ($"running at {v}", st);
        }

        yield return ("walking at -100", new InterpretedMotionState { ForwardCommand = MotionCommand.WalkForward, ForwardSpeed = -100f });
        yield return ("undefined commands", new InterpretedMotionState
        {
            CurrentStyle = (MotionCommand)0x7FFFFFFF, ForwardCommand = (MotionCommand)0x7FFFFFFF,
            SidestepCommand = (MotionCommand)0x7FFFFFFF, TurnCommand = (MotionCommand)0x7FFFFFFF,
        });
    }

    /// <summary>MovementEvents a client can build (or a hostile server send, after the decoder): every movement type with
    /// each bad value its fields allow. <see cref="Address"/> addresses each to the object it is handed to.</summary>
    private static IEnumerable<(string, MovementEventMessage)> Messages(MisuseScene? s)
    {
        MovementEventMessage M(MovementEventType type)
        {
            var m = new MovementEventMessage { MovementTimestamp = 1, MovementType = type, TargetId = 2u, Origin = MisuseScene.At(100f, 110f) };
            return m;
        }

        var other = M(MovementEventType.InterpretedMotion);
        other.ObjectId = 0x7FFFFFFFu;
        yield return ("for another object", other);
        yield return ("movement type 5", M((MovementEventType)5));
        yield return ("stale stamp 0", new MovementEventMessage { MovementTimestamp = 0 });
        foreach ((string l, InterpretedMotionState st) in States())
        {
            MovementEventMessage m = M(MovementEventType.InterpretedMotion);
            m.State.CopyFrom(st);
            m.StickToObject = 2u;
            yield return ("type 0 " + l, m);
        }

        foreach (MovementEventType type in new[] { MovementEventType.MoveToObject, MovementEventType.MoveToPosition })
        {
            foreach ((string l, float f) in Floats)
            {
                MovementEventMessage m = M(type);
                m.RunRate = f;
                yield return ($"type {(int)type} run rate {l}", m);
            }

            foreach (float f in new[] { 0f, 1e38f, 100.00001f, 100f })
            {
                MovementEventMessage m = M(type);
                m.RunRate = f;
                yield return ($"type {(int)type} run rate {f}", m);
            }

            foreach ((string l, Position p) in Positions(MisuseScene.At(100f, 110f)))
            {
                MovementEventMessage m = M(type);
                m.Origin = p;
                yield return ($"type {(int)type} origin {l}", m);
            }

            MovementEventMessage unknown = M(type);
            unknown.TargetId = 0x12345678u;
            yield return ($"type {(int)type} unknown target", unknown);
        }

        foreach (MovementEventType type in new[] { MovementEventType.MoveToObject, MovementEventType.MoveToPosition,
                     MovementEventType.TurnToObject, MovementEventType.TurnToHeading })
        {
            foreach ((string l, object? p) in For(typeof(MovementParameters), new MovementParameters()))
            {
                MovementEventMessage m = M(type);
                m.Parameters = (MovementParameters)p!;
                yield return ($"type {(int)type} parameters {l}", m);
            }
        }

        foreach ((string l, float f) in Floats)
        {
            MovementEventMessage m = M(MovementEventType.TurnToObject);
            m.TurnToObjectHeading = f;
            yield return ("type 8 heading " + l, m);
        }
    }

    /// <summary>Addresses every MovementEvent argument that has no object id (0) to <paramref name="target"/>.</summary>
    public static void Address(object?[] args, PhysicsObj? target)
    {
        foreach (object? a in args)
        {
            if (a is MovementEventMessage { ObjectId: 0 } m && target is not null)
            {
                m.ObjectId = target.Id;
            }
        }
    }

    /// <summary>Vectors with each bad float in one component, the whole vector huge, and the 8,000 km-per-tick speed.</summary>
    private static IEnumerable<(string, Vector3)> Vectors()
    {
        foreach ((string l, float f) in Floats)
        {
            yield return ("y=" + l, new Vector3(0.25f, f, 0.5f));
        }

        yield return ("all 1e30", new Vector3(1e30f));
        yield return ("all MaxValue", new Vector3(float.MaxValue));
        yield return ("8,000 km per 0.05 s", new Vector3(0f, 1.6e8f, 0f));
    }

    private static IEnumerable<(string, Frame)> Frames(Frame good)
    {
        foreach ((string l, Vector3 v) in Vectors())
        {
            Frame f = good;
            f.Origin = v;
            yield return ("origin " + l, f);
        }

        Frame outside = good;
        outside.Origin = new Vector3(good.Origin.X + 1000f, good.Origin.Y, good.Origin.Z);
        yield return ("origin 1000 m east", outside);
        yield return ("default(Frame)", default);
        Frame nanQ = good;
        nanQ.SetQuaternionRaw(float.NaN, 0f, 0f, 0f);
        yield return ("NaN quaternion", nanQ);
        Frame longQ = good;
        longQ.SetQuaternionRaw(2f, 0f, 0f, 0f);
        yield return ("quaternion of length 2", longQ);
        Frame subQ = good;
        subQ.SetQuaternionRaw(Subnormal, 0f, 0f, 0f);
        yield return ("subnormal quaternion", subQ);
    }

    private static IEnumerable<(string, Position)> Positions(Position good)
    {
        foreach ((string l, Frame f) in Frames(good.Frame))
        {
            yield return (l, new Position(good.ObjCellId, f));
        }

        foreach ((string l, uint id) in CellIds)
        {
            yield return ("cell " + l, new Position(id, good.Frame));
        }
    }

    /// <summary>A good value of type <paramref name="t"/> in scene <paramref name="s"/>; false when there is none.</summary>
    public static bool TryGood(Type t, MisuseScene? s, out object? value)
    {
        if (s is null && (t == typeof(Frame) || t == typeof(Position) || t == typeof(TransitionResult) || t == typeof(TargetInfo)
                          || t == typeof(PhysicsObj)))
        {
            value = null;
            return false;
        }

        value = t switch
        {
            _ when Nullable.GetUnderlyingType(t) is not null => null,
            _ when t == typeof(Sphere) => new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f),
            _ when t == typeof(MovementParameters) => new MovementParameters { DesiredHeading = 90f },
            _ when t == typeof(float) => 0.5f,
            _ when t == typeof(double) => 0.5,
            _ when t == typeof(int) => 0,
            _ when t == typeof(uint) => 0u,
            _ when t == typeof(ushort) => (ushort)1,
            _ when t == typeof(long) => 0L,
            _ when t == typeof(bool) => false,
            _ when t.IsEnum => Enum.GetValues(t).GetValue(0),
            _ when t == typeof(Vector3) => new Vector3(0.1f, 0.2f, 0.3f),
            _ when t == typeof(Frame) => s!.Walker.Position.Frame,
            _ when t == typeof(Position) => s!.Walker.Position,
            _ when t == typeof(TransitionResult) => new TransitionResult
            {
                CurrentPosition = s!.Walker.Position,
                CurrentCellId = s.Walker.Position.ObjCellId,
                ContactPlaneValid = true,
                ContactPlaneNormal = Vector3.UnitZ,
                ContactPlaneD = -10f,
                ContactPlaneCellId = s.Walker.Position.ObjCellId,
            },
            _ when t == typeof(TargetInfo) => new TargetInfo
            {
                ContextId = 0, ObjectId = 2u, Status = TargetStatus.Ok, TargetPosition = s!.Other.Position,
            },
            _ when t == typeof(PhysicsObj) => s!.Other,
            _ when t == typeof(ActionNode) => new ActionNode(GoodAction, 1f, 1, false),
            _ when t == typeof(InterpretedMotionState) => new InterpretedMotionState
            {
                ForwardCommand = MotionCommand.RunForward, ForwardSpeed = 2f,
            },
            _ when t == typeof(RawMotionState) => new RawMotionState(),
            _ when t == typeof(MovementEventMessage) => GoodMessage(),
            _ when t == typeof(IAnimHook) => new NopAnimHook(),
            _ when t == typeof(PhysicsObjHook) => new NopHook(),
            _ when t == typeof(IPartArray) => new SimplePartArray(1, 1),
            _ when t == typeof(IMovementManager) => new BasicMovementManager(),
            _ when t == typeof(IWeenieObject) => WeenieTraits.Creature,
            _ when t == typeof(CollisionSweep) => FreeSpaceSweep.Instance,
            _ when !t.IsValueType => null, // other client seams: null (a nullable setter) is the good value
            _ => Missing,
        };
        return !ReferenceEquals(value, Missing);
    }

    private static readonly object Missing = new();

    // A type-0 event running at rate 2 (ObjectId 0: Address gives it the object it is handed to).
    private static MovementEventMessage GoodMessage()
    {
        var m = new MovementEventMessage { MovementTimestamp = 1 };
        m.State.ForwardCommand = MotionCommand.RunForward;
        m.State.ForwardSpeed = 2f;
        return m;
    }

    private sealed class NopAnimHook : IAnimHook
    {
        public void Execute(PhysicsObj obj)
        {
        }
    }

    private sealed class NopHook : PhysicsObjHook
    {
        public override bool Execute(PhysicsObj obj) => true;
    }
}
