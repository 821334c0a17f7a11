using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion;

/// <summary>Argument checks of the motion API: speeds within ±<see cref="InputLimits.MaxMotionSpeed"/>, run rates in
/// (0, <see cref="InputLimits.MaxRunRate"/>].</summary>
internal static class MotionChecks
{
    /// <summary>The speed, or an <see cref="System.ArgumentException"/> when it is NaN, infinite or beyond
    /// ±<see cref="InputLimits.MaxMotionSpeed"/>.</summary>
    public static float Speed(float value) =>
        IsSpeedInDomain(value)
            ? value
            : throw new System.ArgumentException(
                $"Motion speeds must be finite and within ±{InputLimits.MaxMotionSpeed} (got {value}).", nameof(value));

    /// <summary>True when <paramref name="value"/> is a motion speed: finite, |value| ≤ <see cref="InputLimits.MaxMotionSpeed"/>
    /// (NaN fails the compare).</summary>
    public static bool IsSpeedInDomain(float value) => System.Math.Abs(value) <= InputLimits.MaxMotionSpeed;

    /// <summary>True when <paramref name="value"/> is a run rate: in (0, <see cref="InputLimits.MaxRunRate"/>] (NaN fails).</summary>
    public static bool IsRunRateInDomain(float value) => value > 0f && value <= InputLimits.MaxRunRate;

    /// <summary>The run rate, or an <see cref="System.ArgumentException"/> when it is not in (0, <see cref="InputLimits.MaxRunRate"/>].</summary>
    public static float RunRate(float value, string paramName = "value") =>
        IsRunRateInDomain(value)
            ? value
            : throw new System.ArgumentException(
                $"A run rate must be in (0, {InputLimits.MaxRunRate}] (got {value}).", paramName);

    /// <summary>Throws unless <paramref name="s"/> is in the domain of a state handed to the interpreter whole: an
    /// interpreted <see cref="MotionCommand.RunForward"/> runs at a run rate (its speed in (0, <see cref="InputLimits.MaxRunRate"/>],
    /// which <c>apply_interpreted_movement</c> takes as the interpreter's run rate), and every action's speed is a motion speed.</summary>
    public static void CheckState(InterpretedMotionState s, string paramName)
    {
        if (s.ForwardCommand == MotionCommand.RunForward && !IsRunRateInDomain(s.ForwardSpeed))
        {
            throw new System.ArgumentException(
                $"A RunForward state runs at a run rate, in (0, {InputLimits.MaxRunRate}] (got {s.ForwardSpeed}).", paramName);
        }

        for (int i = 0; i < s.Actions.Count; i++)
        {
            if (!IsSpeedInDomain(s.Actions[i].Speed))
            {
                throw new System.ArgumentException("An action's speed must be a motion speed.", paramName);
            }
        }
    }

    /// <summary>The message of the refused <c>default(MovementParameters)</c>.</summary>
    public const string DefaultParametersMessage =
        "default(MovementParameters) is all zeros; use new MovementParameters() for retail's defaults.";

    /// <summary>Throws when the parameters are <c>default(MovementParameters)</c> (every field zero) or their speed is NaN,
    /// infinite or beyond ±<see cref="InputLimits.MaxMotionSpeed"/>.</summary>
    public static void Check(in MovementParameters p)
    {
        // Flags first: retail's defaults (and every parameter the interpreter builds) have flags, so one compare decides.
        if (p.Flags == MovementParameterFlags.None && p.IsAllZero)
        {
            throw new System.ArgumentException(DefaultParametersMessage, nameof(p));
        }

        if (!IsSpeedInDomain(p.Speed))
        {
            throw new System.ArgumentException(
                $"The motion speed must be finite and within ±{InputLimits.MaxMotionSpeed} (got {p.Speed}).", nameof(p));
        }
    }
}
