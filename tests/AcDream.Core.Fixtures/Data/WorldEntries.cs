using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Fixtures.Data;

/// <summary>A Setup to write (<c>CSetup::UnPack</c>'s fields that physics reads; no holding locations, connection points or
/// lights).</summary>
internal sealed record SetupDef(uint Id, uint[] Parts)
{
    public (Vector3 Low, float Radius, float Height)[] CylSpheres { get; init; } = [];

    public (Vector3 Center, float Radius)[] Spheres { get; init; } = [];

    public float Height { get; init; }

    public float Radius { get; init; }

    public float StepUp { get; init; }

    public float StepDown { get; init; }

    public (Vector3 Center, float Radius) Sorting { get; init; }

    public Vector3[]? DefaultScales { get; init; }

    /// <summary>Placement frames: key, then one frame per part.</summary>
    public (uint Key, Frame[] Frames)[] Placements { get; init; } = [];

    public uint DefaultAnimation { get; init; }

    public uint DefaultScript { get; init; }
}

/// <summary>
/// Writes the entries of the world's objects in retail's byte layouts: Setups (<c>CSetup::UnPack</c> order), degrade tables
/// (<c>GfxObjDegradeInfo::UnPack</c>), and box-shaped GfxObjs with a physics BSP.
/// </summary>
internal static class WorldEntries
{
    /// <summary>A Setup entry: id, flags (2 when default scales are given), parts, scales, no holding locations or connection
    /// points, the placement frames (each: key, one frame per part, no hooks), cylinder spheres, spheres, height, radius, step
    /// heights, sorting and selection spheres, no lights, five default ids (animation, script, 0, 0, 0), alignment.</summary>
    public static byte[] Setup(SetupDef d)
    {
        var w = new RetailDataWriter();
        uint flags = d.DefaultScales is null ? 0u : 2u;
        w.UInt32(d.Id).UInt32(flags).UInt32((uint)d.Parts.Length);
        foreach (uint p in d.Parts)
        {
            w.UInt32(p);
        }

        if (d.DefaultScales is not null)
        {
            foreach (Vector3 s in d.DefaultScales)
            {
                w.Vector3(s);
            }
        }

        w.UInt32(0).UInt32(0).UInt32((uint)d.Placements.Length);
        foreach ((uint key, Frame[] frames) in d.Placements)
        {
            w.UInt32(key);
            foreach (Frame f in frames)
            {
                w.Frame(f);
            }

            w.UInt32(0);
        }

        w.UInt32((uint)d.CylSpheres.Length);
        foreach ((Vector3 low, float r, float h) in d.CylSpheres)
        {
            w.Vector3(low).Single(r).Single(h);
        }

        w.UInt32((uint)d.Spheres.Length);
        foreach ((Vector3 c, float r) in d.Spheres)
        {
            w.Vector3(c).Single(r);
        }

        w.Single(d.Height).Single(d.Radius).Single(d.StepUp).Single(d.StepDown);
        w.Vector3(d.Sorting.Center).Single(d.Sorting.Radius);
        w.Vector3(d.Sorting.Center).Single(d.Sorting.Radius);
        w.UInt32(0);
        w.UInt32(d.DefaultAnimation).UInt32(d.DefaultScript).UInt32(0).UInt32(0).UInt32(0);
        return w.Align4().ToArray();
    }

    /// <summary>A degrade table: id, count, then each level's GfxObj id, mode and three distances (0, 25, 50 m).</summary>
    public static byte[] DegradeInfo(uint id, params (uint GfxObj, uint Mode)[] levels)
    {
        var w = new RetailDataWriter();
        w.UInt32(id).UInt32((uint)levels.Length);
        foreach ((uint g, uint mode) in levels)
        {
            w.UInt32(g).UInt32(mode).Single(0f).Single(25f).Single(50f);
        }

        return w.ToArray();
    }

    /// <summary>A GfxObj whose physics is <paramref name="polys"/> (a BSP built over them; e.g. a box's six outward faces),
    /// optionally naming a degrade table.</summary>
    public static byte[] PhysicsGfxObj(uint id, IReadOnlyList<Polygon> polys, uint? degrade = null)
    {
        var arr = new Polygon[polys.Count];
        for (int i = 0; i < arr.Length; i++)
        {
            arr[i] = polys[i];
        }

        BspTree t = BspBuilder.Build(arr);
        (List<Vector3> v, PolyDef[] defs) = RetailEntries.Defs(t.Polygons.ToArray());
        return RetailEntries.GfxObj(id, v, defs, t, Vector3.Zero, degrade: degrade);
    }

    /// <summary>A GfxObj with no physics: only vertices (its drawing box), optionally naming a degrade table.</summary>
    public static byte[] DrawingOnlyGfxObj(uint id, Vector3 min, Vector3 max, uint? degrade = null) =>
        RetailEntries.GfxObj(id, [min, max], [], null, (min + max) * 0.5f, degrade: degrade);
}
