namespace AcDream.Core.Physics.Scenery;

/// <summary>
/// The one pseudo-random function of the procedural scenery: every draw is
/// <c>h(x, y, k) = 1813693831·y − k·(1360117743·x·y + 1888038839) − 1109124029·x</c> in wrapping 32-bit unsigned arithmetic,
/// of a terrain vertex's global coordinates (landblock x·8 + vertex column, likewise y) and a salt <c>k</c>, and
/// <c>u = h · 2⁻³²</c> in [0, 1). The decompilation writes each draw with its salt folded in (and the frequency draw
/// strength-reduced); <c>Retail/SceneryHashTests</c> shows each is this function with the salts below.
/// </summary>
/// <remarks>
/// The decompilation's literal <c>2.3283064e-10</c> is the float 0x2F800000, exactly 2⁻³², and the x87 ran at 53 bits:
/// <see cref="Unit"/> is the exact double product, as the terrain split already computes it.
/// </remarks>
public static class SceneryHash
{
    /// <summary>The scene pick (<c>CLandBlock::get_land_scenes</c>, acclient.c:352529).</summary>
    public const uint ScenePickSalt = 11257;

    /// <summary>The frequency of object <c>k</c>: salt <c>23399 + k</c> (acclient.c:352529).</summary>
    public const uint FrequencySalt = 23399;

    /// <summary>The x displacement of object <c>k</c>: salt <c>45773 + k</c> (<c>ObjectDesc::Place</c>, acclient.c:462604).</summary>
    public const uint DisplaceXSalt = 45773;

    /// <summary>The y displacement of object <c>k</c>: salt <c>72719 + k</c> (<c>ObjectDesc::Place</c>).</summary>
    public const uint DisplaceYSalt = 72719;

    /// <summary>The vertex's quarter turn, shared by all its objects: salt 59371, no <c>k</c> (<c>ObjectDesc::Place</c>).</summary>
    public const uint QuadrantSalt = 59371;

    /// <summary>The scale of object <c>k</c>: salt <c>32593 + k</c> (<c>ObjectDesc::ScaleObj</c>, acclient.c:351360).</summary>
    public const uint ScaleSalt = 32593;

    /// <summary>The heading of object <c>k</c>: salt <c>63127 + k</c> (<c>ObjectDesc::GetObjFrame</c>, acclient.c:462659).</summary>
    public const uint HeadingSalt = 63127;

    /// <summary>2⁻³², the scale from a hash to [0, 1) (float 0x2F800000, printed <c>2.3283064e-10</c>).</summary>
    public const double UnitScale = 1.0 / 4294967296.0;

    /// <summary>The hash <c>h(x, y, salt)</c>, wrapping 32-bit unsigned.</summary>
    /// <param name="x">The vertex's global x (landblock x · 8 + vertex column, 0–2040).</param>
    /// <param name="y">The vertex's global y.</param>
    /// <param name="salt">The draw's salt (one of the constants, plus the object index where the draw has one).</param>
    public static uint Hash(uint x, uint y, uint salt) =>
        unchecked(1813693831u * y - salt * (1360117743u * y * x + 1888038839u) - 1109124029u * x);

    /// <summary>The draw <c>u = h(x, y, salt) · 2⁻³²</c>, in [0, 1), as the x87 computed it (53-bit double).</summary>
    public static double Unit(uint x, uint y, uint salt) => Hash(x, y, salt) * UnitScale;
}
