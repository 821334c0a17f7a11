using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// A graphics object (a part's mesh; data-file entry 0x01xxxxxx) as retail's <c>CGfxObj::Serialize</c> reads it, its physics
/// half kept: the vertex positions, the physics polygons, the physics BSP as stored, the physics sphere and the sort centre.
/// The surfaces' ids are kept; the drawing polygons and the drawing BSP are read and dropped.
/// </summary>
public sealed class GfxObjEntry
{
    /// <summary>Retail flag 1: the entry holds physics polygons and a physics BSP.</summary>
    public const uint HasPhysicsFlag = 1;

    /// <summary>Retail flag 2: the entry holds drawing polygons and a drawing BSP.</summary>
    public const uint HasDrawingFlag = 2;

    /// <summary>Retail flag 8: the entry ends with a degrade table id.</summary>
    public const uint HasDegradeFlag = 8;

    private readonly uint[] _surfaceIds;
    private readonly Vector3[] _vertices;
    private readonly Polygon[] _physicsPolygons;

    private GfxObjEntry(uint id, uint flags, uint[] surfaceIds, Vector3[] vertices, Polygon[] physicsPolygons, BspTree? physicsBsp,
        Vector3 sortCenter, uint degradeId, int drawingPolygonCount)
    {
        Id = id;
        Flags = flags;
        _surfaceIds = surfaceIds;
        _vertices = vertices;
        _physicsPolygons = physicsPolygons;
        PhysicsBsp = physicsBsp;
        SortCenter = sortCenter;
        DegradeId = degradeId;
        DrawingPolygonCount = drawingPolygonCount;
        Physics = physicsBsp is null ? null : new GfxObjPhysics(physicsBsp);
    }

    /// <summary>The entry's id (0x01xxxxxx). Retail: <c>m_DID</c>.</summary>
    public uint Id { get; }

    /// <summary>The stored flags (<see cref="HasPhysicsFlag"/>, <see cref="HasDrawingFlag"/>, <see cref="HasDegradeFlag"/>).</summary>
    public uint Flags { get; }

    /// <summary>The surfaces' ids (0x08xxxxxx). Retail: <c>m_rgSurfaces</c>.</summary>
    public ReadOnlySpan<uint> SurfaceIds => _surfaceIds;

    /// <summary>The vertex positions, object-local. Retail: <c>vertex_array</c>.</summary>
    public ReadOnlySpan<Vector3> Vertices => _vertices;

    /// <summary>The physics polygons, object-local, planes by <c>CPolygon::make_plane</c>. Retail: <c>physics_polygons</c>.</summary>
    public ReadOnlySpan<Polygon> PhysicsPolygons => _physicsPolygons;

    /// <summary>The physics BSP as stored (null without <see cref="HasPhysicsFlag"/>). Retail: <c>physics_bsp</c>.</summary>
    public BspTree? PhysicsBsp { get; }

    /// <summary>The physics sphere: the physics BSP's root sphere (retail <c>BSPTREE::GetSphere</c>), or null. Retail:
    /// <c>physics_sphere</c>.</summary>
    public Sphere? PhysicsSphere => PhysicsBsp?.Sphere;

    /// <summary>The drawing sphere: the drawing BSP's root sphere (retail <c>drawing_sphere</c> = <c>BSPTREE::GetSphere</c>
    /// of the drawing tree, acclient.c CGfxObj::Serialize), or null when the entry has no drawing tree or its root stores no
    /// sphere. <c>CSetup::makeSimpleSetup</c> falls back to it for a GfxObj without a physics sphere.</summary>
    internal Sphere? DrawingSphere { get; private init; }

    /// <summary>The sort centre. Retail: <c>sort_center</c>.</summary>
    public Vector3 SortCenter { get; }

    /// <summary>The degrade table id, 0 when not stored. Retail: <c>m_didDegrade</c>.</summary>
    public uint DegradeId { get; }

    /// <summary>How many drawing polygons the entry holds (read and dropped).</summary>
    public int DrawingPolygonCount { get; }

    /// <summary>The object's physics for a <see cref="Objects.Parts.PhysicsPart"/> or a building, or null when it has none.</summary>
    public GfxObjPhysics? Physics { get; }

    /// <summary>
    /// Unpacks one GfxObj entry's bytes (after the data-file container): the id (u32 at 0), the flags (u32 at 4), the surface
    /// count (compressed: 1, 2 or 4 bytes, at 8) and the surface ids (u32 each, directly after it), the vertex array, the
    /// physics polygons and BSP (flag 1), the sort centre, the drawing polygons and BSP (flag 2), the degrade id (flag 8: u32,
    /// directly after whatever precedes it). No padding anywhere. Retail <c>CGfxObj::Serialize</c>.
    /// </summary>
    /// <remarks>
    /// Retail calls <c>Archive::CheckAlignment</c> before the flags, each surface id and the degrade id, but
    /// <c>CheckAlignment</c> (acclient.c:70280) pads only when the archive's word-aligned flag (2) is set, and every archive
    /// that unpacks a data-file object starts with its flags 0 (<c>AsyncCache::SerializeFromCachePack</c> acclient.c:84376,
    /// <c>TransientArchive::TransientArchive</c> 290180; <c>Archive::InitForUnpacking</c> 70527 leaves flag 2 alone) and
    /// only <c>Archive::SetWordAligned</c> (70048) sets it, which no data-file load calls: no padding is read.
    /// </remarks>
    /// <exception cref="RetailDataFormatException">The bytes are not a GfxObj (truncated, inconsistent, or not finite).</exception>
    // retail: CGfxObj::Serialize (acclient.c:356682)
    public static GfxObjEntry UnPack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "CGfxObj");
        return UnPack(ref r);
    }

    internal static GfxObjEntry UnPack(ref RetailDataReader r)
    {
        uint id = r.ReadUInt32("id");
        // Archive::CheckAlignment(4) here and before each surface id and the degrade id: a no-op (word-aligned flag clear).
        uint flags = r.ReadUInt32("flags");
        int numSurfaces = r.ReadCompressedCount("surface count", 4);
        var surfaces = new uint[numSurfaces];
        for (int i = 0; i < surfaces.Length; i++)
        {
            surfaces[i] = ReadDataId(ref r);
        }

        Vector3[] vertices = SerializeVertexArray(ref r);
        Polygon[] physicsPolys = [];
        BspTree? physicsBsp = null;
        if ((flags & HasPhysicsFlag) != 0)
        {
            r.Structure = "CPolygon";
            int nAt = r.Offset;
            int n = r.ReadCompressedCount("physics polygon count", 12);
            PolygonInfo[] raw = SerializePolygons(ref r, n, vertices.Length, nAt);
            physicsPolys = PolygonInfo.ToPolygons(raw, vertices, "CGfxObj");
            physicsBsp = SerializeBsp(ref r, BspKind.Physics, physicsPolys, physicsPolys.Length, out int sphereAt)!;
            if (physicsBsp.Sphere.Radius < 0f)
            {
                // The radius field of the root's sphere (centre 12 bytes, then the radius).
                throw r.ErrorAt(sphereAt + 12, "the physics sphere has a negative radius");
            }
        }

        r.Structure = "CGfxObj";
        Vector3 sortCenter = SerializeVector3(ref r);
        int drawingCount = 0;
        Sphere? drawingSphere = null;
        if ((flags & HasDrawingFlag) != 0)
        {
            r.Structure = "CPolygon";
            int drawingAt = r.Offset;
            drawingCount = r.ReadCompressedCount("drawing polygon count", 12);
            SerializePolygons(ref r, drawingCount, vertices.Length, drawingAt);
            SerializeBsp(ref r, BspKind.Drawing, [], drawingCount, out int drawingSphereAt);
            if (drawingSphereAt >= 0)
            {
                // The root's sphere, already read and checked by the tree's unpack, read again where it stands.
                var at = new RetailDataReader(r.From(drawingSphereAt), "BSP");
                drawingSphere = Sphere.UnPack(ref at, "drawing sphere");
            }
        }

        r.Structure = "CGfxObj";
        uint degrade = 0;
        if ((flags & HasDegradeFlag) != 0)
        {
            degrade = r.ReadUInt32("degrade id");
        }

        return new GfxObjEntry(id, flags, surfaces, vertices, physicsPolys, physicsBsp, sortCenter, degrade, drawingCount)
        {
            DrawingSphere = drawingSphere,
        };
    }

    // The vertex array through its own unpack.
    // retail: SB_AsPackObj<0>::Serialize (acclient.c:356238), the CVertexArray instance
    private static Vector3[] SerializeVertexArray(ref RetailDataReader r)
    {
        r.Structure = "CVertexArray";
        return VertexArrayReader.UnPack(ref r);
    }

    // Each polygon through its own unpack.
    // retail: SB_AsPackObj<0>::Serialize (acclient.c:356272), the CPolygon instance
    private static PolygonInfo[] SerializePolygons(ref RetailDataReader r, int count, int numVertices, int countAt)
    {
        r.Structure = "CPolygon";
        return PolygonInfo.UnPackList(ref r, count, numVertices, countAt);
    }

    // A BSP tree through its own unpack.
    // retail: SB_AsPackObj<0>::Serialize (acclient.c:356306), the BSPTREE instance
    private static BspTree? SerializeBsp(ref RetailDataReader r, BspKind kind, Polygon[] polygons, int numPolys, out int rootSphereAt)
    {
        r.Structure = "BSPTREE";
        return BspReader.UnPackTree(ref r, kind, polygons, numPolys, out rootSphereAt);
    }

    // The sort centre: 12 bytes, x, y, z.
    // retail: SB_AsPackObj<0>::Serialize (acclient.c:356559), the Vector3 instance
    private static Vector3 SerializeVector3(ref RetailDataReader r)
    {
        r.Structure = "CGfxObj";
        return r.ReadFiniteVector3("sort center");
    }

    // A surface id: 4 bytes, unpadded (CheckAlignment is a no-op on a data-file archive, see UnPack).
    // retail: SB_AsDataID<0>::Serialize (acclient.c:356648)
    private static uint ReadDataId(ref RetailDataReader r)
    {
        return r.ReadUInt32("surface id");
    }
}
