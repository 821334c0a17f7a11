namespace AcDream.Core.Physics.Motion;

/// <summary>Argument checks of the motion API.</summary>
internal static class MotionChecks
{
    /// <summary>The value, or an <see cref="System.ArgumentException"/> when it is NaN or infinite.</summary>
    public static float Finite(float value) =>
        float.IsFinite(value) ? value : throw new System.ArgumentException("Motion speeds and rates must be finite.", nameof(value));

    /// <summary>The message of the refused <c>default(MovementParameters)</c>.</summary>
    public const string DefaultParametersMessage =
        "default(MovementParameters) is all zeros; use new MovementParameters() for retail's defaults.";

    /// <summary>Throws when the parameters are <c>default(MovementParameters)</c> (every field zero) or their speed is NaN
    /// or infinite.</summary>
    public static void Check(in MovementParameters p)
    {
        // Flags first: retail's defaults (and every parameter the interpreter builds) have flags, so one compare decides.
        if (p.Flags == MovementParameterFlags.None && p.IsAllZero)
        {
            throw new System.ArgumentException(DefaultParametersMessage, nameof(p));
        }

        if (!float.IsFinite(p.Speed))
        {
            throw new System.ArgumentException("The motion speed must be finite.", nameof(p));
        }
    }
}
