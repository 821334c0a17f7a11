using System;
using AcDream.Core.Physics.Motion;
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
