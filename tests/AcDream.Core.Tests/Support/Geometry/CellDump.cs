using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using System.Text.Json;

namespace AcDream.Core.Tests.Support.Geometry;

/// <summary>One polygon of a geometry dump: its vertices (the dumped plane is recomputed by the library).</summary>
internal sealed record DumpPolygon(int Id, Vector3[] Vertices, Vector3 Normal, float D);

/// <summary>A portal of an EnvCell dump: the neighbour's low id (0xFFFF = outside), the portal polygon's index into
/// <see cref="CellDump.PortalPolygons"/> and the raw flags (bit 1 exact match, bit 2 portal side).</summary>
internal readonly record struct DumpPortal(ushort OtherCellId, ushort PolygonId, ushort Flags);

/// <summary>
/// An EnvCell dump of ../shared/data/geometry (format: its README): cell id, world transform (row vectors, translation in
/// M41..M43, landblock-local metres), physics polygons, drawing/portal polygons and portals, all cell-local.
/// </summary>
internal sealed record CellDump(uint CellId, Matrix4x4 WorldTransform, DumpPolygon[] PhysicsPolygons, DumpPolygon[] PortalPolygons, DumpPortal[] Portals)
{
    /// <summary>Reads one EnvCell dump (<c>0xXXXXXXXX.json</c>).</summary>
    public static CellDump Read(string path)
    {
        using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(path));
        JsonElement root = doc.RootElement;
        JsonElement m = root.GetProperty("WorldTransform");
        var world = new Matrix4x4(
            F(m, "M11"), F(m, "M12"), F(m, "M13"), F(m, "M14"),
            F(m, "M21"), F(m, "M22"), F(m, "M23"), F(m, "M24"),
            F(m, "M31"), F(m, "M32"), F(m, "M33"), F(m, "M34"),
            F(m, "M41"), F(m, "M42"), F(m, "M43"), F(m, "M44"));
        var portals = new List<DumpPortal>();
        foreach (JsonElement p in root.GetProperty("Portals").EnumerateArray())
        {
            portals.Add(new DumpPortal(p.GetProperty("OtherCellId").GetUInt16(), p.GetProperty("PolygonId").GetUInt16(), p.GetProperty("Flags").GetUInt16()));
        }

        return new CellDump(root.GetProperty("CellId").GetUInt32(), world, Polygons(root.GetProperty("ResolvedPolygons")),
            Polygons(root.GetProperty("PortalPolygons")), portals.ToArray());
    }

    /// <summary>Reads the polygons of a GfxObj dump (<c>0xXXXXXXXX.gfxobj.json</c>), object-local.</summary>
    public static DumpPolygon[] ReadGfxObjPolygons(string path)
    {
        using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(path));
        return Polygons(doc.RootElement.GetProperty("ResolvedPolygons"));
    }

    private static DumpPolygon[] Polygons(JsonElement list)
    {
        var result = new List<DumpPolygon>();
        foreach (JsonElement p in list.EnumerateArray())
        {
            var verts = new List<Vector3>();
            foreach (JsonElement v in p.GetProperty("Vertices").EnumerateArray())
            {
                verts.Add(V(v));
            }

            JsonElement plane = p.GetProperty("Plane");
            result.Add(new DumpPolygon(p.GetProperty("Id").GetInt32(), verts.ToArray(), V(plane.GetProperty("Normal")), F(plane, "D")));
        }

        return result.ToArray();
    }

    private static Vector3 V(JsonElement e) => new(F(e, "X"), F(e, "Y"), F(e, "Z"));

    private static float F(JsonElement e, string name) => e.GetProperty(name).GetSingle();
}

/// <summary>Where the geometry dumps are: <c>ACDREAM_GEOMETRY_DIR</c>, else the <c>geometry</c> folder beside the terrain
/// folder (both live in ../shared/data); see <see cref="SharedDataDir.Geometry"/>.</summary>
internal static class GeometryTestData
{
    /// <summary>The environment variable naming the geometry folder.</summary>
    public const string Variable = "ACDREAM_GEOMETRY_DIR";

    /// <summary>The geometry folder, or null.</summary>
    public static string? Dir => SharedDataDir.Geometry.Dir;
}

/// <summary>A fact that needs the real cellar geometry and the real terrain; skipped with the reason when either is absent
/// (<c>GeometryDataReportTests</c> prints the reason in every run).</summary>
public sealed class GeometryDataFactAttribute : Xunit.FactAttribute
{
    /// <summary>Skips the test when the geometry or terrain folder is missing.</summary>
    public GeometryDataFactAttribute()
    {
        if (SharedDataDir.Geometry.Find(out string reason) is null)
        {
            Skip = "Real cellar geometry not found: " + reason + ".";
        }
        else if (TerrainTestData.FindDir(out reason) is null)
        {
            Skip = "Real terrain data not found: " + reason + ".";
        }
    }
}
