using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// Shared builders for static-geometry scenes: boxes as one-sided quads with outward normals, buildings (a BSP shell on
/// the land cells it covers), indoor cells with portals, and a world over flat terrain at <see cref="Ground"/>.
/// </summary>
internal static class BspScene
{
    /// <summary>Height of the flat terrain, metres (height index 20 of the one-metre table).</summary>
    public const float Ground = 20f;

    /// <summary>A flat landblock (0x80, 0x80) at <see cref="Ground"/> with a cell source for indoor cells.</summary>
    public static WorldCells FlatWorld()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => (int)Ground);
        return new WorldCells(terrain);
    }

    /// <summary>A physics world sweeping through <paramref name="cells"/> with the retail sweep.</summary>
    public static PhysicsWorld Physics(WorldCells cells)
    {
        var world = new PhysicsWorld(0.0);
        world.Sweep = new RetailSweep(cells);
        return world;
    }

    /// <summary>The outdoor cell id under the landblock-local point (x, y) of block (0x80, 0x80).</summary>
    public static uint OutdoorCell(float x, float y) =>
        SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, (int)(x / 24f), (int)(y / 24f));

    /// <summary>An indoor cell id of block (0x80, 0x80).</summary>
    public static uint IndoorCell(int index) => ((uint)SweepScene.BlockX << 24) | ((uint)SweepScene.BlockY << 16) | (uint)(0x100 + index);

    /// <summary>A quad with corners in order (counter-clockwise seen from the side it faces).</summary>
    public static Polygon Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d, short id = 0) => BoxShapes.Quad(a, b, c, d, id);

    /// <summary>Appends the six outward-facing faces of the box <paramref name="min"/>..<paramref name="max"/>.</summary>
    public static void AddBox(List<Polygon> polys, Vector3 min, Vector3 max) => BoxShapes.AddBox(polys, min, max);

    /// <summary>
    /// Places a building whose shell is <paramref name="shell"/> (local to <paramref name="origin"/>, identity rotation)
    /// on every land cell its bounding box covers (with a 1 m margin), with doors <paramref name="portals"/>.
    /// </summary>
    public static BuildingObj AddBuilding(WorldCells cells, Vector3 origin, List<Polygon> shell, params BldPortal[] portals) =>
        AddBuilding(cells, new Frame(origin, Quaternion.Identity), 1f, shell, portals);

    /// <summary>
    /// Places a building whose shell is <paramref name="shell"/> in part space: a part point p lies at
    /// <c>frame.LocalToGlobal(p * scale)</c>. It is attached to the land cells under its bounding box (1 m margin).
    /// </summary>
    public static BuildingObj AddBuilding(WorldCells cells, in Frame frame, float scale, List<Polygon> shell, params BldPortal[] portals)
    {
        BspTree bsp = BspBuilder.Build(shell.ToArray());
        Vector3 origin = frame.Origin;
        var part = new PhysicsPart(new GfxObjPhysics(bsp), new Position(OutdoorCell(origin.X, origin.Y), frame), new Vector3(scale));
        var building = new BuildingObj(part, portals);
        Vector3 min = new(float.MaxValue), max = new(float.MinValue);
        foreach (Polygon p in shell)
        {
            foreach (Vector3 v in p.Vertices)
            {
                Vector3 g = frame.LocalToGlobal(v * scale);
                min = Vector3.Min(min, g);
                max = Vector3.Max(max, g);
            }
        }

        for (int cx = (int)((min.X - 1f) / 24f); cx <= (int)((max.X + 1f) / 24f); cx++)
        {
            for (int cy = (int)((min.Y - 1f) / 24f); cy <= (int)((max.Y + 1f) / 24f); cy++)
            {
                LandCell? lc = cells.Terrain.GetLandCell(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, cx, cy));
                if (lc is not null)
                {
                    lc.Building = building;
                }
            }
        }

        return building;
    }

    /// <summary>A building made of solid boxes (no doors), each given by its min and max corners relative to <paramref name="origin"/>.</summary>
    public static BuildingObj AddBoxes(WorldCells cells, Vector3 origin, params (Vector3 Min, Vector3 Max)[] boxes)
    {
        var polys = new List<Polygon>();
        foreach (var (mn, mx) in boxes)
        {
            AddBox(polys, mn, mx);
        }

        return AddBuilding(cells, origin, polys);
    }

    /// <summary>Distance from <paramref name="p"/> to the box <paramref name="min"/>..<paramref name="max"/> (0 inside).</summary>
    public static float DistanceToBox(Vector3 p, Vector3 min, Vector3 max)
    {
        float dx = MathF.Max(MathF.Max(min.X - p.X, 0f), p.X - max.X);
        float dy = MathF.Max(MathF.Max(min.Y - p.Y, 0f), p.Y - max.Y);
        float dz = MathF.Max(MathF.Max(min.Z - p.Z, 0f), p.Z - max.Z);
        return MathF.Sqrt(dx * dx + dy * dy + dz * dz);
    }

    /// <summary>
    /// A walker with two spheres of radius <paramref name="r"/>: feet (centre (0, 0, r)) and head (centre (0, 0, r + 1)).
    /// Default state minus EDGE_SLIDE; step heights 0.4.
    /// </summary>
    public static PhysicsObj TwoSphereWalker(PhysicsWorld world, in Position p, float r = 0.5f, uint id = 1)
    {
        var parts = new SimplePartArray(1, 0) { StepUpHeight = 0.4f, StepDownHeight = 0.4f };
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, r), r), new Sphere(new Vector3(0f, 0f, r + 1f), r) });
        return Walkers.Create(world, id, p, parts, (PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.EdgeSlide);
    }

    /// <summary>The centre of the walker's single sphere (radius r, resting on its origin).</summary>
    public static Vector3 SphereCenter(PhysicsObj obj, float r) => obj.Position.Frame.Origin + new Vector3(0f, 0f, r);
}

/// <summary>
/// A one-room building at <see cref="Origin"/>: interior x 0..6, y 0..6, z 0..3 (local), walls 0.2 m thick, a 2 m wide,
/// 2.5 m high door in the south wall (x 2..4), and behind the north wall a corridor cell (x 2..4, y 6.2..12) reached
/// through a 2 m opening. Cells: the room 0x80800100 and the corridor 0x80800101.
/// </summary>
internal static class RoomScene
{
    /// <summary>The building's origin in the landblock.</summary>
    public static readonly Vector3 Origin = new(100f, 100f, BspScene.Ground);

    /// <summary>The room's cell id.</summary>
    public static readonly uint Room = BspScene.IndoorCell(0);

    /// <summary>The corridor's cell id.</summary>
    public static readonly uint Corridor = BspScene.IndoorCell(1);

    /// <summary>The building's frame for a heading (degrees clockwise from north; 0 = local axes are the landblock's).</summary>
    public static Frame FrameFor(float heading) => Frame.FromHeading(Origin, heading);

    /// <summary>Builds the scene into <paramref name="cells"/>, turned to <paramref name="heading"/>.</summary>
    public static void Build(WorldCells cells, float heading = 0f)
    {
        Frame frame = FrameFor(heading);
        // Shell (outdoor collision), local to the origin.
        var shell = new List<Polygon>();
        BspScene.AddBox(shell, new(-0.2f, -0.2f, 0f), new(2f, 0f, 3f));     // south wall, west of the door
        BspScene.AddBox(shell, new(4f, -0.2f, 0f), new(6.2f, 0f, 3f));      // south wall, east of the door
        BspScene.AddBox(shell, new(2f, -0.2f, 2.5f), new(4f, 0f, 3f));      // lintel
        BspScene.AddBox(shell, new(-0.2f, 6f, 0f), new(2f, 6.2f, 3f));      // north wall, west of the opening
        BspScene.AddBox(shell, new(4f, 6f, 0f), new(6.2f, 6.2f, 3f));       // north wall, east of the opening
        BspScene.AddBox(shell, new(-0.2f, 0f, 0f), new(0f, 6f, 3f));        // west wall
        BspScene.AddBox(shell, new(6f, 0f, 0f), new(6.2f, 6f, 3f));         // east wall
        BspScene.AddBox(shell, new(1.8f, 6.2f, 0f), new(2f, 12.2f, 3f));    // corridor, west wall
        BspScene.AddBox(shell, new(4f, 6.2f, 0f), new(4.2f, 12.2f, 3f));    // corridor, east wall
        BspScene.AddBox(shell, new(1.8f, 12f, 0f), new(4.2f, 12.2f, 3f));   // corridor, end wall
        BspScene.AddBuilding(cells, frame, 1f, shell, new BldPortal(Room, 0));

        // Room: floor over the room and the door's threshold, inward wall faces, the door and corridor portals.
        var room = new List<Polygon>();
        room.Add(BspScene.Quad(new(0f, -0.2f, 0f), new(6f, -0.2f, 0f), new(6f, 6f, 0f), new(0f, 6f, 0f)));          // floor, +z
        room.Add(BspScene.Quad(new(0f, 6f, 0f), new(2f, 6f, 0f), new(2f, 6f, 3f), new(0f, 6f, 3f)));               // north, -y
        room.Add(BspScene.Quad(new(4f, 6f, 0f), new(6f, 6f, 0f), new(6f, 6f, 3f), new(4f, 6f, 3f)));               // north, -y
        room.Add(BspScene.Quad(new(0f, 0f, 0f), new(0f, 0f, 3f), new(2f, 0f, 3f), new(2f, 0f, 0f)));               // south, +y
        room.Add(BspScene.Quad(new(4f, 0f, 0f), new(4f, 0f, 3f), new(6f, 0f, 3f), new(6f, 0f, 0f)));               // south, +y
        room.Add(BspScene.Quad(new(0f, 0f, 0f), new(0f, 6f, 0f), new(0f, 6f, 3f), new(0f, 0f, 3f)));               // west, +x
        room.Add(BspScene.Quad(new(6f, 0f, 0f), new(6f, 0f, 3f), new(6f, 6f, 3f), new(6f, 6f, 0f)));               // east, -x
        Polygon door = BspScene.Quad(new(2f, -0.2f, 0f), new(4f, -0.2f, 0f), new(4f, -0.2f, 2.5f), new(2f, -0.2f, 2.5f), 100);
        Polygon roomToCorridor = BspScene.Quad(new(2f, 6f, 0f), new(4f, 6f, 0f), new(4f, 6f, 3f), new(2f, 6f, 3f), 101);
        var roomStruct = new CellStruct(BspBuilder.Build(room.ToArray()),
            BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(new(0f, -0.2f, -0.5f), new(6f, 6f, 3f))), new[] { door, roomToCorridor });
        cells.AddEnvCell(new EnvCell(Room, frame, roomStruct, new[]
        {
            new CellPortal(CellPortal.OutsideCellId, door, 0),
            new CellPortal(Corridor, roomToCorridor, 1, 0),
        }));

        // Corridor: y 6..12 (its region starts at the room's north wall face), x 2..4, floor, side and end walls.
        var corr = new List<Polygon>();
        corr.Add(BspScene.Quad(new(2f, 6f, 0f), new(4f, 6f, 0f), new(4f, 12f, 0f), new(2f, 12f, 0f)));              // floor, +z
        corr.Add(BspScene.Quad(new(2f, 6f, 0f), new(2f, 12f, 0f), new(2f, 12f, 3f), new(2f, 6f, 3f)));              // west, +x
        corr.Add(BspScene.Quad(new(4f, 6f, 0f), new(4f, 6f, 3f), new(4f, 12f, 3f), new(4f, 12f, 0f)));              // east, -x
        corr.Add(BspScene.Quad(new(2f, 12f, 0f), new(4f, 12f, 0f), new(4f, 12f, 3f), new(2f, 12f, 3f)));            // end, -y
        Polygon corridorToRoom = BspScene.Quad(new(2f, 6f, 0f), new(4f, 6f, 0f), new(4f, 6f, 3f), new(2f, 6f, 3f), 200);
        var corrStruct = new CellStruct(BspBuilder.Build(corr.ToArray()),
            BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(new(2f, 6f, -0.5f), new(4f, 12f, 3f))), new[] { corridorToRoom });
        cells.AddEnvCell(new EnvCell(Corridor, frame, corrStruct, new[]
        {
            new CellPortal(Room, corridorToRoom, 0, 1),
        }));
    }
}
