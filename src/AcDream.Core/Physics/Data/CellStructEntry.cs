using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// One cell structure of an environment (the shape an indoor cell takes), as retail's <c>CCellStruct::UnPack</c> reads it:
/// the vertex positions, the portal polygons, the cell BSP, the physics polygons and the physics BSP, all as stored and in
/// cell-local space. The drawing polygons other than the portals and the drawing BSP are read and dropped.
/// </summary>
public sealed class CellStructEntry
{
    private readonly Vector3[] _vertices;
    private readonly Polygon[] _portals;
    private readonly Polygon[] _physicsPolygons;

    private CellStructEntry(uint id, Vector3[] vertices, int polygonCount, Polygon[] portals, BspTree cellBsp, Polygon[] physicsPolygons,
        BspTree physicsBsp, bool hasDrawingBsp)
    {
        CellStructId = id;
        _vertices = vertices;
        PolygonCount = polygonCount;
        _portals = portals;
        CellBsp = cellBsp;
        _physicsPolygons = physicsPolygons;
        PhysicsBsp = physicsBsp;
        HasDrawingBsp = hasDrawingBsp;
        Structure = new CellStruct(physicsBsp, cellBsp, portals);
    }

    /// <summary>The structure's key in its environment. Retail: <c>cellstruct_id</c>.</summary>
    public uint CellStructId { get; }

    /// <summary>The vertex positions, cell-local. Retail: <c>vertex_array</c>.</summary>
    public ReadOnlySpan<Vector3> Vertices => _vertices;

    /// <summary>How many drawing polygons the structure holds. Retail: <c>num_polygons</c>.</summary>
    public int PolygonCount { get; }

    /// <summary>The portal polygons (drawing polygons the portal list names, in list order). Retail: <c>portals</c>.</summary>
    public ReadOnlySpan<Polygon> Portals => _portals;

    /// <summary>The cell's region as stored. Retail: <c>cell_bsp</c>.</summary>
    public BspTree CellBsp { get; }

    /// <summary>The physics polygons, cell-local. Retail: <c>physics_polygons</c>.</summary>
    public ReadOnlySpan<Polygon> PhysicsPolygons => _physicsPolygons;

    /// <summary>The physics BSP as stored. Retail: <c>physics_bsp</c>.</summary>
    public BspTree PhysicsBsp { get; }

    /// <summary>True when a drawing BSP was stored (read and dropped). Retail: <c>drawing_bsp</c> not null.</summary>
    public bool HasDrawingBsp { get; }

    /// <summary>The library's cell structure over the stored trees and portals, for an <see cref="EnvCell"/>.</summary>
    public CellStruct Structure { get; }

    /// <summary>
    /// Reads one structure: its id, the polygon, physics polygon and portal counts, the vertex array, the drawing polygons,
    /// the portal list (16-bit indices into the drawing polygons), 4-alignment, the cell BSP (planes only), the physics
    /// polygons, the physics BSP, a flag and the drawing BSP when it is set, 4-alignment.
    /// </summary>
    // retail: CCellStruct::UnPack (acclient.c:355822)
    internal static CellStructEntry UnPack(ref RetailDataReader r)
    {
        r.Structure = "CCellStruct";
        uint id = r.ReadUInt32("cell struct id");
        int countsAt = r.Offset;
        uint numPolygons = r.ReadUInt32("polygon count");
        uint numPhysics = r.ReadUInt32("physics polygon count");
        int numPortals = r.ReadCount("portal count", 2);
        r.Structure = "CVertexArray";
        Vector3[] vertices = VertexArrayReader.UnPack(ref r);
        r.Structure = "CPolygon";
        int nPolys = r.CheckCount(numPolygons, "polygon count", 12, countsAt);
        PolygonInfo[] polygons = PolygonInfo.UnPackList(ref r, nPolys, vertices.Length, countsAt);
        r.Structure = "CCellStruct";
        r.CheckCount((uint)numPortals, "portal count", 2, countsAt + 8);
        var portals = new Polygon[numPortals];
        for (int i = 0; i < numPortals; i++)
        {
            int at = r.Offset;
            ushort index = r.ReadUInt16("portal polygon index");
            if (index >= polygons.Length)
            {
                throw r.ErrorAt(at, $"portal polygon index {index} is outside the polygon list ({polygons.Length} polygons)");
            }

            portals[i] = polygons[index].ToPolygon(vertices, "CCellStruct");
        }

        r.Align4();
        r.Structure = "BSPTREE";
        BspTree cellBsp = BspReader.UnPackTree(ref r, BspKind.Cell, [], polygons.Length)!;
        r.Structure = "CPolygon";
        int nPhysics = r.CheckCount(numPhysics, "physics polygon count", 12, countsAt + 4);
        Polygon[] physics = PolygonInfo.ToPolygons(PolygonInfo.UnPackList(ref r, nPhysics, vertices.Length, countsAt + 4), vertices, "CCellStruct");
        r.Structure = "BSPTREE";
        BspTree physicsBsp = BspReader.UnPackTree(ref r, BspKind.Physics, physics, physics.Length)!;
        r.Structure = "CCellStruct";
        bool hasDrawing = r.ReadUInt32("drawing BSP flag") != 0;
        if (hasDrawing)
        {
            r.Structure = "BSPTREE";
            BspReader.UnPackTree(ref r, BspKind.Drawing, [], polygons.Length);
            r.Structure = "CCellStruct";
        }

        r.Align4();
        return new CellStructEntry(id, vertices, polygons.Length, portals, cellBsp, physics, physicsBsp, hasDrawing);
    }
}
