namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// Retail's compass-heading arithmetic: degrees clockwise from north (+Y), in [0, 360).
/// </summary>
internal static class HeadingMath
{
    /// <summary>Degrees per radian, retail's literal printed 57.29577951308232: the double nearest 180/π, bits
    /// 0x404CA5DC1A63C1F8 (these 16 digits parse back to it).</summary>
    public const double RadToDeg = 57.29577951308232;

    /// <summary>Radians per degree, retail's literal printed 0.0174532925199433 (acclient.c:357667, 357691). The binary
    /// holds the double nearest π/180, bits 0x3F91DF46A2529D39 (what a compiler emits for the source constant; its 16-digit
    /// print is the one shown); parsing the printed digits would give 0x3F91DF46A2529D3A, one ulp high.</summary>
    public const double DegToRad = 0.017453292519943295;

    /// <summary>
    /// Converts a mathematical angle <c>atan2(y, x)</c> (radians, anticlockwise from +X) to a compass heading in degrees
    /// clockwise from north: <c>fmod(450 - a * 57.29577951308232, 360)</c>. +Y gives 0, +X gives 90, -Y 180, -X 270.
    /// C's <c>fmod</c> and C#'s <c>%</c> on doubles agree (both truncate towards zero; the argument is always positive here
    /// because atan2 lies in [-180, 180] degrees).
    /// </summary>
    /// <remarks>
    /// The decompilation prints these calls as <c>atan2(v.x, v.y)</c> (acclient.c:357409, 357667, 467050). Read literally, the
    /// identity frame would face east with heading 90. We read the x87 <c>FPATAN</c> operand order as <c>atan2(v.y, v.x)</c>,
    /// which makes the identity frame face north with heading 0 — the convention of the game data, of ACE's port and of this
    /// library. The choice is pinned by <c>FrameHeadingTests</c>.
    /// </remarks>
    public static double CompassFromAtan2(double atan2Radians) => Fmod360(450.0 - atan2Radians * RadToDeg);

    /// <summary>
    /// C's <c>fmod(x, 360)</c> with the library call skipped where the result is known exactly: for 0 ≤ x &lt; 360 it is x,
    /// and for 360 ≤ x &lt; 720 it is x − 360, which double subtraction gives exactly (Sterbenz: x is within a factor of two
    /// of 360). An atan2 angle always lands in that range (270 ≤ x ≤ 630); anything else takes <c>%</c>.
    /// </summary>
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    internal static double Fmod360(double x)
    {
        if (x >= 0.0 && x < 720.0)
        {
            return x >= 360.0 ? x - 360.0 : x;
        }

        return x % 360.0;
    }
}
