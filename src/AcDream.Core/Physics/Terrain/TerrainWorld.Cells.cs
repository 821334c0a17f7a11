using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Terrain;

/// <summary>The terrain world as the sweep's cell source.</summary>
public sealed partial class TerrainWorld : ICellSource
{
    /// <summary>The world whose objects' shadows these cells hold (set when a world takes a sweep over them).</summary>
    internal PhysicsWorld? OwnerWorld { get; set; }

    /// <summary>The loaded outdoor cell <paramref name="cellId"/>, or null (interior cells arrive with issue 6).</summary>
    // retail: CObjCell::GetVisible (acclient.c:346416) -> CLandCell::Get (acclient.c:354915) -> LScape::get_landcell
    public ObjCell? GetVisible(uint cellId) => GetLandCell(cellId);
}
