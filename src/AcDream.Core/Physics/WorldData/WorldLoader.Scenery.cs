using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Scenery;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.WorldData;

// The door's procedural scenery: the region's scene tables placed by SceneryGenerator, read before the world changes.
public sealed partial class WorldLoader
{
    /// <summary>The region id of Dereth (<c>0x13000000</c>), the one region retail's client loads.</summary>
    public const uint DerethRegionId = 0x13000000u;

    private readonly Dictionary<uint, SceneEntry?> _scenes = new();
    private readonly List<ScenePlacement> _placements = new();

    /// <summary>
    /// The region whose terrain and scene tables place each loaded block's procedural scenery (retail
    /// <c>CRegionDesc::current_region</c>); the constructor reads <see cref="DerethRegionId"/> when the data source holds it.
    /// Null: blocks load without scenery, as retail's <c>get_land_scenes</c> does without a region (acclient.c:352610).
    /// </summary>
    /// <remarks>Set it between loads; blocks already loaded keep the scenery they were built with.</remarks>
    public RegionEntry? Region { get; set; }

    // The region the source holds, read once at construction (a bad entry is a format error there, before any load).
    private static RegionEntry? ReadRegion(IRetailDataSource source) =>
        source.TryGetEntry(DerethRegionId, out ReadOnlyMemory<byte> bytes) ? RegionEntry.UnPack(bytes.Span) : null;

    // The scenery of a block, placed up to makeObject (steps 1–10 of get_land_scenes and the ScaleObj value) before the world
    // changes: a bad scene entry throws here, with nothing added. The land cells holding a building are those under the
    // origin of each building of the block whose model can be made (init_buildings runs before, in retail's first pass;
    // a building outside the block is dropped, and CSortCell::has_building is per land cell).
    private IReadOnlyList<SceneryItem> RegionScenery(uint block, LandBlock landBlock, LandBlockInfoEntry? info)
    {
        if (Region is null)
        {
            return Array.Empty<SceneryItem>();
        }

        HashSet<uint>? buildingCells = null;
        if (info is not null)
        {
            foreach (BuildingInfo b in info.Buildings)
            {
                if (Objects.InitPartArrayModel(b.ModelId, out _) is not null
                    && GetLandCell(landBlock, block, b.Frame.Origin) is LandCell cell)
                {
                    (buildingCells ??= new HashSet<uint>()).Add(cell.Id);
                }
            }
        }

        _placements.Clear();
        SceneryGenerator.Generate(landBlock, Region, LookupScene, buildingCells is null ? null : buildingCells.Contains,
            _placements);
        var items = new SceneryItem[_placements.Count];
        for (int i = 0; i < items.Length; i++)
        {
            ScenePlacement p = _placements[i];
            items[i] = new SceneryItem(p.ObjectId, p.LandCellId, p.Frame, p.Scale);
        }

        return items;
    }

    // A scene by id (0x12…), read once per door; null when the source holds none (retail skips the vertex).
    private SceneEntry? LookupScene(uint id)
    {
        if (!_scenes.TryGetValue(id, out SceneEntry? scene))
        {
            scene = _source.TryGetEntry(id, out ReadOnlyMemory<byte> bytes) ? SceneEntry.UnPack(bytes.Span) : null;
            _scenes[id] = scene;
        }

        return scene;
    }
}
