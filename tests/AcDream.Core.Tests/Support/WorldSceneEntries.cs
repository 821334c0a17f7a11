using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// A flat landblock 0x8080 at <see cref="BspScene.Ground"/> as retail entries, with the objects of the scene walks: a
/// pine-like Setup (one cylinder, radius 1.53 m, height 34.6 m, low point z −3.8 m), grass (a Setup with a drawing-only
/// part and no shapes), a low and a tall rock GfxObj (physics BSP boxes 0.4 m and 1.2 m high, 2 m wide) and a two-part
/// Setup building (part 0 a 2 m box at the building's origin, part 1 the same box 10 m north of it).
/// </summary>
internal static class WorldSceneEntries
{
    public const uint Block = 0x8080FFFF, Info = 0x8080FFFE;
    public const uint Pine = 0x02000010, Grass = 0x02000011, LowRock = 0x01000012, TallRock = 0x01000013, Building = 0x02000020;
    public const uint Blade = 0x01000011, Box = 0x01000020;

    /// <summary>The source with the landblock, its info (<paramref name="objects"/>, <paramref name="buildings"/>,
    /// <paramref name="restrictions"/>) and every model above.</summary>
    public static DictionarySource Source((uint Id, Frame Frame)[] objects, BuildingDef[]? buildings = null,
        (uint Key, uint Value)[]? restrictions = null)
    {
        var s = new DictionarySource();
        var height = new byte[81];
        Array.Fill(height, (byte)BspScene.Ground);
        s.Entries[Block] = RetailEntries.LandBlock(Block, true, new ushort[81], height);
        s.Entries[Info] = RetailEntries.LandBlockInfo(Info, 0, objects, buildings ?? [], restrictions);
        AddModels(s);
        return s;
    }

    /// <summary>Adds the models (Setups and GfxObjs) to <paramref name="s"/>.</summary>
    public static void AddModels(DictionarySource s)
    {
        s.Entries[Blade] = WorldEntries.DrawingOnlyGfxObj(Blade, new Vector3(-0.2f, -0.2f, 0f), new Vector3(0.2f, 0.2f, 0.5f));
        s.Entries[Pine] = WorldEntries.Setup(new SetupDef(Pine, [Blade])
        {
            CylSpheres = [(new Vector3(0f, 0f, -3.8f), 1.53f, 34.6f)],
            Height = 30.8f,
            Radius = 1.53f,
            Placements = [(0x65, [Frame.Identity])],
        });
        s.Entries[Grass] = WorldEntries.Setup(new SetupDef(Grass, [Blade]) { Placements = [(0x65, [Frame.Identity])] });
        s.Entries[LowRock] = WorldEntries.PhysicsGfxObj(LowRock, BoxPolys(new Vector3(-1f, -1f, 0f), new Vector3(1f, 1f, 0.4f)));
        s.Entries[TallRock] = WorldEntries.PhysicsGfxObj(TallRock, BoxPolys(new Vector3(-1f, -1f, 0f), new Vector3(1f, 1f, 1.2f)));
        s.Entries[Box] = WorldEntries.PhysicsGfxObj(Box, BoxPolys(new Vector3(-1f, -1f, 0f), new Vector3(1f, 1f, 3f)));
        s.Entries[Building] = WorldEntries.Setup(new SetupDef(Building, [Box, Box])
        {
            Placements = [(0x65, [Frame.Identity, new Frame(new Vector3(0f, 10f, 0f), Quaternion.Identity)])],
            Sorting = (new Vector3(0f, 5f, 1.5f), 7f),
        });
    }

    /// <summary>The six outward faces of a box.</summary>
    public static List<Polygon> BoxPolys(Vector3 min, Vector3 max)
    {
        var polys = new List<Polygon>();
        BoxShapes.AddBox(polys, min, max);
        return polys;
    }

    /// <summary>A world over the flat terrain table (no landblock yet), sweeping with the retail sweep over world cells.</summary>
    public static PhysicsWorld World(out WorldCells cells)
    {
        cells = new WorldCells(SweepScene.Terrain());
        var world = new PhysicsWorld(0.0);
        world.Sweep = new RetailSweep(cells);
        return world;
    }

    /// <summary>A frame at block-local (x, y) on the ground.</summary>
    public static Frame At(float x, float y) => new(new Vector3(x, y, BspScene.Ground), Quaternion.Identity);
}
