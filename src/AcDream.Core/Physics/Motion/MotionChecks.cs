namespace AcDream.Core.Physics.Motion;

/// <summary>Argument checks of the motion API.</summary>
internal static class MotionChecks
{
    /// <summary>The value, or an <see cref="System.ArgumentException"/> when it is NaN or infinite.</summary>
    public static float Finite(float value) =>
        float.IsFinite(value) ? value : throw new System.ArgumentException("Motion speeds and rates must be finite.", nameof(value));

    /// <summary>Throws when the parameters' speed is NaN or infinite.</summary>
    public static void Check(in MovementParameters p)
    {
        if (!float.IsFinite(p.Speed))
        {
            throw new System.ArgumentException("The motion speed must be finite.", nameof(p));
        }
    }
}
