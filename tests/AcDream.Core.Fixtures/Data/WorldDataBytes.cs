using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Fixtures.Data;

/// <summary>
/// Entry bytes in retail's layouts for a client that has no data files at hand (the first-scene sample): a landblock, its
/// info with buildings and static objects, a box-shaped GfxObj with a physics BSP, a drawing-only GfxObj and a one-cylinder
/// Setup (a tree). A real client hands the library its data files' entries instead.
/// </summary>
public static class WorldDataBytes
{
    /// <summary>A landblock entry (0xXXYYFFFF): the info flag, 81 terrain words and 81 height indexes.</summary>
    public static byte[] LandBlock(uint id, bool hasInfo, ReadOnlySpan<ushort> terrain, ReadOnlySpan<byte> height) =>
        RetailEntries.LandBlock(id, hasInfo, terrain, height);

    /// <summary>A landblock info entry (0xXXYYFFFE) without indoor cells: its static objects and its buildings (no doors).</summary>
    public static byte[] LandBlockInfo(uint id, (uint Id, Frame Frame)[] objects, (uint ModelId, Frame Frame)[] buildings)
    {
        var defs = new BuildingDef[buildings.Length];
        for (int i = 0; i < defs.Length; i++)
        {
            defs[i] = new BuildingDef(buildings[i].ModelId, buildings[i].Frame, 0, []);
        }

        return RetailEntries.LandBlockInfo(id, 0, objects, defs);
    }

    /// <summary>A GfxObj (0x01…) whose physics is the closed box <paramref name="min"/>..<paramref name="max"/>.</summary>
    public static byte[] BoxGfxObj(uint id, Vector3 min, Vector3 max)
    {
        float x0 = min.X, y0 = min.Y, z0 = min.Z, x1 = max.X, y1 = max.Y, z1 = max.Z;
        var polys = new List<Polygon>();
        void Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d) =>
            polys.Add(new Polygon((short)polys.Count, new[] { a, b, c, d }, new ushort[] { 0, 1, 2, 3 }));
        Quad(new(x1, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x1, y0, z1));
        Quad(new(x0, y0, z0), new(x0, y0, z1), new(x0, y1, z1), new(x0, y1, z0));
        Quad(new(x0, y1, z0), new(x0, y1, z1), new(x1, y1, z1), new(x1, y1, z0));
        Quad(new(x0, y0, z0), new(x1, y0, z0), new(x1, y0, z1), new(x0, y0, z1));
        Quad(new(x0, y0, z1), new(x1, y0, z1), new(x1, y1, z1), new(x0, y1, z1));
        Quad(new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0));
        return WorldEntries.PhysicsGfxObj(id, polys);
    }

    /// <summary>A GfxObj (0x01…) with vertices only (drawn, never collided with).</summary>
    public static byte[] DrawingGfxObj(uint id, Vector3 min, Vector3 max) => WorldEntries.DrawingOnlyGfxObj(id, min, max);

    /// <summary>A Setup (0x02…) of one drawing part and one cylinder sphere (a tree's trunk).</summary>
    public static byte[] CylinderSetup(uint id, uint partId, float radius, float height, float lowZ) =>
        WorldEntries.Setup(new SetupDef(id, [partId])
        {
            CylSpheres = [(new Vector3(0f, 0f, lowZ), radius, height)],
            Height = height + lowZ,
            Radius = radius,
            Placements = [(0x65, [Frame.Identity])],
        });
}
