using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// Retail's BSP pack (<c>BSPNODE::PackChild</c> acclient.c:363316, <c>BSPNODE::Pack</c> 363142, <c>BSPLEAF::PackLeaf</c>
/// 364091, <c>BSPPORTAL::PackPortal</c> 364589 and their sizes) against the unpack: a round trip, and the same bytes the
/// tests' writer produces by following the unpack field by field.
/// </summary>
public class BspPackTests
{
    private static BspTree Tree()
    {
        var polys = new List<Polygon>();
        BspScene.AddBox(polys, Vector3.Zero, new Vector3(2f, 1f, 3f));
        BspScene.AddBox(polys, new Vector3(3f, 0f, 0f), new Vector3(4f, 1f, 1f));
        // Ids = index (as in retail data, where the pack writes poly_id and the unpack reads an index).
        var withIds = new Polygon[polys.Count];
        for (int i = 0; i < withIds.Length; i++)
        {
            withIds[i] = new Polygon((short)i, polys[i].Vertices, polys[i].VertexIds);
        }

        return BspBuilder.Build(withIds, 2);
    }

    [Fact]
    public void APhysicsTree_RoundTrips_NodeForNode()
    {
        BspTree t = Tree();
        byte[] bytes = BspPack.Pack(t, BspKind.Physics);
        var r = new RetailDataReader(bytes, "BSPTREE");
        BspTree back = BspReader.UnPackTree(ref r, BspKind.Physics, t.Polygons.ToArray(), t.Polygons.Length)!;
        Assert.Equal(0, r.Remaining); // pack_child_size is exactly what the unpack consumes
        Assert.Equal(t.Nodes.Length, back.Nodes.Length);
        for (int i = 0; i < t.Nodes.Length; i++)
        {
            Assert.Equal(t.Nodes[i].Type, back.Nodes[i].Type);
            Assert.Equal(t.Nodes[i].PosNode, back.Nodes[i].PosNode);
            Assert.Equal(t.Nodes[i].NegNode, back.Nodes[i].NegNode);
            Assert.Equal(t.Nodes[i].SplittingPlane.D, back.Nodes[i].SplittingPlane.D);
            Assert.Equal(t.Nodes[i].Sphere.Center, back.Nodes[i].Sphere.Center);
        }

        Assert.Equal(t.PolyIndices.ToArray(), back.PolyIndices.ToArray());
    }

    [Fact]
    public void ThePackedBytes_AreTheTestWritersBytes()
    {
        // Two independent writers of one layout: the port of retail's Pack and the tests' writer that follows the UnPack.
        BspTree t = Tree();
        var w = new RetailDataWriter();
        RetailEntries.Tree(w, t, 1);
        Assert.Equal(w.ToArray(), BspPack.Pack(t, BspKind.Physics));
    }

    [Fact]
    public void ACellChain_RoundTrips_WhenItEndsInALeaf()
    {
        // A cell chain of two planes ending in a leaf (as retail's data holds them); the cell kind writes planes and leaf indices.
        var nodes = new[]
        {
            BspNode.Split(BspNodeType.SplitPositiveChild, new CollisionPlane(Vector3.UnitX, 0f), default, 1, -1),
            BspNode.Split(BspNodeType.SplitPositiveChild, new CollisionPlane(-Vector3.UnitX, 4f), default, 2, -1),
            BspNode.MakeLeaf(0, default, 0, 0, false),
        };
        var t = new BspTree(nodes, [], []);
        byte[] bytes = BspPack.Pack(t, BspKind.Cell);
        // Two nodes of tag + plane (20 bytes each) and a leaf of tag + index (8): 48 bytes.
        Assert.Equal(48, bytes.Length);
        var r = new RetailDataReader(bytes, "BSPTREE");
        BspTree back = BspReader.UnPackTree(ref r, BspKind.Cell, [], 0)!;
        Assert.True(back.PointInsideCellBsp(new Vector3(2f, 0f, 0f)));
        Assert.False(back.PointInsideCellBsp(new Vector3(5f, 0f, 0f)));
    }
}
