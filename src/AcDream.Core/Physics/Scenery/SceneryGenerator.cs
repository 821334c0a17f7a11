using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.Scenery;

/// <summary>
/// Retail's procedural scenery of one landblock (<c>CLandBlock::get_land_scenes</c>, acclient.c:352529) as a pure function:
/// the objects retail makes from the region's scene tables at the block's terrain vertices, with their land cell, frame and
/// scale, up to <c>makeObject</c>. What needs the object's shape, <c>obj_within_block</c>, is <see cref="ObjWithinBlock"/>,
/// which the caller runs on each placement at scale 1 once it knows the object's shape (docs/world.md, "Procedural
/// scenery").
/// </summary>
public static partial class SceneryGenerator
{
    /// <summary>
    /// Appends the scenery of <paramref name="block"/> to <paramref name="placements"/>, in retail's order (vertex column
    /// outer, row inner, then the scene's objects), and returns how many were appended. The block's terrain words give
    /// each vertex's terrain type (bits 2–6), scene-type slot (bits 11–15) and roads (bits 0–1); its triangles give the
    /// height and slope.
    /// </summary>
    /// <param name="block">The landblock (its height table is the one it was built with: the region's, for retail's).</param>
    /// <param name="region">The region: its terrain types name the scene types, and those the scenes.</param>
    /// <param name="sceneLookup">The scene of an id (0x12…), or null when the data holds none (retail skips the vertex).</param>
    /// <param name="cellHasBuilding">True for a land cell id holding a building (retail <c>CSortCell::has_building</c>:
    /// the cell of a building's origin, first building kept); such a cell grows no scenery. Null: no buildings.</param>
    /// <param name="placements">Where the placements are appended.</param>
    /// <exception cref="ArgumentNullException">An argument other than <paramref name="cellHasBuilding"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">A scene's bytes, read by <paramref name="sceneLookup"/>, are bad; nothing
    /// is appended then.</exception>
    // retail: CLandBlock::get_land_scenes (acclient.c:352529)
    public static int Generate(LandBlock block, RegionEntry region, Func<uint, SceneEntry?> sceneLookup,
        Func<uint, bool>? cellHasBuilding, List<ScenePlacement> placements)
    {
        ArgumentNullException.ThrowIfNull(block);
        ArgumentNullException.ThrowIfNull(region);
        ArgumentNullException.ThrowIfNull(sceneLookup);
        ArgumentNullException.ThrowIfNull(placements);
        int start = placements.Count;
        try
        {
            GetLandScenes(block, region, sceneLookup, cellHasBuilding, placements);
        }
        catch
        {
            placements.RemoveRange(start, placements.Count - start);
            throw;
        }

        return placements.Count - start;
    }

    /// <summary>
    /// Appends the scenery of the landblock <paramref name="block"/> (built with the region's height table) to
    /// <paramref name="placements"/>, reading scenes (0x12…) from <paramref name="source"/>; returns how many were appended.
    /// See <see cref="Generate(LandBlock, RegionEntry, Func{uint, SceneEntry}, Func{uint, bool}, List{ScenePlacement})"/>.
    /// </summary>
    /// <param name="block">The landblock's entry.</param>
    /// <param name="region">The region.</param>
    /// <param name="source">The data files: scenes the source does not hold are skipped, as retail skips them.</param>
    /// <param name="buildingCells">The land cell ids holding a building; null for none.</param>
    /// <param name="placements">Where the placements are appended.</param>
    /// <exception cref="ArgumentNullException">An argument other than <paramref name="buildingCells"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">A scene entry's bytes are bad; nothing is appended then.</exception>
    public static int Generate(LandBlockEntry block, RegionEntry region, IRetailDataSource source,
        IReadOnlySet<uint>? buildingCells, List<ScenePlacement> placements)
    {
        ArgumentNullException.ThrowIfNull(block);
        ArgumentNullException.ThrowIfNull(region);
        ArgumentNullException.ThrowIfNull(source);
        ArgumentNullException.ThrowIfNull(placements);
        var scenes = new Dictionary<uint, SceneEntry?>();
        SceneEntry? Lookup(uint id)
        {
            if (!scenes.TryGetValue(id, out SceneEntry? s))
            {
                s = source.TryGetEntry(id, out ReadOnlyMemory<byte> bytes) ? SceneEntry.UnPack(bytes.Span) : null;
                scenes[id] = s;
            }

            return s;
        }

        Func<uint, bool>? hasBuilding = buildingCells is null ? null : buildingCells.Contains;
        return Generate(block.ToLandBlock(region.LandHeightTable), region, Lookup, hasBuilding, placements);
    }

    // retail: CLandBlock::get_land_scenes (acclient.c:352529)
    private static void GetLandScenes(LandBlock block, RegionEntry region, Func<uint, SceneEntry?> sceneLookup,
        Func<uint, bool>? cellHasBuilding, List<ScenePlacement> placements)
    {
        ReadOnlySpan<ushort> terrain = block.Terrain;
        uint blockX = (uint)block.BlockX * LandDefs.BlockSide, blockY = (uint)block.BlockY * LandDefs.BlockSide;
        for (int i = 0; i < LandBlock.SideVertexCount; i++)
        {
            for (int j = 0; j < LandBlock.SideVertexCount; j++)
            {
                ushort word = terrain[i * LandBlock.SideVertexCount + j];
                uint type = (uint)(word >> 2) & 0x1F;
                uint slot = (uint)word >> 11;
                if (slot >= (uint)region.NumSceneType(type))
                {
                    continue;
                }

                int count = region.SceneCount(type, slot);
                if (count == 0)
                {
                    continue;
                }

                uint x = blockX + (uint)i, y = blockY + (uint)j;
                uint pick = 0;
                if (count != 1)
                {
                    pick = unchecked((uint)(ulong)Math.Floor(SceneryHash.Unit(x, y, SceneryHash.ScenePickSalt) * count));
                    if (pick >= (uint)count)
                    {
                        pick = 0; // an index past the list becomes 0, not a skip (acclient.c:352645)
                    }
                }

                uint sceneId = region.GetScene(type, slot, pick);
                SceneEntry? scene = sceneId == 0 ? null : sceneLookup(sceneId);
                if (scene is null)
                {
                    continue;
                }

                PlaceScene(block, scene, x, y, i, j, cellHasBuilding, placements);
            }
        }
    }

    /// <summary>The outdoor cell holding block-local <paramref name="origin"/> of block <paramref name="blockId"/>; 0 past
    /// the world's edge.</summary>
    // retail: Position::get_outside_cell_id (acclient.c:143773)
    private static uint OutsideCellId(uint blockId, Vector3 origin)
    {
        uint cellId = blockId;
        return LandDefs.AdjustToOutside(ref cellId, ref origin) ? cellId : 0u;
    }

    // The loop over one scene's objects at vertex (i, j) of get_land_scenes (acclient.c:352529).
    private static void PlaceScene(LandBlock block, SceneEntry scene, uint x, uint y, int i, int j,
        Func<uint, bool>? cellHasBuilding, List<ScenePlacement> placements)
    {
        IReadOnlyList<ObjectDesc> objects = scene.Objects;
        for (int k = 0; k < objects.Count; k++)
        {
            ObjectDesc desc = objects[k];
            uint uk = (uint)k;
            if (!(SceneryHash.Unit(x, y, SceneryHash.FrequencySalt + uk) < desc.Frequency) || desc.WeenieObj != 0)
            {
                continue;
            }

            Vector3 v = ObjectPlacement.Place(desc, x, y, uk);
            v.X = (float)(i * 24.0 + v.X);
            v.Y = (float)(j * 24.0 + v.Y);
            if (!(v.X >= 0.0 && v.Y >= 0.0 && v.X < (double)LandDefs.BlockLength && v.Y < (double)LandDefs.BlockLength)
                || OnRoadUnchecked(block.Terrain, v.X, v.Y))
            {
                continue;
            }

            uint cellId = OutsideCellId(block.Id, v);
            LandCell? cell = cellId != 0 ? block.GetLandCell(cellId) : null;
            if (cell is null || cellHasBuilding?.Invoke(cellId) == true
                || !cell.FindTerrainPoly(v, out Polygon? walkable) || !ObjectPlacement.CheckSlope(desc, walkable.Plane.N.Z))
            {
                continue;
            }

            walkable.Plane.SetHeight(ref v);
            Frame frame = desc.Align != 0
                ? ObjectPlacement.ObjAlign(desc, walkable.Plane, v)
                : ObjectPlacement.GetObjFrame(desc, x, y, uk, v);
            float scale = ObjectPlacement.ScaleObj(desc, x, y, uk);
            placements.Add(new ScenePlacement(desc.ObjectId, cellId, frame, scale, scene.Id, k, i, j));
        }
    }
}
