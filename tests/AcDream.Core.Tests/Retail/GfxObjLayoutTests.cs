using System.Buffers.Binary;
using System.Numerics;
using System;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// A GfxObj's bytes as <c>CGfxObj::Serialize</c> (acclient.c:356682) reads them from a data-file archive, written here at
/// literal offsets worked out from the decompilation (not with the fixtures' writer): id u32 @0, flags u32 @4, surface count
/// (<c>SB_As32Bit_Compressed</c>, 1, 2 or 4 bytes) @8, the surface ids u32 directly after it, the vertex array, [flag 1: the
/// physics part], the sort centre 3 × f32, [flag 2: the drawing part], [flag 8: the degrade id u32 directly after]. No
/// padding anywhere: <c>Archive::CheckAlignment</c> (70280) pads only on a word-aligned archive (flag 2), and a data-file
/// archive's flags start at 0 (<c>AsyncCache::SerializeFromCachePack</c> 84376; only <c>Archive::SetWordAligned</c> 70048
/// sets it).
/// </summary>
public class GfxObjLayoutTests
{
    private const uint Degrade = 0x11000123;

    private static void U32(byte[] b, int at, uint v) => BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(at), v);

    private static void F32(byte[] b, int at, float v) => BinaryPrimitives.WriteSingleLittleEndian(b.AsSpan(at), v);

    /// <summary>An entry with <paramref name="n"/> surfaces (count encoded as <paramref name="count"/>), an empty vertex
    /// array, no physics and no drawing part, the sort centre (1, 2, 3) and, with <paramref name="degrade"/>, flag 8 and the
    /// degrade id. Returns the bytes and the offsets of the surface ids and of the degrade id.</summary>
    private static (byte[] Bytes, int SurfacesAt, int DegradeAt) Entry(byte[] count, int n, bool degrade)
    {
        int surfacesAt = 8 + count.Length;
        int vertexArrayAt = surfacesAt + 4 * n;
        int sortCenterAt = vertexArrayAt + 8;     // vertex type u32, vertex count u32
        int degradeAt = sortCenterAt + 12;
        var b = new byte[degradeAt + (degrade ? 4 : 0)];
        U32(b, 0, 0x010005E8);
        U32(b, 4, degrade ? 8u : 0u);
        count.CopyTo(b, 8);
        for (int i = 0; i < n; i++)
        {
            U32(b, surfacesAt + 4 * i, 0x08000000u | (uint)(0x1B8 + i));
        }

        U32(b, vertexArrayAt, 1);
        U32(b, vertexArrayAt + 4, 0);
        F32(b, sortCenterAt, 1f);
        F32(b, sortCenterAt + 4, 2f);
        F32(b, sortCenterAt + 8, 3f);
        if (degrade)
        {
            U32(b, degradeAt, Degrade);
        }

        return (b, surfacesAt, degradeAt);
    }

    private static GfxObjEntry ReadWhole(byte[] bytes)
    {
        var r = new RetailDataReader(bytes, "CGfxObj");
        GfxObjEntry g = GfxObjEntry.UnPack(ref r);
        Assert.Equal(0, r.Remaining);   // consumed exactly: no byte skipped, none left
        return g;
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void OneByteSurfaceCount_TheSurfaceIdIsAtOffset9(bool degrade)
    {
        // The shape of the real portal file's 0x010005E8: one surface, 0x080001B8, at offset 9 after the count byte 0x01.
        (byte[] b, int at, int degradeAt) = Entry([0x01], 1, degrade);
        Assert.Equal(9, at);
        Assert.Equal(degrade ? 33 : -1, degrade ? degradeAt : -1);   // 9 + 4 + 8 + 12: unaligned, as stored
        GfxObjEntry g = ReadWhole(b);
        Assert.Equal(new uint[] { 0x080001B8 }, g.SurfaceIds.ToArray());
        Assert.Equal(new Vector3(1f, 2f, 3f), g.SortCenter);
        Assert.Equal(degrade ? Degrade : 0u, g.DegradeId);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void TwoByteSurfaceCount_TheIdsStartAtOffset10(bool degrade)
    {
        // 128 = 0x80 needs two bytes: 0x80 | (128 >> 8), 128 & 0xFF = 0x80 0x80.
        (byte[] b, int at, int degradeAt) = Entry([0x80, 0x80], 128, degrade);
        Assert.Equal(10, at);
        Assert.Equal(10 + 512 + 8 + 12, degradeAt);                 // 542: 2 mod 4
        GfxObjEntry g = ReadWhole(b);
        Assert.Equal(128, g.SurfaceIds.Length);
        Assert.Equal(0x080001B8u, g.SurfaceIds[0]);
        Assert.Equal(0x080001B8u + 127, g.SurfaceIds[127]);
        Assert.Equal(new Vector3(1f, 2f, 3f), g.SortCenter);
        Assert.Equal(degrade ? Degrade : 0u, g.DegradeId);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void FourByteSurfaceCount_TheIdsStartAtOffset12(bool degrade)
    {
        // 0x4000 needs four bytes: 0xC0 | (v >> 24), (v >> 16) & 0xFF, then the low word little-endian = C0 00 00 40.
        (byte[] b, int at, int degradeAt) = Entry([0xC0, 0x00, 0x00, 0x40], 0x4000, degrade);
        Assert.Equal(12, at);
        Assert.Equal(12 + 0x10000 + 8 + 12, degradeAt);
        GfxObjEntry g = ReadWhole(b);
        Assert.Equal(0x4000, g.SurfaceIds.Length);
        Assert.Equal(0x080001B8u + 0x3FFF, g.SurfaceIds[0x3FFF]);
        Assert.Equal(new Vector3(1f, 2f, 3f), g.SortCenter);
        Assert.Equal(degrade ? Degrade : 0u, g.DegradeId);
    }

    [Fact]
    public void TheDegradeId_FollowsADrawingTreeThatEndsOffTheWordBoundary()
    {
        // Flags 2 | 8, no surfaces, no vertices; one drawing polygon; a drawing tree of one 'BPIN' over two leaves whose own
        // polygon list holds two u16s: the tree ends 2 bytes past a word boundary and the degrade id follows at once.
        var b = new byte[128];
        U32(b, 0, 0x01000001);
        U32(b, 4, 2u | 8u);
        b[8] = 0;                                  // surface count 0 (1 byte)
        U32(b, 9, 1);                              // vertex type
        U32(b, 13, 0);                             // vertex count 0
        F32(b, 17, 0.5f); F32(b, 21, 0.5f); F32(b, 25, 0.5f);   // sort centre @17
        b[29] = 1;                                 // drawing polygon count 1 (1 byte)
        // CPolygon::UnPack @30: id u16, point count u8 (0), stippling u8 (4: no uvs), sides i32 (0), surfaces i16 × 2.
        b[32] = 0; b[33] = 4;
        int tree = 30 + 12;                        // 42
        U32(b, tree, 0x4250494E);                  // 'BPIN'
        F32(b, tree + 4, 1f);                      // plane n (1, 0, 0), d 0
        U32(b, tree + 20, 0x4C454146); U32(b, tree + 24, 0);   // 'LEAF', index 0 (a drawing leaf stores nothing more)
        U32(b, tree + 28, 0x4C454146); U32(b, tree + 32, 1);
        F32(b, tree + 48, 1f);                     // BPIN's sphere @78 (centre 0, radius 1 @90)
        U32(b, tree + 52, 2);                      // polygon count u32 @94
        b[tree + 56] = 0; b[tree + 58] = 0;        // polygons 0, 0 (u16) @98, @100
        int degradeAt = tree + 60;                 // 102: 2 mod 4, read there (a 4-aligned read would start at 104)
        U32(b, degradeAt, Degrade);
        GfxObjEntry g = ReadWhole(b.AsSpan(0, degradeAt + 4).ToArray());
        Assert.Equal(Degrade, g.DegradeId);
        Assert.Equal(1, g.DrawingPolygonCount);
    }
    [Fact]
    public void ADrawingTreeWithABPOLRoot_IsReadAndTheDegradeIdFollows()
    {
        // As 0x010005E8: one surface at 9, and a drawing tree whose root is 'BPOL' (0x42504F4C): BSPNODE::UnPack reads its
        // plane, no child, the sphere, a u32 polygon count and the u16 indices (acclient.c:363185).
        var b = new byte[128];
        U32(b, 0, 0x010005E8);
        U32(b, 4, 2u | 8u);
        b[8] = 1;                                  // surface count 1
        U32(b, 9, 0x080001B8);                     // the surface id @9
        U32(b, 13, 1); U32(b, 17, 0);              // vertex array: type 1, no vertices
        // sort centre @21 (0, 0, 0); drawing polygon count @33; CPolygon @34 (12 bytes: no points, stippling 4)
        b[33] = 1;
        b[37] = 4;
        int tree = 46;
        U32(b, tree, 0x42504F4C);                  // 'BPOL'
        F32(b, tree + 12, 1f);                     // plane n (0, 0, 1), d 0
        F32(b, tree + 28, 1.5f);                   // sphere @66: centre (0, 0, 1.5) (z @74), radius 2 @78
        F32(b, tree + 32, 2f);
        U32(b, tree + 36, 1);                      // polygon count @82
        int degradeAt = tree + 42;                 // polygon 0 (u16) @86; degrade @88
        var bytes = new byte[degradeAt + 4];
        b.AsSpan(0, degradeAt).CopyTo(bytes);
        U32(bytes, degradeAt, Degrade);
        GfxObjEntry g = ReadWhole(bytes);
        Assert.Equal(new uint[] { 0x080001B8 }, g.SurfaceIds.ToArray());
        Assert.Equal(1, g.DrawingPolygonCount);
        Assert.Equal(Degrade, g.DegradeId);
        // CGfxObj::Serialize keeps drawing_sphere = BSPTREE::GetSphere(drawing_bsp): the root's sphere, read where it stands.
        Assert.Equal(new Sphere(new Vector3(0f, 0f, 1.5f), 2f), g.DrawingSphere);

        // CSetup::makeSimpleSetup (acclient.c:334455): no physics sphere (offset 116 of the GfxObj is null), so the sorting
        // sphere is the drawing sphere (offset 144).
        byte[] noDegrade = bytes[..degradeAt];
        U32(noDegrade, 4, 2u);
        var source = new DictionarySource();
        source.Entries[0x010005E8] = noDegrade;
        PhysicsObj o = new ObjectFactory(source).MakeObject(new PhysicsWorld(), 0x010005E8)!;
        Assert.Equal(new Sphere(new Vector3(0f, 0f, 1.5f), 2f), ((SimplePartArray)o.PartArray!).SortingSphere);
    }
}
