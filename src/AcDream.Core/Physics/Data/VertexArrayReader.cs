using System.Numerics;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// Retail <c>CVertexArray::UnPack</c> and <c>CSWVertex::UnPack</c>: the vertex positions of a GfxObj or a cell structure, the
/// array every <c>CPolygon</c> of the owner indexes by position. Normals and texture coordinates are read and dropped (the
/// physics uses only positions).
/// </summary>
internal static class VertexArrayReader
{
    /// <summary>Retail <c>VertexType</c> 1: the software vertex (<c>CSWVertex</c>), the only type the data holds.</summary>
    public const uint SoftwareVertexType = 1;

    /// <summary>
    /// Reads a vertex array: the vertex type, the count, then (type 1) each vertex. A position that is not finite is a format
    /// error (the library's polygons take finite vertices).
    /// </summary>
    /// <remarks>Divergence (why): retail reads no vertex bytes for a type other than 1 and leaves the vertices uninitialised;
    /// the port refuses such an array unless it is empty (uninitialised memory is no geometry).</remarks>
    // retail: CVertexArray::UnPack (acclient.c:362801)
    public static Vector3[] UnPack(ref RetailDataReader r)
    {
        int typeAt = r.Offset;
        uint vertexType = r.ReadUInt32("vertex type");
        // CSWVertex: id 2, uv count 2, position 12, normal 12 = 28 bytes at least.
        int count = r.ReadCount("vertex count", 28);
        if (vertexType != SoftwareVertexType && count != 0)
        {
            throw r.ErrorAt(typeAt, $"vertex type {vertexType} is not the software vertex type 1");
        }

        var vertices = new Vector3[count];
        for (int i = 0; i < count; i++)
        {
            vertices[i] = UnPackVertex(ref r);
        }

        return vertices;
    }

    /// <summary>One vertex: its id (unused: retail indexes by position), the uv count, position, normal, then the uvs.</summary>
    // retail: CSWVertex::UnPack (acclient.c:364860)
    private static Vector3 UnPackVertex(ref RetailDataReader r)
    {
        r.ReadUInt16("vertex id");
        int numUvsAt = r.Offset;
        int numUvs = r.ReadCount16("vertex uv count", 0);
        Vector3 position = r.ReadFiniteVector3("vertex position");
        r.ReadVector3("vertex normal");
        r.CheckCount((uint)numUvs, "vertex uv count", 8, numUvsAt);
        r.Skip(numUvs * 8, "vertex uvs");
        return position;
    }
}
