using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// One polygon as retail's <c>CPolygon::UnPack</c> reads it: its id, sides type, surfaces and the indices of its vertices in
/// the owner's vertex array (the texture indices are consumed and dropped). <see cref="ToPolygon"/> resolves it into the
/// library's <see cref="Polygon"/> (whose constructor runs <c>CPolygon::make_plane</c>, as the unpack does).
/// </summary>
internal sealed class PolygonInfo
{
    private PolygonInfo(short polyId, byte stippling, int sidesType, short posSurface, short negSurface, ushort[] vertexIds, int offset)
    {
        PolyId = polyId;
        Stippling = stippling;
        SidesType = sidesType;
        PosSurface = posSurface;
        NegSurface = negSurface;
        VertexIds = vertexIds;
        Offset = offset;
    }

    /// <summary>Retail <c>poly_id</c>.</summary>
    public short PolyId { get; }

    /// <summary>Retail <c>stippling</c> (bit 4: no positive uvs stored, bit 8: no negative uvs stored).</summary>
    public byte Stippling { get; }

    /// <summary>Retail <c>sides_type</c> (0 single, 1 both sides the same, 2 both sides each its own).</summary>
    public int SidesType { get; }

    /// <summary>Retail <c>pos_surface</c>.</summary>
    public short PosSurface { get; }

    /// <summary>Retail <c>neg_surface</c> (the positive one when <see cref="SidesType"/> is 1, as retail sets it).</summary>
    public short NegSurface { get; }

    /// <summary>Retail <c>vertex_ids</c>: indices into the owner's vertex array, checked in range.</summary>
    public ushort[] VertexIds { get; }

    /// <summary>Byte offset where the polygon starts (named by errors raised when it is resolved).</summary>
    public int Offset { get; }

    /// <summary>
    /// Reads one polygon: id, point count (byte), stippling (byte), sides type, positive and negative surface, the vertex
    /// ids, then the positive uv indices unless stippling has 4, and the negative ones when the sides type is 2 and stippling
    /// lacks 8. A vertex id past <paramref name="numVertices"/> is a format error (retail would point past its array).
    /// </summary>
    // retail: CPolygon::UnPack (acclient.c:359808)
    public static PolygonInfo UnPack(ref RetailDataReader r, int numVertices)
    {
        int at = r.Offset;
        short polyId = (short)r.ReadUInt16("polygon id");
        int numPtsAt = r.Offset;
        byte numPts = r.ReadByte("polygon point count");
        byte stippling = r.ReadByte("polygon stippling");
        int sidesType = r.ReadInt32("polygon sides type");
        short posSurface = r.ReadInt16("polygon positive surface");
        short negSurface = r.ReadInt16("polygon negative surface");
        r.CheckCount(numPts, "polygon point count", 2, numPtsAt);
        var ids = new ushort[numPts];
        for (int i = 0; i < ids.Length; i++)
        {
            int idAt = r.Offset;
            ids[i] = r.ReadUInt16("polygon vertex id");
            if (ids[i] >= numVertices)
            {
                throw r.ErrorAt(idAt, $"polygon vertex id {ids[i]} is past the vertex array ({numVertices} vertices)");
            }
        }

        if ((stippling & 4) == 0)
        {
            r.Skip(numPts, "polygon positive uv indices");
        }

        if (sidesType == 2 && (stippling & 8) == 0)
        {
            r.Skip(numPts, "polygon negative uv indices");
        }

        if (sidesType == 1)
        {
            negSurface = posSurface;
        }

        return new PolygonInfo(polyId, stippling, sidesType, posSurface, negSurface, ids, at);
    }

    /// <summary>Reads <paramref name="count"/> polygons (each at least 12 bytes).</summary>
    public static PolygonInfo[] UnPackList(ref RetailDataReader r, int count, int numVertices, int countAt)
    {
        r.CheckCount((uint)count, "polygon count", 12, countAt);
        var list = new PolygonInfo[count];
        for (int i = 0; i < count; i++)
        {
            list[i] = UnPack(ref r, numVertices);
        }

        return list;
    }

    /// <summary>The library polygon over <paramref name="vertices"/> (plane by <c>CPolygon::make_plane</c>). Fewer than three
    /// points is a format error naming <paramref name="structure"/> (retail's plane of such a polygon is undefined).</summary>
    public Polygon ToPolygon(Vector3[] vertices, string structure)
    {
        if (VertexIds.Length < 3)
        {
            throw new RetailDataFormatException(structure, Offset, $"polygon {PolyId} has {VertexIds.Length} points, fewer than three");
        }

        Span<Vector3> pts = VertexIds.Length <= 64 ? stackalloc Vector3[VertexIds.Length] : new Vector3[VertexIds.Length];
        for (int i = 0; i < VertexIds.Length; i++)
        {
            pts[i] = vertices[VertexIds[i]];
        }

        return new Polygon(PolyId, pts, VertexIds);
    }

    /// <summary>Every polygon of the list resolved (see <see cref="ToPolygon"/>).</summary>
    public static Polygon[] ToPolygons(PolygonInfo[] list, Vector3[] vertices, string structure)
    {
        var result = new Polygon[list.Length];
        for (int i = 0; i < list.Length; i++)
        {
            result[i] = list[i].ToPolygon(vertices, structure);
        }

        return result;
    }
}
