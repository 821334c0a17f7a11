using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// Every node tag in every tree kind, read as <c>BSPNODE::UnPackChild</c> (acclient.c:363343) reads it: PORT →
/// <c>BSPPORTAL::UnPackPortal</c> (364645), LEAF → <c>BSPLEAF::UnPackLeaf</c> (364132), any other tag → <c>BSPNODE::UnPack</c>
/// (363185): the plane (4 × f32), the children its tag names ('BPIN' / 'BPnN' both, 'BPIn' / 'BPnn' the positive one, 'BpIN' /
/// 'BpnN' the negative one, any other tag such as 'BPOL' or 'BPFL' none), then by <c>pack_tree_type</c>: drawing (0) the sphere
/// (4 × f32), a u32 polygon count and u16 polygon indices; physics (1) the sphere; cell (2) nothing. Bytes are laid out
/// here by hand from those functions; a 4-byte marker after each tree shows it was consumed exactly.
/// </summary>
public class BspNodeTagTests
{
    private const uint Marker = 0xDEADBEEF;
    private const uint Odd = 0x12345678;   // a tag no table names

    private static (BspTree? Tree, uint After) Read(RetailDataWriter w, BspKind kind, int numPolys)
    {
        w.UInt32(Marker);
        var r = new RetailDataReader(w.ToArray(), "BSPTREE");
        BspTree? t = BspReader.UnPackTree(ref r, kind, [], numPolys);
        uint after = r.ReadUInt32("marker");
        Assert.Equal(0, r.Remaining);
        return (t, after);
    }

    private static void Plane(RetailDataWriter w, float d) => w.Vector3(Vector3.UnitZ).Single(d);

    // A drawing split node's tail: sphere, u32 polygon count, u16 polygon indices.
    private static void DrawingTail(RetailDataWriter w, params short[] polys)
    {
        w.Vector3(Vector3.Zero).Single(1f).UInt32((uint)polys.Length);
        foreach (short p in polys)
        {
            w.Int16(p);
        }
    }

    private static void DrawingLeaf(RetailDataWriter w, int index) => w.UInt32(RetailEntries.Leaf).Int32(index);

    [Fact]
    public void ADrawingTreeHoldingEveryTag_IsConsumedExactly()
    {
        // BPIN ( BPnN ( BPIn ( BPOL ), odd ), BpIN ( PORT ( BPnN ( LEAF, LEAF ), BPnn ( BpnN ( BPFL ) ) ) ) ): the six split
        // tags, PORT, LEAF, BPOL, BPFL and a tag no table names, each followed by exactly what it stores.
        var w = new RetailDataWriter();
        w.UInt32(RetailEntries.BPIN); Plane(w, 0f);
        {
            w.UInt32(RetailEntries.BPnN); Plane(w, 1f);
            {
                w.UInt32(RetailEntries.BPIn); Plane(w, 2f);
                {
                    w.UInt32(RetailEntries.BPOL); Plane(w, 3f);   // no children
                    DrawingTail(w, 0, 1, 2);                      // 3 polygons: the node ends 2 bytes off a word
                }

                DrawingTail(w);
                w.UInt32(Odd); Plane(w, 4f);                      // no children
                DrawingTail(w, 2);
            }

            DrawingTail(w);
            w.UInt32(RetailEntries.BpIN); Plane(w, 5f);
            {
                w.UInt32(RetailEntries.Port); Plane(w, 6f);
                {
                    w.UInt32(RetailEntries.BPnN); Plane(w, 7f);
                    DrawingLeaf(w, 0);
                    DrawingLeaf(w, 1);
                    DrawingTail(w, 1);
                    w.UInt32(RetailEntries.BPnn); Plane(w, 8f);
                    {
                        w.UInt32(RetailEntries.BpnN); Plane(w, 9f);
                        {
                            w.UInt32(RetailEntries.BPFL); Plane(w, 10f);   // no children
                            DrawingTail(w, 2);
                        }

                        DrawingTail(w);
                    }

                    DrawingTail(w);
                }

                // PORT's tail: sphere, u32 polygon count, u32 portal count, u16 polygon indices, then (u16 polygon, u16
                // portal) per portal.
                w.Vector3(Vector3.Zero).Single(1f).UInt32(1).UInt32(1).Int16(0).Int16(1).Int16(5);
            }

            DrawingTail(w);
        }

        DrawingTail(w, 0);
        (BspTree? t, uint after) = Read(w, BspKind.Drawing, 3);
        Assert.Null(t);            // a drawing tree is consumed, not kept
        Assert.Equal(Marker, after);
    }

    [Fact]
    public void BPOL_InACellTree_IsItsPlaneAlone()
    {
        var w = new RetailDataWriter();
        w.UInt32(RetailEntries.BPOL); Plane(w, -2f);
        (BspTree? t, uint after) = Read(w, BspKind.Cell, 0);
        Assert.Equal(Marker, after);                         // 4 + 16 bytes, no sphere
        Assert.Equal(RetailEntries.BPOL, (uint)t!.Nodes[0].Type);
        Assert.Equal((-1, -1), (t.Nodes[0].PosNode, t.Nodes[0].NegNode));
        Assert.Equal(-2f, t.Nodes[0].SplittingPlane.D);
    }

    [Fact]
    public void BPFL_InAPhysicsTree_IsItsPlaneAndSphere_WithoutChildrenOrPolygons()
    {
        // Under a 'BPIN' whose negative child is a leaf: BPFL reads no child, so the leaf after it is BPIN's second child.
        var w = new RetailDataWriter();
        w.UInt32(RetailEntries.BPIN); Plane(w, 0f);
        w.UInt32(RetailEntries.BPFL); Plane(w, 1f);
        w.Vector3(new Vector3(1f, 2f, 3f)).Single(4f);       // BPFL's sphere; no polygon list in a physics tree
        w.UInt32(RetailEntries.Leaf).Int32(7).UInt32(1).Vector3(Vector3.Zero).Single(1f).UInt32(0);
        w.Vector3(Vector3.Zero).Single(5f);                  // BPIN's sphere
        (BspTree? t, uint after) = Read(w, BspKind.Physics, 0);
        Assert.Equal(Marker, after);
        Assert.Equal(3, t!.Nodes.Length);
        Assert.Equal((1, 2), (t.Nodes[0].PosNode, t.Nodes[0].NegNode));
        Assert.Equal(RetailEntries.BPFL, (uint)t.Nodes[1].Type);
        Assert.Equal((-1, -1), (t.Nodes[1].PosNode, t.Nodes[1].NegNode));
        Assert.Equal(new Vector3(1f, 2f, 3f), t.Nodes[1].Sphere.Center);
        Assert.Equal(0, t.Nodes[1].NumPolys);
        Assert.Equal(7, t.Nodes[2].LeafIndex);
        Assert.True(t.Nodes[2].Solid);
        Assert.Equal(5f, t.Sphere.Radius);
    }

    [Fact]
    public void AnOddTag_InEachTreeKind_ReadsWhatThatKindStoresForASplitNode()
    {
        // Drawing: tag, plane, sphere, u32 count, u16 × count = 4 + 16 + 16 + 4 + 2.
        var d = new RetailDataWriter();
        d.UInt32(Odd); Plane(d, 0f); DrawingTail(d, 0);
        Assert.Equal(Marker, Read(d, BspKind.Drawing, 1).After);

        // Physics: tag, plane, sphere = 36.
        var p = new RetailDataWriter();
        p.UInt32(Odd); Plane(p, 0f); p.Vector3(Vector3.Zero).Single(1f);
        Assert.Equal(Marker, Read(p, BspKind.Physics, 0).After);

        // Cell: tag, plane = 20.
        var c = new RetailDataWriter();
        c.UInt32(Odd); Plane(c, 0f);
        Assert.Equal(Marker, Read(c, BspKind.Cell, 0).After);
    }
}
