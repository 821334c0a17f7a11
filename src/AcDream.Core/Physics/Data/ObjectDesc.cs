using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// One object spot of a <see cref="SceneEntry"/> (retail <c>ObjectDesc</c>, acclient.h:57271): what the procedural scenery
/// places at a terrain vertex, where around it, how often, and within which slope, scale and rotation.
/// <c>AcDream.Core.Physics.Scenery.ObjectPlacement</c> holds retail's placement functions over it.
/// </summary>
/// <param name="ObjectId">The Setup (0x02…) or GfxObj (0x01…) to make; 0 for a server spot. Retail: <c>obj_id</c>.</param>
/// <param name="BaseFrame">The spot's frame relative to its vertex (origin in metres, rotation). Retail: <c>base_loc</c>.</param>
/// <param name="Frequency">The chance, in [0, 1], that the spot is filled at a vertex. Retail: <c>freq</c>.</param>
/// <param name="DisplaceX">The largest random x offset, metres (0 or less: none). Retail: <c>displace_x</c>.</param>
/// <param name="DisplaceY">The largest random y offset, metres (0 or less: none). Retail: <c>displace_y</c>.</param>
/// <param name="MinScale">The smallest scale. Retail: <c>min_scale</c>.</param>
/// <param name="MaxScale">The largest scale. Retail: <c>max_scale</c>.</param>
/// <param name="MaxRotation">The largest random heading, degrees (0 or less: the base frame's). Retail: <c>max_rot</c>.</param>
/// <param name="MinSlope">The smallest terrain normal z (a cosine) the spot accepts. Retail: <c>min_slope</c>.</param>
/// <param name="MaxSlope">The largest terrain normal z (a cosine) the spot accepts. Retail: <c>max_slope</c>.</param>
/// <param name="Align">Non-zero: the object faces the heading of the terrain's <c>−N</c> (uphill) instead of a random heading. Retail: <c>align</c>.</param>
/// <param name="Orient">Stored but read by nothing in retail. Retail: <c>orient</c>.</param>
/// <param name="WeenieObj">Non-zero: a spot the server fills (an encounter); the client never makes it. Retail:
/// <c>weenie_obj</c>.</param>
public sealed record ObjectDesc(
    uint ObjectId,
    Frame BaseFrame,
    float Frequency,
    float DisplaceX,
    float DisplaceY,
    float MinScale,
    float MaxScale,
    float MaxRotation,
    float MinSlope,
    float MaxSlope,
    uint Align,
    uint Orient,
    uint WeenieObj)
{
    /// <summary>The bytes of one object spot on disk: id, frame (28), eleven 32-bit fields. Retail <c>Scene::Pack</c> sizes
    /// a scene <c>76 · n + 4</c> (acclient.c:463063).</summary>
    public const int PackedSize = 76;

    /// <summary>
    /// Reads one spot in <c>ObjectDesc::UnPack</c>'s order: id, frame (<c>Frame::UnPack</c>, acclient.c:357132), then freq,
    /// displace x, y, min and max scale, max rotation, min and max slope, align, orient, weenie object.
    /// </summary>
    /// <remarks>Retail keeps a field's constructor default (acclient.c:462677) when the bytes run out, and ignores a
    /// frame <c>Frame::IsValid</c> refuses; the library refuses both, and a non-finite float.</remarks>
    // retail: ObjectDesc::UnPack (acclient.c:462929)
    internal static ObjectDesc UnPack(ref RetailDataReader r)
    {
        if (r.Remaining < PackedSize)
        {
            throw r.Error($"an object spot needs {PackedSize} bytes, {r.Remaining} remain");
        }

        uint id = r.ReadUInt32("object id");
        Frame frame = r.ReadFrame("object base frame");
        float freq = r.ReadFiniteSingle("object frequency");
        float dx = r.ReadFiniteSingle("object displacement x");
        float dy = r.ReadFiniteSingle("object displacement y");
        float minScale = r.ReadFiniteSingle("object min scale");
        float maxScale = r.ReadFiniteSingle("object max scale");
        float maxRot = r.ReadFiniteSingle("object max rotation");
        float minSlope = r.ReadFiniteSingle("object min slope");
        float maxSlope = r.ReadFiniteSingle("object max slope");
        uint align = r.ReadUInt32("object align");
        uint orient = r.ReadUInt32("object orient");
        uint weenie = r.ReadUInt32("object weenie spot");
        return new ObjectDesc(id, frame, freq, dx, dy, minScale, maxScale, maxRot, minSlope, maxSlope, align, orient, weenie);
    }
}
