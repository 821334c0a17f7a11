using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Primitives;

/// <summary>
/// A convex polygon with its plane, ported from retail's <c>CPolygon</c> (acclient.h:31855, PORTAL/cgeometry/CPolygon.c).
/// Vertices are kept in retail's order (the order the data lists them); a polygon wound counter-clockwise when seen from
/// the side its normal points to has that normal (right-hand rule), as <see cref="MakePlane"/> computes it.
/// </summary>
/// <remarks>
/// <para>Retail holds pointers into a shared vertex array; this port copies the vertex positions into the polygon when it
/// is built (terrain vertices never move afterwards) and keeps the shared indices in <see cref="VertexIds"/>.</para>
/// <para>The class is partial so that further retail polygon tests (sphere hits, walkable checks, crossed edges) can be
/// added in their own files.</para>
/// <para>Valid domain of the queries: any point, sphere or vector; they never change the polygon, and a non-finite input
/// gives an answer, never an exception (the misuse suite calls each with NaN, ±∞, ±MaxValue, subnormal and −0).</para>
/// </remarks>
public sealed partial class Polygon
{
    private readonly Vector3[] _vertices;
    private readonly ushort[] _vertexIds;

    /// <summary>The polygon's plane; set by <see cref="MakePlane"/>. Retail: <c>plane</c>.</summary>
    public CollisionPlane Plane;

    /// <summary>
    /// Creates a polygon from its vertex positions and their indices in the owner's vertex array, and computes its plane.
    /// </summary>
    /// <param name="polyId">Retail <c>poly_id</c>: the polygon's index in its owner.</param>
    /// <param name="vertices">Three or more vertex positions, in order.</param>
    /// <param name="vertexIds">The vertices' indices in the owner's vertex array (same length as <paramref name="vertices"/>).</param>
    /// <exception cref="ArgumentException">Fewer than three vertices, mismatched lengths, or a NaN or infinite vertex.</exception>
    public Polygon(short polyId, ReadOnlySpan<Vector3> vertices, ReadOnlySpan<ushort> vertexIds)
    {
        if (vertices.Length < 3)
        {
            throw new ArgumentException("A polygon needs at least three vertices.", nameof(vertices));
        }

        if (vertexIds.Length != vertices.Length)
        {
            throw new ArgumentException("One vertex id per vertex is required.", nameof(vertexIds));
        }

        for (int i = 0; i < vertices.Length; i++)
        {
            if (!VectorMath.IsFinite(vertices[i]))
            {
                throw new ArgumentException("Polygon vertices must be finite.", nameof(vertices));
            }
        }

        PolyId = polyId;
        _vertices = vertices.ToArray();
        _vertexIds = vertexIds.ToArray();
        MakePlane();
    }

    /// <summary>The polygon's index in its owner. Retail: <c>poly_id</c>.</summary>
    public short PolyId { get; }

    /// <summary>The number of vertices. Retail: <c>num_pts</c>.</summary>
    public int NumPoints => _vertices.Length;

    /// <summary>The vertex positions, in retail order, in the owner's coordinates (landblock-local for terrain).</summary>
    public ReadOnlySpan<Vector3> Vertices => _vertices;

    /// <summary>The vertices' indices in the owner's vertex array. Retail: <c>vertex_ids</c>.</summary>
    public ReadOnlySpan<ushort> VertexIds => _vertexIds;

    /// <summary>
    /// Computes <see cref="CollisionPlane"/> from the vertices: the normal is the normalised sum of the fan cross products
    /// <c>(v[t] - v[0]) × (v[t+1] - v[0])</c>, and d is minus the mean of <c>N·v</c> over all vertices.
    /// </summary>
    /// <remarks>
    /// Arithmetic as retail: the x and y sums are double, the z sum a float; the cross components are rounded to float;
    /// the inverse length is double for x but its float rounding is used for y and z; d sums z, y, x per vertex in double.
    /// </remarks>
    // retail: CPolygon::make_plane (acclient.c:359627)
    public void MakePlane()
    {
        Vector3[] v = _vertices;
        int n = v.Length;
        Vector3 v0 = v[0];
        double sumX = 0.0;
        double sumY = 0.0;
        float sumZ = 0f;
        for (int t = 1; t < n - 1; t++)
        {
            Vector3 a = v[t];
            Vector3 b = v[t + 1];
            double bx = (double)b.X - v0.X;
            double by = (double)b.Y - v0.Y;
            double bz = (double)b.Z - v0.Z;
            float ax = (float)((double)a.X - v0.X);
            float ay = (float)((double)a.Y - v0.Y);
            double az = (double)a.Z - v0.Z;
            float cx = (float)(ay * bz - az * by);
            float cy = (float)(az * bx - bz * ax);
            sumX += cx;
            sumY += cy;
            sumZ = (float)(by * ax - ay * bx + sumZ);
        }

        double inv = 1.0 / Math.Sqrt((double)sumZ * sumZ + sumY * sumY + sumX * sumX);
        float invF = (float)inv;
        float nx = (float)(inv * sumX);
        float ny = (float)(invF * sumY);
        float nz = (float)(invF * (double)sumZ);

        double s = 0.0;
        for (int i = 0; i < n; i++)
        {
            s = s + (double)nz * v[i].Z + (double)ny * v[i].Y + (double)nx * v[i].X;
        }

        Plane = new CollisionPlane(new Vector3(nx, ny, nz), (float)-(s / n));
    }

    /// <summary>
    /// True when <paramref name="point"/>'s x, y lie inside the polygon's outline projected onto the ground plane (edges
    /// included). Tests each edge's 2D cross product; with <see cref="Sidedness.Positive"/> (terrain's choice) a point is
    /// outside when it lies strictly to the right of any edge of a counter-clockwise (seen from above) polygon.
    /// </summary>
    /// <remarks>Edges are visited from the last vertex back: (v[n-1]→v[0]), (v[n-2]→v[n-1]), …, (v[0]→v[1]).</remarks>
    // retail: CPolygon::point_in_poly2D (acclient.c:359419)
    public bool PointInPoly2D(Vector3 point, Sidedness side)
    {
        Vector3[] v = _vertices;
        Vector3 q = v[0];
        for (int j = v.Length - 1; j >= 0; j--)
        {
            Vector3 p = v[j];
            double ey = (double)q.Y - p.Y;
            double ex = (double)p.X - q.X;
            double s = -(ey * p.X) - ex * p.Y + ex * point.Y + ey * point.X;
            if (side != Sidedness.Positive)
            {
                if (s < 0.0)
                {
                    return false;
                }
            }
            else if (s > 0.0)
            {
                return false;
            }

            q = p;
        }

        return true;
    }
}
