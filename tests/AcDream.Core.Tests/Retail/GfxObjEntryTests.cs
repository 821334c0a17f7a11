using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CGfxObj::Serialize</c> (acclient.c:356682) with <c>CVertexArray::UnPack</c>, <c>CPolygon::UnPack</c> and the physics BSP
/// (<c>BSPTREE::UnPack</c>, <c>BSPNODE::UnPackChild</c> / <c>UnPack</c>, <c>BSPLEAF::UnPackLeaf</c>,
/// <c>BSPPORTAL::UnPackPortal</c>): a test per field group, bytes written field by field.
/// </summary>
public class GfxObjEntryTests
{
    // A unit square floor (z = 0, counter-clockwise from above: normal +z) and a wall x = 1 facing -x.
    private static readonly Vector3[] Verts =
    [
        new(0f, 0f, 0f), new(1f, 0f, 0f), new(1f, 1f, 0f), new(0f, 1f, 0f), new(1f, 0f, 1f), new(1f, 1f, 1f),
    ];

    private static readonly PolyDef Floor = new(0, [0, 1, 2, 3]);
    private static readonly PolyDef Wall = new(1, [1, 4, 5, 2], Stippling: 0, Sides: 2); // uv indices both sides

    // A physics tree by hand: root 'BPIN' on plane x = 0.5 (n (1, 0, 0), d -0.5); positive child a solid leaf with the wall,
    // negative child 'BpnN' on plane z = 0 whose negative child is a leaf with the floor.
    private static byte[] PhysicsTree()
    {
        var w = new RetailDataWriter();
        w.UInt32(RetailEntries.BPIN).Vector3(new Vector3(1f, 0f, 0f)).Single(-0.5f);
        w.UInt32(RetailEntries.Leaf).Int32(0).UInt32(1).Vector3(new Vector3(1f, 0.5f, 0.5f)).Single(0.75f).UInt32(1).Int16(1);
        w.UInt32(RetailEntries.BpnN).Vector3(new Vector3(0f, 0f, 1f)).Single(0f);
        w.UInt32(RetailEntries.Leaf).Int32(1).UInt32(0).Vector3(new Vector3(0.5f, 0.5f, 0f)).Single(0.71f).UInt32(1).Int16(0);
        w.Vector3(new Vector3(0.25f, 0.5f, 0f)).Single(0.8f);   // BpnN's sphere
        w.Vector3(new Vector3(0.5f, 0.5f, 0.5f)).Single(1f);    // root sphere
        return w.ToArray();
    }

    private static byte[] Entry(bool drawing = true, uint? degrade = 0x11000001, byte[]? tree = null)
    {
        var w = new RetailDataWriter();
        uint flags = 1u | (drawing ? 2u : 0u) | (degrade is null ? 0u : 8u);
        w.UInt32(0x01000AAA).UInt32(flags);
        RetailEntries.Compressed(w, 2);
        w.UInt32(0x08000001).UInt32(0x08000002);   // at 9 and 13: no padding (CheckAlignment is off on a data-file archive)
        RetailEntries.Vertices(w, Verts, uvsEach: 1);
        RetailEntries.Compressed(w, 2);
        RetailEntries.Polygon(w, Floor);
        RetailEntries.Polygon(w, Wall);
        w.Bytes(tree ?? PhysicsTree());
        w.Vector3(new Vector3(0.5f, 0.5f, 0.25f));
        if (drawing)
        {
            // Drawing part: one polygon, a drawing tree 'BPIN' → portal node → two leaves, and a leaf; consumed exactly.
            RetailEntries.Compressed(w, 1);
            RetailEntries.Polygon(w, Floor);
            w.UInt32(RetailEntries.BPIN).Vector3(new Vector3(0f, 0f, 1f)).Single(0f);
            w.UInt32(RetailEntries.Port).Vector3(new Vector3(1f, 0f, 0f)).Single(0f);
            w.UInt32(RetailEntries.Leaf).Int32(0).UInt32(RetailEntries.Leaf).Int32(1);
            w.Vector3(Vector3.Zero).Single(1f).UInt32(1).UInt32(1).Int16(0).Int16(0).Int16(3);   // portal: sphere, 1 poly, 1 portal
            w.UInt32(RetailEntries.Leaf).Int32(2);
            w.Vector3(Vector3.Zero).Single(2f).UInt32(1).Int16(0);                               // root: sphere, 1 poly
        }

        if (degrade is uint d)
        {
            w.UInt32(d);   // directly after the drawing tree or the sort centre
        }

        return w.ToArray();
    }

    [Fact]
    public void Id_Flags_Surfaces_AndVertexArray()
    {
        GfxObjEntry g = GfxObjEntry.UnPack(Entry());
        Assert.Equal(0x01000AAAu, g.Id);
        Assert.Equal(0xBu, g.Flags);
        Assert.Equal(new uint[] { 0x08000001, 0x08000002 }, g.SurfaceIds.ToArray());
        Assert.Equal(Verts, g.Vertices.ToArray());
    }

    [Fact]
    public void PhysicsPolygons_TheirVertices_AndPlanesByMakePlane()
    {
        GfxObjEntry g = GfxObjEntry.UnPack(Entry());
        Assert.Equal(2, g.PhysicsPolygons.Length);
        Polygon wall = g.PhysicsPolygons[1];
        Assert.Equal(1, wall.PolyId);
        Assert.Equal(new ushort[] { 1, 4, 5, 2 }, wall.VertexIds.ToArray());
        // (v4 - v1) × (v5 - v1) = (0,0,1) × (0,1,1) = (-1, 0, 0), and (v5 - v1) × (v2 - v1) = (0,1,1) × (0,1,0) = (-1, 0, 0):
        // the normal is -x, d = -(n·v) = 1.
        Assert.Equal(new Vector3(-1f, 0f, 0f), wall.Plane.N);
        Assert.Equal(1f, wall.Plane.D);
        Assert.Equal(new Vector3(0f, 0f, 1f), g.PhysicsPolygons[0].Plane.N);
    }

    [Fact]
    public void PhysicsBsp_KeepsTheStoredNodeOrder_Planes_Leaves_AndSpheres()
    {
        BspTree t = GfxObjEntry.UnPack(Entry()).PhysicsBsp!;
        // Preorder as stored: 0 root BPIN, 1 solid leaf (wall), 2 BpnN, 3 leaf (floor).
        Assert.Equal(4, t.Nodes.Length);
        Assert.Equal(0, t.Root);
        Assert.Equal(BspNodeType.SplitBothChildren, t.Nodes[0].Type);
        Assert.Equal((1, 2), (t.Nodes[0].PosNode, t.Nodes[0].NegNode));
        Assert.Equal(-0.5f, t.Nodes[0].SplittingPlane.D);
        Assert.True(t.Nodes[1].Solid);
        Assert.Equal(1, t.PolyIndices[t.Nodes[1].FirstPoly]);
        Assert.Equal(0.75f, t.Nodes[1].Sphere.Radius);
        Assert.Equal(BspNodeType.SplitNegativeChildUnmarked, t.Nodes[2].Type);
        Assert.Equal((-1, 3), (t.Nodes[2].PosNode, t.Nodes[2].NegNode));
        Assert.Equal(0.8f, t.Nodes[2].Sphere.Radius);
        Assert.False(t.Nodes[3].Solid);
        Assert.Equal(1, t.Nodes[3].LeafIndex);
        // physics_sphere = BSPTREE::GetSphere = the root's sphere.
        Assert.Equal(1f, GfxObjEntry.UnPack(Entry()).PhysicsSphere!.Value.Radius);
    }

    [Fact]
    public void TheStoredSolidLeaf_DecidesTheSolidTest_WhereABuiltTreeHasNone()
    {
        // A sphere at (0.9, 0.5, 0.5), r 0.1, touching no polygon: the root's plane x = 0.5 puts it 0.4 (> r) on the positive
        // side, whose stored leaf is solid: BSPLEAF::sphere_intersects_solid's centre check says inside. BspBuilder's tree over
        // the same two polygons has no solid leaf, so the same test says outside.
        GfxObjEntry g = GfxObjEntry.UnPack(Entry());
        var s = new Sphere(new Vector3(0.9f, 0.5f, 0.5f), 0.1f);
        Assert.True(g.PhysicsBsp!.SphereIntersectsSolid(s, centerCheck: true));
        Assert.False(BspBuilder.Build(g.PhysicsPolygons).SphereIntersectsSolid(s, centerCheck: true));
    }

    [Fact]
    public void SortCenter_DrawingPartConsumedExactly_AndDegradeId()
    {
        GfxObjEntry g = GfxObjEntry.UnPack(Entry());
        Assert.Equal(new Vector3(0.5f, 0.5f, 0.25f), g.SortCenter);
        Assert.Equal(1, g.DrawingPolygonCount);
        // The degrade id is read after the drawing tree: had a byte been skipped or left, it would not read back.
        Assert.Equal(0x11000001u, g.DegradeId);
        Assert.Equal(0u, GfxObjEntry.UnPack(Entry(drawing: false, degrade: null)).DegradeId);
    }

    [Fact]
    public void CompressedCounts_OneTwoAndFourBytes()
    {
        // SB_As32Bit_Compressed: 0x7F in one byte; 0x80 as 0x80 0x80; 0x4000 as 0xC0 0x00 0x4000.
        foreach (uint v in new uint[] { 0, 0x7F, 0x80, 0x3FFF, 0x4000, 0x12345678 & 0x3FFFFFFF })
        {
            var w = new RetailDataWriter();
            RetailEntries.Compressed(w, v);
            var r = new RetailDataReader(w.ToArray(), "t");
            Assert.Equal(v, r.ReadCompressedUInt32());
            Assert.Equal(0, r.Remaining);
        }
    }

    [Fact]
    public void EverySplitTag_ReadsTheChildrenItNames()
    {
        // Each tag over two leaves' worth of children; the bytes after the tree (a sort centre) must line up.
        var cases = new (uint Tag, bool Pos, bool Neg)[]
        {
            (RetailEntries.BPIN, true, true), (RetailEntries.BPnN, true, true), (RetailEntries.BPIn, true, false),
            (RetailEntries.BPnn, true, false), (RetailEntries.BpIN, false, true), (RetailEntries.BpnN, false, true),
        };
        foreach ((uint tag, bool pos, bool neg) in cases)
        {
            var w = new RetailDataWriter();
            w.UInt32(tag).Vector3(Vector3.UnitZ).Single(0f);
            if (pos)
            {
                w.UInt32(RetailEntries.Leaf).Int32(0).UInt32(0).Vector3(Vector3.Zero).Single(1f).UInt32(1).Int16(0);
            }

            if (neg)
            {
                w.UInt32(RetailEntries.Leaf).Int32(1).UInt32(1).Vector3(Vector3.Zero).Single(1f).UInt32(1).Int16(1);
            }

            w.Vector3(Vector3.Zero).Single(2f);
            BspTree t = GfxObjEntry.UnPack(Entry(drawing: false, degrade: null, tree: w.ToArray())).PhysicsBsp!;
            Assert.Equal((uint)tag, (uint)t.Nodes[0].Type);
            Assert.Equal(pos ? 1 : -1, t.Nodes[0].PosNode);
            Assert.Equal(neg ? (pos ? 2 : 1) : -1, t.Nodes[0].NegNode);
        }
    }

    [Fact]
    public void APortalNodeInAPhysicsTree_ReadsPlaneAndBothChildrenOnly()
    {
        var w = new RetailDataWriter();
        w.UInt32(RetailEntries.Port).Vector3(Vector3.UnitX).Single(0f);
        w.UInt32(RetailEntries.Leaf).Int32(0).UInt32(0).Vector3(Vector3.Zero).Single(1f).UInt32(0);
        w.UInt32(RetailEntries.Leaf).Int32(1).UInt32(0).Vector3(Vector3.Zero).Single(1f).UInt32(0);
        BspTree t = GfxObjEntry.UnPack(Entry(drawing: false, tree: w.ToArray())).PhysicsBsp!;
        Assert.Equal(BspNodeType.Portal, t.Nodes[0].Type);
        Assert.Equal((1, 2), (t.Nodes[0].PosNode, t.Nodes[0].NegNode));
    }

    [Fact]
    public void AnUnknownNodeTagInThePhysicsTree_IsASplitNodeWithoutChildren_PlaneThenSphere()
    {
        // BSPNODE::UnPackChild (acclient.c:363343) makes a BSPNODE of any tag but PORT and LEAF; BSPNODE::UnPack (363185)
        // reads its plane, no child (the tag is none of the six split tags), then in a physics tree the sphere only.
        var w = new RetailDataWriter();
        w.UInt32(0x12345678u).Vector3(Vector3.UnitX).Single(-0.5f);    // tag, plane
        w.Vector3(new Vector3(0.5f, 0.5f, 0.5f)).Single(0.9f);          // sphere; no polygon list in a physics tree
        GfxObjEntry g = GfxObjEntry.UnPack(Entry(drawing: false, tree: w.ToArray()));
        BspTree t = g.PhysicsBsp!;
        // The sort centre and the degrade id after the tree read back: the node took exactly 4 + 16 + 16 bytes.
        Assert.Equal(new Vector3(0.5f, 0.5f, 0.25f), g.SortCenter);
        Assert.Equal(0x11000001u, g.DegradeId);
        Assert.Equal(1, t.Nodes.Length);
        Assert.Equal(0x12345678u, (uint)t.Nodes[0].Type);
        Assert.Equal((-1, -1), (t.Nodes[0].PosNode, t.Nodes[0].NegNode));
        Assert.Equal(0.9f, t.Nodes[0].Sphere.Radius);
        Assert.Equal(-0.5f, t.Nodes[0].SplittingPlane.D);
    }

    [Fact]
    public void ALeafPolygonIndexPastThePolygonList_IsAFormatError()
    {
        var w = new RetailDataWriter();
        w.UInt32(RetailEntries.Leaf).Int32(0).UInt32(0).Vector3(Vector3.Zero).Single(1f).UInt32(1).Int16(2); // 2 polygons: 0, 1
        var e = Assert.Throws<RetailDataFormatException>(() => GfxObjEntry.UnPack(Entry(drawing: false, tree: w.ToArray())));
        Assert.Contains("polygon index 2", e.Reason);
    }

    [Fact]
    public void APolygonVertexIdPastTheVertexArray_IsAFormatError()
    {
        var w = new RetailDataWriter();
        w.UInt32(0x01000001).UInt32(1);
        RetailEntries.Compressed(w, 0);
        RetailEntries.Vertices(w, Verts);
        RetailEntries.Compressed(w, 1);
        int polyAt = w.Length;
        RetailEntries.Polygon(w, new PolyDef(0, [0, 1, 6]));
        var e = Assert.Throws<RetailDataFormatException>(() => GfxObjEntry.UnPack(w.ToArray()));
        Assert.Equal("CPolygon", e.Structure);
        Assert.Equal(polyAt + 12 + 4, e.Offset); // the third vertex id
    }

    [Fact]
    public void ATreeDeeperThanTheLimit_IsAFormatError_NotAStackOverflow()
    {
        var w = new RetailDataWriter();
        for (int i = 0; i < BspReader.MaxDepth + 10; i++)
        {
            w.UInt32(RetailEntries.BPIn).Vector3(Vector3.UnitZ).Single(i);
        }

        var e = Assert.Throws<RetailDataFormatException>(() => GfxObjEntry.UnPack(Entry(drawing: false, tree: w.ToArray())));
        Assert.Contains("deeper than 256", e.Reason);
    }

    [Fact]
    public void ABspBuilderTree_WrittenInRetailLayout_ReadsBackNodeForNode()
    {
        // The round trip the cellar tests rely on: BspBuilder's tree written by BSPNODE::PackChild's order and read back.
        var polys = new List<Polygon>();
        Support.BspScene.AddBox(polys, new Vector3(0f), new Vector3(2f, 1f, 3f));
        Support.BspScene.AddBox(polys, new Vector3(3f, 0f, 0f), new Vector3(4f, 1f, 1f));
        BspTree built = BspBuilder.Build(polys.ToArray(), 2);
        (List<Vector3> v, PolyDef[] defs) = RetailEntries.Defs(built.Polygons.ToArray());
        BspTree read = GfxObjEntry.UnPack(RetailEntries.GfxObj(0x01000002, v, defs, built, Vector3.Zero)).PhysicsBsp!;
        Assert.Equal(built.Nodes.Length, read.Nodes.Length);
        for (int i = 0; i < built.Nodes.Length; i++)
        {
            Assert.Equal(built.Nodes[i].Type, read.Nodes[i].Type);
            Assert.Equal(built.Nodes[i].SplittingPlane.N, read.Nodes[i].SplittingPlane.N);
            Assert.Equal(built.Nodes[i].Sphere.Radius, read.Nodes[i].Sphere.Radius);
            Assert.Equal(built.Nodes[i].NumPolys, read.Nodes[i].NumPolys);
        }

        Assert.Equal(built.PolyIndices.ToArray(), read.PolyIndices.ToArray());
    }
}
