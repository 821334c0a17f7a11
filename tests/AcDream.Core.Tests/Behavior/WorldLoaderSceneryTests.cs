using System;
using System.Linq;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.WorldSceneEntries;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The door places the region's scenery (issue #35): retail's <c>get_land_scenes</c> (acclient.c:352529) reads the region
/// (<c>CRegionDesc::current_region</c>; none, no scenery: 352610), skips the land cell holding a building (352697), and makes,
/// checks within the block at scale 1 (352721) and shadows each spot. The block: every vertex grassland (type 1) at scene slot
/// 1, whose one scene 0x12000010 holds one pine spot at cell-local (12, 12), always placed, unturned by rotation, scale 1.
/// </summary>
public class WorldLoaderSceneryTests
{
    private static DictionarySource SourceWithScenery(bool withRegion, bool withBuilding)
    {
        DictionarySource s = Source([], withBuilding ? [new BuildingDef(LowRock, At(12f, 12f), 0, [])] : null);
        var height = new byte[81];
        Array.Fill(height, (byte)BspScene.Ground);
        var words = new ushort[81];
        Array.Fill(words, SceneryScene.Word(1, 1));
        s.Entries[Block] = RetailEntries.LandBlock(Block, true, words, height);
        s.Entries[SceneryScene.SingleScene] = RegionSceneBytes.Scene(SceneryScene.SingleScene,
            [SceneryScene.Spot(new Vector3(12f, 12f, 0f), Pine)]);
        if (withRegion)
        {
            s.Entries[WorldLoader.DerethRegionId] = SceneryScene.RegionBytes();
        }

        return s;
    }

    // By hand, from ObjectDesc::Place: the spot (12, 12) turned by the vertex's quarter turn (SceneryHash's quadrant salt,
    // pinned in SceneryHashTests), plus the vertex offset (24 i, 24 j); kept when the pine's cylinder (r 1.53, low point at the
    // origin's x, y) lies within the block, r <= x < 192 - r (obj_within_block, 318306), and, with the building, when its
    // cell is not cell (0, 0), which holds the building's origin (12, 12).
    private static Vector2[] Expected(bool withBuilding)
    {
        const uint blockX = 0x80 * 8, blockY = 0x80 * 8;
        var list = new System.Collections.Generic.List<Vector2>();
        for (uint i = 0; i < 9; i++)
        {
            for (uint j = 0; j < 9; j++)
            {
                Vector2 p = SceneryScene.Turn(blockX + i, blockY + j, new Vector2(12f, 12f)) + new Vector2(24f * i, 24f * j);
                bool inBlock = p.X >= 0f && p.X < 192f && p.Y >= 0f && p.Y < 192f;
                bool within = p.X >= 1.53f && p.X < 192f - 1.53f && p.Y >= 1.53f && p.Y < 192f - 1.53f;
                bool buildingCell = withBuilding && p.X < 24f && p.Y < 24f;
                if (inBlock && within && !buildingCell)
                {
                    list.Add(p);
                }
            }
        }

        return list.ToArray();
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void TheRegionsScenery_IsBuilt_WhereRetailPlacesIt(bool withBuilding)
    {
        PhysicsWorld world = World(out _);
        var loader = new WorldLoader(world, SourceWithScenery(withRegion: true, withBuilding));
        Assert.NotNull(loader.Region);
        WorldBlock b = loader.Load(Block)[0];
        Vector2[] got = b.Objects.Where(o => o.Kind == WorldObjectKind.Scenery)
            .Select(o => new Vector2(o.Frame.Origin.X, o.Frame.Origin.Y)).ToArray();
        Vector2[] expected = Expected(withBuilding);
        Assert.True(expected.Length > 30, $"the scene should grow most of its 81 spots, got {expected.Length}");
        Assert.Equal(expected, got);
        Assert.All(b.Objects.Where(o => o.Kind == WorldObjectKind.Scenery), o => Assert.Equal(Pine, o.DataId));
    }

    [Fact]
    public void TheRegionId_IsDerethsPortalEntry()
    {
        // Region entries are 0x13xxxxxx in the portal file; Dereth, the world of the data in ../shared, is 0x13000000.
        Assert.Equal(0x13000000u, WorldLoader.DerethRegionId);
    }

    [Fact]
    public void WithoutARegion_TheBlockHasNoScenery()
    {
        PhysicsWorld world = World(out _);
        var loader = new WorldLoader(world, SourceWithScenery(withRegion: false, withBuilding: false));
        Assert.Null(loader.Region);
        WorldBlock b = loader.Load(Block)[0];
        Assert.DoesNotContain(b.Objects, o => o.Kind == WorldObjectKind.Scenery);
    }

    [Fact]
    public void ABadScene_IsAFormatError_AndNothingIsAdded()
    {
        PhysicsWorld world = World(out WorldCells cells);
        DictionarySource s = SourceWithScenery(withRegion: true, withBuilding: false);
        s.Entries[SceneryScene.SingleScene] = s.Entries[SceneryScene.SingleScene][..6];
        var loader = new WorldLoader(world, s);
        Assert.Throws<AcDream.Core.Physics.Format.RetailDataFormatException>(() => loader.Load(Block));
        Assert.Equal(0, world.ObjectCount);
        Assert.Empty(loader.LoadedBlockIds);
        Assert.Null(cells.Terrain.GetLandCell(Block & 0xFFFF0000u | 1u));
    }
}
