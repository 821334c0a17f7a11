using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Behavior;

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
        world.Transition = new RetailTransition(cells);
        return world;
    }

    /// <summary>The outdoor cell id under the landblock-local point (x, y) of block (0x80, 0x80).</summary>
    public static uint OutdoorCell(float x, float y) =>
        SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, (int)(x / 24f), (int)(y / 24f));

    /// <summary>An indoor cell id of block (0x80, 0x80).</summary>
    public static uint IndoorCell(int index) => ((uint)SweepScene.BlockX << 24) | ((uint)SweepScene.BlockY << 16) | (uint)(0x100 + index);

    /// <summary>A quad with corners in order (counter-clockwise seen from the side it faces).</summary>
    public static Polygon Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d, short id = 0) =>
        new(id, new[] { a, b, c, d }, new ushort[] { 0, 1, 2, 3 });

    /// <summary>Appends the six outward-facing faces of the box <paramref name="min"/>..<paramref name="max"/>.</summary>
    public static void AddBox(List<Polygon> polys, Vector3 min, Vector3 max)
    {
        float x0 = min.X, y0 = min.Y, z0 = min.Z, x1 = max.X, y1 = max.Y, z1 = max.Z;
        short id = (short)polys.Count;
        polys.Add(Quad(new(x1, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x1, y0, z1), id++)); // +X
        polys.Add(Quad(new(x0, y0, z0), new(x0, y0, z1), new(x0, y1, z1), new(x0, y1, z0), id++)); // -X
        polys.Add(Quad(new(x0, y1, z0), new(x0, y1, z1), new(x1, y1, z1), new(x1, y1, z0), id++)); // +Y
        polys.Add(Quad(new(x0, y0, z0), new(x1, y0, z0), new(x1, y0, z1), new(x0, y0, z1), id++)); // -Y
        polys.Add(Quad(new(x0, y0, z1), new(x1, y0, z1), new(x1, y1, z1), new(x0, y1, z1), id++)); // +Z
        polys.Add(Quad(new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0), id));   // -Z
    }

    /// <summary>
    /// Places a building whose shell is <paramref name="shell"/> (local to <paramref name="origin"/>, identity rotation)
    /// on every land cell its bounding box covers (with a 1 m margin), with doors <paramref name="portals"/>.
    /// </summary>
    public static BuildingObj AddBuilding(WorldCells cells, Vector3 origin, List<Polygon> shell, params BldPortal[] portals)
    {
        BspTree bsp = BspBuilder.Build(shell.ToArray());
        var part = new PhysicsPart(new GfxObjPhysics(bsp), new Position(OutdoorCell(origin.X, origin.Y), new Frame(origin, Quaternion.Identity)), Vector3.One);
        var building = new BuildingObj(part, portals);
        Vector3 min = new(float.MaxValue), max = new(float.MinValue);
        foreach (Polygon p in shell)
        {
            foreach (Vector3 v in p.Vertices)
            {
                min = Vector3.Min(min, v + origin);
                max = Vector3.Max(max, v + origin);
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

    /// <summary>The centre of the walker's single sphere (radius r, resting on its origin).</summary>
    public static Vector3 SphereCenter(PhysicsObj obj, float r) => obj.Position.Frame.Origin + new Vector3(0f, 0f, r);
}
