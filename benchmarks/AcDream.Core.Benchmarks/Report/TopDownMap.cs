using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using System.Text;
using AcDream.Core.Physics.Debug;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// A top-down SVG of what collides in a 3 × 3 of landblocks, drawn through the library's debug view
/// (<see cref="PhysicsDebugDraw"/>): the terrain triangles shaded by height, the land-cell and landblock grid, the buildings'
/// shells, the static objects and the scenery as their collision shapes (each kind its colour), and a walker's path.
/// Plain SVG text; no package.
/// </summary>
internal static class TopDownMap
{
    private const double Scale = 1.5, Margin = 40.0, Side = 3 * 192.0, Legend = 125.0;

    /// <summary>The picture of <paramref name="world"/>'s 3 × 3 whose south-west block is <paramref name="southWest"/>.</summary>
    public static string Render(PhysicsWorld world, IReadOnlyList<WorldBlock> blocks, IReadOnlyList<Position> path, uint southWest,
        string title)
    {
        var view = new PhysicsDebugDraw(world);
        DebugDrawRegion region = DebugDrawRegion.Box(southWest, Vector2.Zero, new Vector2((float)Side, (float)Side));
        var range = new HeightRange { Min = float.MaxValue, Max = float.MinValue };
        view.Draw(ref range, DebugDrawFlags.TerrainTriangles, region);

        var sb = new StringBuilder();
        double w = Side * Scale + 2 * Margin, h = Side * Scale + 2 * Margin + Legend;
        sb.Append(CultureInfo.InvariantCulture,
            $"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w:0}\" height=\"{h:0}\" viewBox=\"0 0 {w:0} {h:0}\" font-family=\"sans-serif\" font-size=\"12\">\n");
        sb.Append(CultureInfo.InvariantCulture, $"<rect width=\"{w:0}\" height=\"{h:0}\" fill=\"white\"/>\n");
        sb.Append(CultureInfo.InvariantCulture, $"<text x=\"{Margin}\" y=\"24\" font-size=\"15\">{title}</text>\n");

        var sink = new SvgSink { Sb = sb, MinZ = range.Min, MaxZ = range.Max };
        sb.Append("<g stroke-width=\"0.3\">\n");
        view.Draw(ref sink, DebugDrawFlags.TerrainTriangles, region);
        sb.Append("</g>\n");
        Grid(sb);

        // Buildings, statics and scenery, each kind in its colour, as the shapes the sweep tests.
        uint frame = region.FrameCellId;
        foreach (WorldBlock b in blocks)
        {
            foreach (WorldObject o in b.Objects)
            {
                (sink.Fill, sink.Stroke) = Colours(o.Kind);
                if (o.Building is not null)
                {
                    view.DrawBuilding(ref sink, o.Building, frame);
                }
                else if (o.Object is not null)
                {
                    view.DrawObject(ref sink, o.Object, DebugDrawFlags.Objects, frame);
                }
            }
        }

        Path(sb, path, frame);
        if (path.Count > 0 && world.Player is { } player)
        {
            (sink.Fill, sink.Stroke) = ("#e02020", "#800000");
            view.DrawObject(ref sink, player, DebugDrawFlags.ObjectSpheres | DebugDrawFlags.LastSweeps, frame);
        }

        Key(sb, range);
        sb.Append("</svg>\n");
        return sb.ToString();
    }

    private static (string Fill, string Stroke) Colours(WorldObjectKind kind) => kind switch
    {
        WorldObjectKind.Building => ("#b08060", "#503020"),
        WorldObjectKind.LandBlockStatic => ("#5070d0", "#203070"),
        WorldObjectKind.EnvCellStatic => ("#8050c0", "#402060"),
        _ => ("#30a040", "#105018"),
    };

    internal static double X(double x) => Margin + x * Scale;

    internal static double Y(double y) => Margin + (Side - y) * Scale;

    // The 24 m land-cell grid (thin) and the 192 m landblock grid (thick), with the blocks' ids.
    private static void Grid(StringBuilder sb)
    {
        sb.Append("<g stroke=\"#000\" fill=\"none\">\n");
        for (int i = 0; i <= 24; i++)
        {
            double t = i * 24.0, width = i % 8 == 0 ? 1.6 : 0.25;
            sb.Append(CultureInfo.InvariantCulture,
                $"<line x1=\"{X(t):0.#}\" y1=\"{Y(0):0.#}\" x2=\"{X(t):0.#}\" y2=\"{Y(Side):0.#}\" stroke-width=\"{width}\" stroke-opacity=\"0.5\"/>\n");
            sb.Append(CultureInfo.InvariantCulture,
                $"<line x1=\"{X(0):0.#}\" y1=\"{Y(t):0.#}\" x2=\"{X(Side):0.#}\" y2=\"{Y(t):0.#}\" stroke-width=\"{width}\" stroke-opacity=\"0.5\"/>\n");
        }

        sb.Append("</g>\n");
        for (int bx = 0; bx < 3; bx++)
        {
            for (int by = 0; by < 3; by++)
            {
                sb.Append(CultureInfo.InvariantCulture,
                    $"<text x=\"{X(bx * 192 + 4):0.#}\" y=\"{Y(by * 192 + 188):0.#}\" fill=\"#000\" fill-opacity=\"0.7\">0x{0xA8 + bx:X2}{0xB3 + by:X2}</text>\n");
            }
        }
    }

    private static void Path(StringBuilder sb, IReadOnlyList<Position> path, uint frame)
    {
        sb.Append("<polyline fill=\"none\" stroke=\"#e02020\" stroke-width=\"2\" points=\"");
        foreach (Position p in path)
        {
            Vector3 g = LandDefs.GetBlockOffset(frame, p.ObjCellId) + p.Frame.Origin;
            sb.Append(CultureInfo.InvariantCulture, $"{X(g.X):0.#},{Y(g.Y):0.#} ");
        }

        sb.Append("\"/>\n");
    }

    private static void Key(StringBuilder sb, HeightRange range)
    {
        double y = Margin + Side * Scale + 30;
        (string Fill, string Label)[] items =
        [
            ("#b08060", "building shell (physics BSP)"), ("#5070d0", "static object (landblock info)"),
            ("#30a040", "scenery (region scenes)"), ("#e02020", "walker's path and sphere"),
        ];
        for (int i = 0; i < items.Length; i++)
        {
            double x = Margin + (i % 2) * 330;
            double yy = y + (i / 2) * 22;
            sb.Append(CultureInfo.InvariantCulture,
                $"<rect x=\"{x:0}\" y=\"{yy - 11:0}\" width=\"14\" height=\"14\" fill=\"{items[i].Fill}\"/><text x=\"{x + 20:0}\" y=\"{yy:0}\">{items[i].Label}</text>\n");
        }

        string[] lines =
        [
            string.Create(CultureInfo.InvariantCulture, $"terrain: its triangles shaded from {range.Min:0} m (dark) to {range.Max:0} m (light)"),
            "grid: thin lines 24 m land cells, thick lines 192 m landblocks; circles: spheres and cylinder spheres seen from above",
            "drawn by the benchmarks' world-map command through AcDream.Core.Physics.Debug.PhysicsDebugDraw (docs/world.md)",
        ];
        for (int i = 0; i < lines.Length; i++)
        {
            sb.Append(CultureInfo.InvariantCulture, $"<text x=\"{Margin}\" y=\"{y + 50 + 18 * i:0}\">{lines[i]}</text>\n");
        }
    }

    private struct HeightRange : IDebugDrawSink
    {
        public float Min, Max;

        public void Triangle(in Vector3 a, in Vector3 b, in Vector3 c, ShapeKind kind, uint id)
        {
            Min = MathF.Min(Min, MathF.Min(a.Z, MathF.Min(b.Z, c.Z)));
            Max = MathF.Max(Max, MathF.Max(a.Z, MathF.Max(b.Z, c.Z)));
        }

        public void Sphere(in Vector3 center, float radius, ShapeKind kind, uint id) { }

        public void Cylinder(in Vector3 lowPoint, float radius, float height, ShapeKind kind, uint id) { }

        public void Polygon(ReadOnlySpan<Vector3> vertices, in Vector3 normal, ShapeKind kind, uint id) { }

        public void Segment(in Vector3 a, in Vector3 b, ShapeKind kind, uint id) { }

        public void Plane(in Vector3 point, in Vector3 normal, ShapeKind kind, uint id) { }
    }

    // Writes each shape as SVG seen from above (x east, y north).
    private struct SvgSink : IDebugDrawSink
    {
        public StringBuilder Sb;
        public float MinZ, MaxZ;
        public string Fill, Stroke;

        public void Triangle(in Vector3 a, in Vector3 b, in Vector3 c, ShapeKind kind, uint id)
        {
            double t = MaxZ > MinZ ? ((a.Z + b.Z + c.Z) / 3.0 - MinZ) / (MaxZ - MinZ) : 0.5;
            int g = (int)(90 + 150 * t), r = (int)(70 + 150 * t), bl = (int)(50 + 120 * t);
            string col = string.Create(CultureInfo.InvariantCulture, $"#{r:X2}{g:X2}{bl:X2}");
            Sb.Append(CultureInfo.InvariantCulture,
                $"<polygon points=\"{X(a.X):0.#},{Y(a.Y):0.#} {X(b.X):0.#},{Y(b.Y):0.#} {X(c.X):0.#},{Y(c.Y):0.#}\" fill=\"{col}\" stroke=\"{col}\"/>\n");
        }

        public void Sphere(in Vector3 center, float radius, ShapeKind kind, uint id) =>
            Sb.Append(CultureInfo.InvariantCulture,
                $"<circle cx=\"{X(center.X):0.#}\" cy=\"{Y(center.Y):0.#}\" r=\"{Math.Max(radius * Scale, 1.0):0.#}\" fill=\"{Fill}\" stroke=\"{Stroke}\" stroke-width=\"0.5\" fill-opacity=\"{(kind == ShapeKind.SweepStart ? 0.3 : 0.9)}\"/>\n");

        public void Cylinder(in Vector3 lowPoint, float radius, float height, ShapeKind kind, uint id) =>
            Sb.Append(CultureInfo.InvariantCulture,
                $"<circle cx=\"{X(lowPoint.X):0.#}\" cy=\"{Y(lowPoint.Y):0.#}\" r=\"{Math.Max(radius * Scale, 1.0):0.#}\" fill=\"{Fill}\" stroke=\"{Stroke}\" stroke-width=\"0.5\"/>\n");

        public void Polygon(ReadOnlySpan<Vector3> vertices, in Vector3 normal, ShapeKind kind, uint id)
        {
            // Seen from above only the faces turned up (roofs, tops) cover ground; walls are their outlines.
            if (normal.Z <= 0.1f)
            {
                return;
            }

            Sb.Append("<polygon points=\"");
            foreach (Vector3 v in vertices)
            {
                Sb.Append(CultureInfo.InvariantCulture, $"{X(v.X):0.#},{Y(v.Y):0.#} ");
            }

            Sb.Append(CultureInfo.InvariantCulture, $"\" fill=\"{Fill}\" stroke=\"{Stroke}\" stroke-width=\"0.6\"/>\n");
        }

        public void Segment(in Vector3 a, in Vector3 b, ShapeKind kind, uint id) =>
            Sb.Append(CultureInfo.InvariantCulture,
                $"<line x1=\"{X(a.X):0.#}\" y1=\"{Y(a.Y):0.#}\" x2=\"{X(b.X):0.#}\" y2=\"{Y(b.Y):0.#}\" stroke=\"{Stroke}\"/>\n");

        public void Plane(in Vector3 point, in Vector3 normal, ShapeKind kind, uint id) { }
    }
}
