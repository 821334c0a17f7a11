using System;
using System.Numerics;

namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// The valid domains of the values the public API accepts (positions, frames, scales, clock times, animation velocity): a
/// value outside them is refused with an <see cref="ArgumentException"/> and the state left as it was, so that no accepted
/// value can make a later tick throw or write a NaN or an infinity. Retail accepts any float here; every bound is a
/// deliberate divergence (docs/divergences.md, "Value domains").
/// </summary>
public static class InputLimits
{
    /// <summary>
    /// Largest magnitude of any origin component, metres: 2^16 = 65,536 m, beyond the world's side of 255 × 192 = 48,960 m, so
    /// a landblock-local origin of any real place fits with room to spare. Applies to every position, frame and child frame.
    /// </summary>
    public const float MaxCoordinate = 65536f;

    /// <summary>
    /// How far an outdoor position's x and y may lie outside its landblock, metres (one landblock, 192 m): an outdoor origin
    /// has x and y in [−192, 384] and is re-homed into the landblock that contains it (x, y in [0, 192)).
    /// </summary>
    public const float OutdoorMargin = LandDefs.BlockLength;

    /// <summary>Largest magnitude of a child frame's offset from its parent (or the parent's part), metres: 192 m.</summary>
    public const float MaxChildOffset = LandDefs.BlockLength;

    /// <summary>Smallest object scale accepted (unitless): 0.01. A smaller sphere would make the sweep's step count
    /// (distance / radius) explode.</summary>
    public const float MinScale = 0.01f;

    /// <summary>Largest object scale accepted (unitless): 100.</summary>
    public const float MaxScale = 100f;

    /// <summary>
    /// Exclusive bound on the magnitude of a clock time, seconds: 2^40 = 1,099,511,627,776 s (about 34,800 years). Below it a
    /// double's spacing is at most 2^-13 s = 1.22e-4 s, finer than EPSILON (2e-4 s, the shortest dt retail runs a step for)
    /// and than the 1/30 s world gate; at 2^40 it is 2^-12 s = 2.44e-4 s, coarser than EPSILON; near 1e15 s it is 0.125 s and
    /// the 1/30 s gate no longer resolves at all.
    /// </summary>
    public const double MaxClockTime = 1099511627776.0;

    /// <summary>Largest speed of an animation (sequence) velocity, m/s: retail's <see cref="PhysicsGlobals.MaxVelocity"/>
    /// (50 m/s), the clamp retail applies to the physics velocity in <c>set_velocity</c> and
    /// <c>UpdatePhysicsInternal</c>.</summary>
    public const float MaxSequenceSpeed = PhysicsGlobals.MaxVelocity;

    /// <summary>
    /// Largest magnitude of an acceleration set directly, m/s²: 1,000 (about 100 g; gravity is 9.8). With the 50 m/s velocity
    /// clamp at the start of every step, one step of at most 0.2 s then ends below 50 + 1,000 × 0.2 = 250 m/s and moves the
    /// object at most 50 × 0.2 + 1,000 × 0.2² / 2 = 30 m: within <see cref="OutdoorMargin"/>.
    /// </summary>
    public const float MaxAcceleration = 1000f;

    /// <summary>Longest sweep accepted, metres: one landblock, 192 m (at most 384 transition steps of a 0.5 m sphere). The
    /// engine's own steps move at most 30 m (<see cref="MaxAcceleration"/>).</summary>
    public const float MaxSweepDistance = LandDefs.BlockLength;

    /// <summary>
    /// Largest reach of a collision shape from its object's origin, metres (object-local, unscaled): 192 m, one landblock.
    /// A sphere needs |centre| + radius &lt;= 192, a cylinder sphere |low point| + radius + height &lt;= 192 (radius and height
    /// positive). The sweep pushes an object out of what its shapes overlap by up to their scaled reach: a 1e7 m sphere
    /// resting on the ground lifts its object 1e7 m in one step, beyond <see cref="MaxCoordinate"/>, and every later sweep
    /// refuses the position (every Tick throws). At this bound and <see cref="MaxScale"/> the push is at most 100 × 192 =
    /// 19,200 m, which keeps any origin above terrain within ±65,536 m. The largest retail setups reach a few metres.
    /// </summary>
    public const float MaxShapeReach = LandDefs.BlockLength;

    /// <summary>Largest step-up or step-down height, metres (object-local, unscaled): 192 m, one landblock; step heights are
    /// in [0, 192] (retail's are 0.01 m to a few metres). At <see cref="MaxScale"/> a step-down probe then moves at most
    /// 19,200 m, within <see cref="MaxCoordinate"/>.</summary>
    public const float MaxStepHeight = LandDefs.BlockLength;

    /// <summary>
    /// Largest magnitude of a motion speed, unitless (a multiple of the motion's normal speed): 100. Applies to the speeds a
    /// client or a server hands the motion interpreter (<c>MovementParameters.Speed</c> of a motion command, the raw and
    /// interpreted states' speeds, an action's speed). Retail's server sends 1, the run rate (about 1 to 4.5) or 1.5 (a
    /// melee charge); at 3e38 the state velocity (4 × speed) overflowed to infinity and the leave-ground velocity became NaN.
    /// The interpreter's own conversions (a run is the walk speed times the run rate) may go beyond it, up to
    /// 100 × <see cref="MaxRunRate"/>.
    /// </summary>
    public const float MaxMotionSpeed = 100f;

    /// <summary>
    /// Largest run rate, unitless: 100; a run rate is in (0, 100]. Applies to <c>MotionInterp.MyRunRate</c>, a MovementEvent's
    /// run rate (types 6 and 7) and the speed of an interpreted <c>RunForward</c> (which the interpreter takes as its run
    /// rate). Retail's run rates are about 1 to 4.5; a rate of zero or below made the state velocity's cap (4 × rate)
    /// negative, and the velocity of a standing object 0 / 0 = NaN.
    /// </summary>
    public const float MaxRunRate = 100f;

    /// <summary>True when <paramref name="h"/> is a step height in [0, <see cref="MaxStepHeight"/>].</summary>
    internal static bool IsStepHeightInDomain(float h) => h >= 0f && h <= MaxStepHeight;

    /// <summary>Throws when <paramref name="h"/> is outside [0, <see cref="MaxStepHeight"/>].</summary>
    /// <exception cref="ArgumentException">The step height is NaN, negative or above 192 m.</exception>
    internal static float ThrowIfStepHeightOutside(float h, string paramName) =>
        IsStepHeightInDomain(h) ? h : throw new ArgumentException("Step heights must be in [0, 192] m (InputLimits.MaxStepHeight).", paramName);

    /// <summary>True when <paramref name="cellId"/>'s low word is an outdoor cell (1..0x40) or the landblock (0xFFFF): the
    /// ids <c>store_position</c> re-homes to the outdoor cell under the origin.</summary>
    internal static bool IsOutdoorOrBlock(uint cellId)
    {
        uint c = cellId & 0xFFFFu;
        return (c >= LandDefs.FirstOutdoorCell && c <= LandDefs.LastOutdoorCell) || c == 0xFFFFu;
    }

    /// <summary>True when <paramref name="origin"/> is finite and inside the domain of a position in <paramref name="cellId"/>:
    /// every component within ±<see cref="MaxCoordinate"/>, and for an outdoor (or block) id x and y in
    /// [−<see cref="OutdoorMargin"/>, 192 + <see cref="OutdoorMargin"/>].</summary>
    internal static bool IsOriginInDomain(uint cellId, Vector3 origin)
    {
        if (!(Math.Abs(origin.X) <= MaxCoordinate && Math.Abs(origin.Y) <= MaxCoordinate
              && Math.Abs(origin.Z) <= MaxCoordinate))
        {
            return false; // also NaN
        }

        if (IsOutdoorOrBlock(cellId))
        {
            const float lo = -OutdoorMargin;
            const float hi = LandDefs.BlockLength + OutdoorMargin;
            return origin.X >= lo && origin.X <= hi && origin.Y >= lo && origin.Y <= hi;
        }

        return true;
    }

    /// <summary>True when the frame's quaternion is a unit quaternion (retail <c>Frame::IsValid</c>'s test: no NaN,
    /// |q|² within 5 × EPSILON of 1), which refuses the all-zero rotation of <c>default(Frame)</c>.</summary>
    internal static bool IsRotationValid(in Frame f) => f.IsValid(); // the origin's NaN test there is repeated by the domain

    /// <summary>True when <paramref name="p"/> is inside the position domain (origin, rotation).</summary>
    internal static bool IsPositionInDomain(in Position p) => IsOriginInDomain(p.ObjCellId, p.Frame.Origin) && IsRotationValid(p.Frame);

    /// <summary>Throws when <paramref name="p"/> is outside the position domain.</summary>
    /// <exception cref="ArgumentException">The origin or the rotation is outside the domain.</exception>
    internal static void ThrowIfOutside(in Position p, string paramName)
    {
        if (!IsPositionInDomain(p))
        {
            throw new ArgumentException(
                "Position must have a unit quaternion and a finite origin within ±65,536 m (outdoor: x, y in [-192, 384]).",
                paramName);
        }
    }

    /// <summary>Throws when <paramref name="frame"/> is outside the domain of a frame of an object in <paramref name="cellId"/>.</summary>
    /// <exception cref="ArgumentException">The origin or the rotation is outside the domain.</exception>
    internal static void ThrowIfOutside(uint cellId, in Frame frame, string paramName)
    {
        if (!IsOriginInDomain(cellId, frame.Origin) || !IsRotationValid(frame))
        {
            throw new ArgumentException(
                "Frame must have a unit quaternion and a finite origin within ±65,536 m (outdoor: x, y in [-192, 384]).",
                paramName);
        }
    }

    /// <summary>True when <paramref name="frame"/> is a valid child frame: unit quaternion, each origin component within
    /// ±<see cref="MaxChildOffset"/>.</summary>
    internal static bool IsChildFrameInDomain(in Frame frame) =>
        Math.Abs(frame.Origin.X) <= MaxChildOffset && Math.Abs(frame.Origin.Y) <= MaxChildOffset
        && Math.Abs(frame.Origin.Z) <= MaxChildOffset && IsRotationValid(frame);

    /// <summary>True when <paramref name="scale"/> is in [<see cref="MinScale"/>, <see cref="MaxScale"/>].</summary>
    internal static bool IsScaleInDomain(float scale) => scale >= MinScale && scale <= MaxScale;

    /// <summary>Throws when <paramref name="scale"/> is outside [<see cref="MinScale"/>, <see cref="MaxScale"/>].</summary>
    /// <exception cref="ArgumentException">The scale is outside the domain (also NaN, infinities, zero and negatives).</exception>
    internal static void ThrowIfScaleOutside(float scale, string paramName)
    {
        if (!IsScaleInDomain(scale))
        {
            throw new ArgumentException("Scale must be in [0.01, 100].", paramName);
        }
    }

    /// <summary>True when <paramref name="time"/> is a clock time in (−<see cref="MaxClockTime"/>, <see cref="MaxClockTime"/>).</summary>
    internal static bool IsClockTimeInDomain(double time) => Math.Abs(time) < MaxClockTime;

    /// <summary>True when <paramref name="n"/> is finite and, when <paramref name="valid"/>, of unit length (|n|² within
    /// 5 × EPSILON of 1, the tolerance of <see cref="Frame.IsValid"/>).</summary>
    internal static bool IsNormalInDomain(Vector3 n, bool valid)
    {
        if (!VectorMath.IsFinite(n))
        {
            return false;
        }

        double m = (double)n.X * n.X + (double)n.Y * n.Y + (double)n.Z * n.Z;
        return !valid || Math.Abs(m - 1.0) <= PhysicsGlobals.Epsilon * 5.0;
    }

}
