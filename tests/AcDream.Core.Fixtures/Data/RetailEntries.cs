using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Fixtures.Data;

/// <summary>A polygon to write: its id, its vertex indices, stippling (4: no positive uvs stored) and sides type.</summary>
internal sealed record PolyDef(short Id, ushort[] Vids, byte Stippling = 4, int Sides = 0);

/// <summary>A cell portal to write (retail <c>CCellPortal::Pack</c> fields).</summary>
internal readonly record struct PortalDef(ushort Flags, short PolyId, ushort OtherCell, short OtherPortal);

/// <summary>A building door to write (retail <c>CBldPortal</c> fields).</summary>
internal sealed record DoorDef(ushort Flags, ushort OtherCell, short OtherPortal, ushort[] Stabs);

/// <summary>A building to write (retail <c>BuildInfo</c>).</summary>
internal sealed record BuildingDef(uint ModelId, Frame Frame, uint NumLeaves, DoorDef[] Doors);

/// <summary>
/// Writes whole data-file entries in retail's byte layouts, following each <c>UnPack</c> field by field (and retail's
/// <c>Pack</c> where retail has one: <c>BSPNODE::PackChild</c>, <c>BSPLEAF::PackLeaf</c>, <c>BSPPORTAL::PackPortal</c>,
/// <c>CCellPortal::Pack</c>, <c>PackableHashTable::Pack</c>). The tests' mirror of the library's unpackers.
/// </summary>
internal static class RetailEntries
{
    public const uint Leaf = 0x4C454146, Port = 0x504F5254, BPIN = 0x4250494E, BPIn = 0x4250496E, BpIN = 0x4270494E,
        BPnN = 0x42506E4E, BPnn = 0x42506E6E, BpnN = 0x42706E4E;

    /// <summary>Tags real drawing trees hold besides the eight: 'BPOL' and 'BPFL' (read as split nodes without children).</summary>
    public const uint BPOL = 0x42504F4C, BPFL = 0x4250464C;

    /// <summary>The vertex array: type 1, count, then each vertex (id, uv count, position, normal (0, 0, 1), uvs).</summary>
    public static void Vertices(RetailDataWriter w, IReadOnlyList<Vector3> v, int uvsEach = 0)
    {
        w.UInt32(1).UInt32((uint)v.Count);
        for (int i = 0; i < v.Count; i++)
        {
            w.UInt16((ushort)i).UInt16((ushort)uvsEach).Vector3(v[i]).Vector3(new Vector3(0f, 0f, 1f));
            for (int u = 0; u < uvsEach; u++)
            {
                w.Single(0.25f * u).Single(0.5f);
            }
        }
    }

    /// <summary>One polygon (<c>CPolygon::UnPack</c> order).</summary>
    public static void Polygon(RetailDataWriter w, PolyDef p)
    {
        w.UInt16((ushort)p.Id).Byte((byte)p.Vids.Length).Byte(p.Stippling).Int32(p.Sides).Int16(7).Int16(9);
        foreach (ushort id in p.Vids)
        {
            w.UInt16(id);
        }

        if ((p.Stippling & 4) == 0)
        {
            for (int i = 0; i < p.Vids.Length; i++)
            {
                w.Byte((byte)i);
            }
        }

        if (p.Sides == 2 && (p.Stippling & 8) == 0)
        {
            for (int i = 0; i < p.Vids.Length; i++)
            {
                w.Byte((byte)(i + 1));
            }
        }
    }

    /// <summary>Distinct vertices of <paramref name="polys"/> (exact equality) and each polygon's indices into them.</summary>
    public static (List<Vector3> Vertices, List<ushort[]> Ids) Mesh(IEnumerable<IReadOnlyList<Vector3>> polys, List<Vector3>? into = null)
    {
        var verts = into ?? new List<Vector3>();
        var ids = new List<ushort[]>();
        foreach (IReadOnlyList<Vector3> p in polys)
        {
            var vid = new ushort[p.Count];
            for (int i = 0; i < p.Count; i++)
            {
                int k = verts.IndexOf(p[i]);
                if (k < 0)
                {
                    verts.Add(p[i]);
                    k = verts.Count - 1;
                }

                vid[i] = (ushort)k;
            }

            ids.Add(vid);
        }

        return (verts, ids);
    }

    /// <summary>
    /// A library tree in retail's layout (0 drawing, 1 physics, 2 cell), depth first from the root as
    /// <c>BSPNODE::PackChild</c> writes it. A split node's missing child (index -1, e.g. the end of
    /// <see cref="BspBuilder.BuildCell"/>'s chain, which retail's tag cannot express) is written as an empty leaf.
    /// </summary>
    public static void Tree(RetailDataWriter w, BspTree tree, int kind) => Child(w, tree, tree.Root, kind);

    private static void Child(RetailDataWriter w, BspTree tree, int i, int kind)
    {
        if (i < 0)
        {
            w.UInt32(Leaf).Int32(0);
            if (kind == 1)
            {
                w.UInt32(0).Vector3(Vector3.Zero).Single(0f).UInt32(0);
            }

            return;
        }

        BspNode n = tree.Nodes[i];
        w.UInt32((uint)n.Type);
        if (n.IsLeaf)
        {
            // BSPLEAF::PackLeaf: leaf index; physics: solid, sphere, polygon count and ids.
            w.Int32(n.LeafIndex);
            if (kind == 1)
            {
                w.UInt32(n.Solid ? 1u : 0u).Vector3(n.Sphere.Center).Single(n.Sphere.Radius).UInt32((uint)n.NumPolys);
                for (int p = 0; p < n.NumPolys; p++)
                {
                    w.Int16((short)tree.PolyIndices[n.FirstPoly + p]);
                }
            }

            return;
        }

        w.Vector3(n.SplittingPlane.N).Single(n.SplittingPlane.D);
        switch (n.Type)
        {
            case BspNodeType.Portal:
            case BspNodeType.SplitBothChildren:
            case BspNodeType.SplitBothChildrenUnmarked:
                Child(w, tree, n.PosNode, kind);
                Child(w, tree, n.NegNode, kind);
                break;
            case BspNodeType.SplitPositiveChild:
            case BspNodeType.SplitPositiveChildUnmarked:
                Child(w, tree, n.PosNode, kind);
                break;
            case BspNodeType.SplitNegativeChild:
            case BspNodeType.SplitNegativeChildUnmarked:
                Child(w, tree, n.NegNode, kind);
                break;
            default:
                // Any other tag (BPOL, BPFL, ...): BSPNODE::UnPack (acclient.c:363185) reads no child for it.
                break;
        }

        if (kind != 2)
        {
            if (n.Type == BspNodeType.Portal && kind != 0)
            {
                return;
            }

            w.Vector3(n.Sphere.Center).Single(n.Sphere.Radius);
            if (kind == 0)
            {
                w.UInt32((uint)n.NumPolys);
                if (n.Type == BspNodeType.Portal)
                {
                    w.UInt32(0);
                }

                for (int p = 0; p < n.NumPolys; p++)
                {
                    w.Int16((short)tree.PolyIndices[n.FirstPoly + p]);
                }
            }
        }
    }

    /// <summary>A drawing tree of one leaf (leaf index only).</summary>
    public static void DrawingLeaf(RetailDataWriter w) => w.UInt32(Leaf).Int32(0);

    /// <summary>A GfxObj entry (<c>CGfxObj::Serialize</c> order). The physics part is written when <paramref name="physicsBsp"/>
    /// is given; the drawing part when <paramref name="drawing"/> is.</summary>
    /// <remarks>No padding anywhere: <c>CGfxObj::Serialize</c> (acclient.c:356682) and <c>SB_AsDataID&lt;0&gt;::Serialize</c>
    /// (356648) call <c>Archive::CheckAlignment</c> before the flags, each surface id and the degrade id, but it pads only
    /// on a word-aligned archive (flag 2, acclient.c:70280), which a data-file archive never is (its flags start at 0:
    /// <c>AsyncCache::SerializeFromCachePack</c> 84376; only <c>Archive::SetWordAligned</c> 70048 sets flag 2).</remarks>
    public static byte[] GfxObj(uint id, IReadOnlyList<Vector3> verts, IReadOnlyList<PolyDef> physics, BspTree? physicsBsp, Vector3 sortCenter,
        IReadOnlyList<PolyDef>? drawing = null, uint? degrade = null, uint[]? surfaces = null)
    {
        var w = new RetailDataWriter();
        uint flags = (physicsBsp is null ? 0u : 1u) | (drawing is null ? 0u : 2u) | (degrade is null ? 0u : 8u);
        w.UInt32(id).UInt32(flags);
        surfaces ??= [];
        Compressed(w, (uint)surfaces.Length);
        foreach (uint s in surfaces)
        {
            w.UInt32(s);   // directly after the compressed count (1, 2 or 4 bytes): no CheckAlignment padding
        }

        Vertices(w, verts);
        if (physicsBsp is not null)
        {
            Compressed(w, (uint)physics.Count);
            foreach (PolyDef p in physics)
            {
                Polygon(w, p);
            }

            Tree(w, physicsBsp, 1);
        }

        w.Vector3(sortCenter);
        if (drawing is not null)
        {
            Compressed(w, (uint)drawing.Count);
            foreach (PolyDef p in drawing)
            {
                Polygon(w, p);
            }

            DrawingLeaf(w);
        }

        if (degrade is uint d)
        {
            w.UInt32(d);   // directly after the drawing tree or the sort centre: no CheckAlignment padding
        }

        return w.ToArray();
    }

    /// <summary>Retail's compressed count (the write side of <c>SB_As32Bit_Compressed::Serialize</c>).</summary>
    public static void Compressed(RetailDataWriter w, uint v)
    {
        if (v <= 0x7F)
        {
            w.Byte((byte)v);
        }
        else if (v <= 0x3FFF)
        {
            w.Byte((byte)((v >> 8) | 0x80)).Byte((byte)v);
        }
        else
        {
            w.Byte((byte)((v >> 24) | 0xC0)).Byte((byte)(v >> 16)).UInt16((ushort)v);
        }
    }

    /// <summary>One cell structure (<c>CCellStruct::UnPack</c> order).</summary>
    public static void CellStruct(RetailDataWriter w, uint id, IReadOnlyList<Vector3> verts, IReadOnlyList<PolyDef> polygons, ushort[] portals,
        BspTree cellBsp, IReadOnlyList<PolyDef> physics, BspTree physicsBsp, bool drawingBsp = true)
    {
        w.UInt32(id).UInt32((uint)polygons.Count).UInt32((uint)physics.Count).UInt32((uint)portals.Length);
        Vertices(w, verts);
        foreach (PolyDef p in polygons)
        {
            Polygon(w, p);
        }

        foreach (ushort p in portals)
        {
            w.UInt16(p);
        }

        w.Align4();   // CCellStruct::UnPack (acclient.c:355822) rounds its cursor up to 4 after the portal list, always
        Tree(w, cellBsp, 2);
        foreach (PolyDef p in physics)
        {
            Polygon(w, p);
        }

        Tree(w, physicsBsp, 1);
        w.UInt32(drawingBsp ? 1u : 0u);
        if (drawingBsp)
        {
            DrawingLeaf(w);
        }

        w.Align4();   // CCellStruct::UnPack (acclient.c:355822) rounds its cursor up to 4 at its end, always
    }

    /// <summary>An environment entry: id, structure count, the structures (each written by a callback).</summary>
    public static byte[] Environment(uint id, params Action<RetailDataWriter>[] structs)
    {
        var w = new RetailDataWriter();
        w.UInt32(id).UInt32((uint)structs.Length);
        foreach (Action<RetailDataWriter> s in structs)
        {
            s(w);
        }

        return w.ToArray();
    }

    /// <summary>An indoor cell entry (entry id, then <c>CEnvCell::UnPack</c> order).</summary>
    public static byte[] EnvCell(uint id, uint flags, ushort environment, ushort structIndex, in Frame frame, PortalDef[] portals,
        ushort[]? visible = null, ushort[]? surfaces = null, (uint Id, Frame Frame)[]? statics = null, uint restriction = 0)
    {
        visible ??= [];
        surfaces ??= [];
        var w = new RetailDataWriter();
        uint f = flags | (statics is null ? 0u : 2u) | (restriction == 0 ? 0u : 8u);
        w.UInt32(id).UInt32(f).UInt32(id).Byte((byte)surfaces.Length).Byte((byte)portals.Length).UInt16((ushort)visible.Length);
        foreach (ushort s in surfaces)
        {
            w.UInt16(s);
        }

        w.UInt16(environment).UInt16(structIndex).Frame(frame);
        foreach (PortalDef p in portals)
        {
            // CCellPortal::Pack: flags, polygon id, other cell, other portal.
            w.UInt16(p.Flags).Int16(p.PolyId).UInt16(p.OtherCell).Int16(p.OtherPortal);
        }

        foreach (ushort v in visible)
        {
            w.UInt16(v);
        }

        if (statics is not null)
        {
            w.UInt32((uint)statics.Length);
            foreach ((uint sid, Frame sf) in statics)
            {
                w.UInt32(sid).Frame(sf);
            }
        }

        if (restriction != 0)
        {
            w.UInt32(restriction);
        }

        return w.ToArray();
    }

    /// <summary>A landblock entry: id, info flag, 81 terrain words, 81 heights, alignment.</summary>
    public static byte[] LandBlock(uint id, bool hasInfo, ReadOnlySpan<ushort> terrain, ReadOnlySpan<byte> height)
    {
        var w = new RetailDataWriter();
        w.UInt32(id).UInt32(hasInfo ? 1u : 0u);
        foreach (ushort t in terrain)
        {
            w.UInt16(t);
        }

        foreach (byte h in height)
        {
            w.Byte(h);
        }

        return w.Align4().ToArray();   // CLandBlockStruct::UnPack (acclient.c:354108): 4-alignment after the 81 heights, always
    }

    /// <summary>A landblock info entry (<c>CLandBlockInfo::UnPack</c> order).</summary>
    public static byte[] LandBlockInfo(uint id, uint numCells, (uint Id, Frame Frame)[] objects, BuildingDef[] buildings,
        (uint Key, uint Value)[]? restrictions = null)
    {
        var w = new RetailDataWriter();
        w.UInt32(id).UInt32(numCells).UInt32((uint)objects.Length);
        foreach ((uint oid, Frame of) in objects)
        {
            w.UInt32(oid).Frame(of);
        }

        w.UInt32((uint)buildings.Length | (restrictions is null ? 0u : 1u << 16));
        foreach (BuildingDef b in buildings)
        {
            w.UInt32(b.ModelId).Frame(b.Frame).UInt32(b.NumLeaves).UInt32((uint)b.Doors.Length);
            foreach (DoorDef d in b.Doors)
            {
                w.UInt16(d.Flags).UInt16(d.OtherCell).Int16(d.OtherPortal).UInt16((ushort)d.Stabs.Length);
                foreach (ushort s in d.Stabs)
                {
                    w.UInt16(s);
                }

                if ((d.Stabs.Length & 1) != 0)
                {
                    w.UInt16(0);   // CBldPortal::UnPack (acclient.c:362498) skips 2 bytes after an odd number of stabs, always
                }
            }
        }

        if (restrictions is not null)
        {
            // PackableHashTable::Pack: count | table size << 16, then the pairs.
            w.UInt32((uint)restrictions.Length | (8u << 16));
            foreach ((uint k, uint v) in restrictions)
            {
                w.UInt32(k).UInt32(v);
            }
        }

        return w.ToArray();
    }

    /// <summary>A tree's polygons as <see cref="PolyDef"/>s over a shared vertex list (ids = index in the list).</summary>
    public static (List<Vector3> Vertices, PolyDef[] Polys) Defs(IReadOnlyList<Polygon> polys, List<Vector3>? verts = null)
    {
        var lists = new List<IReadOnlyList<Vector3>>();
        foreach (Polygon p in polys)
        {
            lists.Add(p.Vertices.ToArray());
        }

        (List<Vector3> v, List<ushort[]> ids) = Mesh(lists, verts);
        var defs = new PolyDef[polys.Count];
        for (int i = 0; i < defs.Length; i++)
        {
            defs[i] = new PolyDef(polys[i].PolyId, ids[i]);
        }

        return (v, defs);
    }
}
