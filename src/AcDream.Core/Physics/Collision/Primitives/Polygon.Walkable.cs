using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Primitives;

// The walkable-polygon queries of the sweep (used with BSP walkables; terrain never sets one).
public sealed partial class Polygon
{
    /// <summary>
    /// True when <paramref name="sphere"/>, dropped along <paramref name="up"/> onto the polygon's plane, still stands on
    /// the polygon: its projected centre is inside every edge, or within the radius of an edge segment or of a vertex.
    /// </summary>
    /// <remarks>Retail ambiguity BSP-B1 (docs/divergences.md): after "outside this edge" the decompiler shows a flags-only
    /// compare whose operands were lost. It is read, here as in the BSP's polygon tests, as "outside this edge by more than
    /// the radius" → not walkable; a centre outside an edge by less than the radius goes on to the edge-segment and vertex
    /// tests (the code the decompiler prints after the compare). Same edge walk as <see cref="CheckSmallWalkable"/> with
    /// the full radius.</remarks>
    // retail: CPolygon::check_walkable (acclient.c:360226)
    public bool CheckWalkable(in Sphere sphere, Vector3 up)
    {
        if (!DropOntoPlane(sphere.Center, up, out Vector3 dropped))
        {
            return false;
        }

        float inside = (float)((double)sphere.Radius * sphere.Radius);
        return DiscTouches(dropped, inside);
    }

    /// <summary>
    /// The first edge (from the last vertex round to the first) that <paramref name="sphere"/>'s centre, dropped along
    /// <paramref name="up"/> onto the plane, lies outside of; <paramref name="normal"/> receives that edge's unit
    /// in-plane normal <c>cross(N, edge)</c> (pointing into the polygon). False when no edge is crossed.
    /// </summary>
    // retail: CPolygon::find_crossed_edge (acclient.c:360396)
    internal bool FindCrossedEdge(in Sphere sphere, Vector3 up, out Vector3 normal)
    {
        normal = Vector3.Zero;
        if (!DropOntoPlane(sphere.Center, up, out Vector3 dropped))
        {
            return false;
        }

        Vector3 n = Plane.N;
        float cx = dropped.X, cy = dropped.Y, cz = dropped.Z;
        ReadOnlySpan<Vector3> v = Vertices;
        int last = v.Length - 1;
        for (int i = 0; i < v.Length; i++)
        {
            Vector3 a = v[last];
            Vector3 b = v[i];
            last = i;
            float ex = b.X - a.X;
            float ey = b.Y - a.Y;
            float ez = (float)((double)b.Z - a.Z);
            double test = ((double)cz - a.Z) * ((double)ey * n.X - (double)ex * n.Y)
                          + ((double)cy - a.Y) * ((double)ex * n.Z - (double)ez * n.X)
                          + ((double)cx - a.X) * ((double)ez * n.Y - (double)ey * n.Z);
            if (test < 0.0 || double.IsNaN(test))
            {
                float nx = (float)((double)ez * n.Y - (double)ey * n.Z);
                float ny = (float)((double)ex * n.Z - (double)ez * n.X);
                float nz = (float)((double)ey * n.X - (double)ex * n.Y);
                double len = Math.Sqrt((double)nx * nx + (double)ny * ny + (double)nz * nz);
                normal = new Vector3((float)(1.0 / len * nx), (float)(1.0 / len * ny), (float)(1.0 / len * nz));
                return true;
            }
        }

        return false;
    }

    // A sphere centre dropped along up onto the plane, as check_walkable, check_small_walkable and find_crossed_edge each do
    // (acclient.c:360226, 360311, 360396): the parameter in double, x subtracted in double, y and z through float products.
    // False when up runs along the plane (|N . up| < EPSILON).
    private bool DropOntoPlane(Vector3 c, Vector3 up, out Vector3 dropped)
    {
        Vector3 n = Plane.N;
        double angleUp = (double)n.Y * up.Y + (double)n.Z * up.Z + (double)n.X * up.X;
        if (Math.Abs(angleUp) < PhysicsGlobals.Epsilon)
        {
            dropped = default;
            return false;
        }

        double t = ((double)n.Z * c.Z + (double)n.Y * c.Y + (double)n.X * c.X + Plane.D) / angleUp;
        float ty = (float)(t * up.Y);
        float tz = (float)(t * up.Z);
        dropped = new Vector3((float)(c.X - t * up.X), c.Y - ty, c.Z - tz);
        return true;
    }
}
