using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Bsp;

/// <summary>How a sphere lies against an indoor cell's region (<see cref="BspTree.SphereIntersectsCellBsp(in Sphere)"/>).</summary>
public enum CellBspSphere
{
    /// <summary>The sphere is outside the cell (retail 0).</summary>
    Outside = 0,

    /// <summary>The sphere crosses the cell's boundary (retail 1).</summary>
    Crossing = 1,

    /// <summary>The sphere is wholly inside the cell (retail 2).</summary>
    Inside = 2,
}

// The cell BSP tests: an indoor cell's region as a chain of planes through the positive children.
public sealed partial class BspTree
{
    /// <summary>Margin added to the radius by the cell-region sphere test, metres. Retail: 0.0099999998 (acclient.c:362979).</summary>
    public const float CellSphereMargin = 0.0099999998f;

    /// <summary>
    /// True when <paramref name="origin"/> (cell-local) is not behind any plane of the chain by more than EPSILON
    /// (in-plane counts as inside).
    /// </summary>
    // retail: BSPTREE::point_inside_cell_bsp (acclient.c:360730) -> BSPNODE::point_inside_cell_bsp (acclient.c:362943)
    public bool PointInsideCellBsp(Vector3 origin)
    {
        int i = Root;
        while (true)
        {
            ref readonly BspNode n = ref _nodes[i];
            CollisionPlane p = n.SplittingPlane;
            double d = (double)p.N.Y * origin.Y + (double)p.N.Z * origin.Z + (double)p.N.X * origin.X + p.D;
            if (d <= PhysicsGlobals.Epsilon && d < -PhysicsGlobals.Epsilon)
            {
                return false;
            }

            if (n.PosNode < 0)
            {
                return true;
            }

            i = n.PosNode;
        }
    }

    /// <summary>
    /// Where the sphere (cell-local) lies against the cell region, with the radius widened by
    /// <see cref="CellSphereMargin"/>: outside once it is that far behind any plane, inside when that far in front of
    /// every plane, crossing otherwise.
    /// </summary>
    // retail: BSPTREE::sphere_intersects_cell_bsp (acclient.c:360736) -> BSPNODE::sphere_intersects_cell_bsp (acclient.c:362979)
    public CellBspSphere SphereIntersectsCellBsp(in Sphere sphere) => SphereIntersectsCellBsp(Root, sphere);

    private CellBspSphere SphereIntersectsCellBsp(int i, in Sphere sphere)
    {
        ref readonly BspNode n = ref _nodes[i];
        Vector3 c = sphere.Center;
        CollisionPlane p = n.SplittingPlane;
        double d = (double)p.N.Y * c.Y + (double)p.N.Z * c.Z + (double)p.N.X * c.X + p.D;
        float r = (float)(sphere.Radius + (double)CellSphereMargin);
        if (d <= -r)
        {
            return CellBspSphere.Outside;
        }

        while (true)
        {
            int next = n.PosNode;
            if (d < r)
            {
                if (next < 0)
                {
                    return CellBspSphere.Crossing;
                }

                return SphereIntersectsCellBsp(next, sphere) != CellBspSphere.Outside ? CellBspSphere.Crossing : CellBspSphere.Outside;
            }

            if (next < 0)
            {
                return CellBspSphere.Inside;
            }

            n = ref _nodes[next];
            p = n.SplittingPlane;
            d = (double)p.N.Y * c.Y + (double)p.N.Z * c.Z + (double)p.N.X * c.X + p.D;
            if (d <= -r)
            {
                return CellBspSphere.Outside;
            }
        }
    }

    /// <summary>
    /// False when the axis-aligned box (cell-local) lies wholly behind some plane of the cell region's chain: its low corner
    /// below -EPSILON and every other corner on the negative side (<see cref="CollisionPlane.WhichSide"/> with EPSILON);
    /// true otherwise.
    /// </summary>
    // retail: BSPTREE::box_intersects_cell_bsp (acclient.c:360724) -> BSPNODE::box_intersects_cell_bsp (acclient.c:363424)
    internal bool BoxIntersectsCellBsp(Vector3 min, Vector3 max)
    {
        const float eps = PhysicsGlobals.Epsilon;
        int i = Root;
        while (true)
        {
            ref readonly BspNode n = ref _nodes[i];
            CollisionPlane p = n.SplittingPlane;
            double d = p.DotProduct(min);
            if (d <= eps && d < -eps
                && p.WhichSide(max, eps) == Sidedness.Negative
                && p.WhichSide(new Vector3(min.X, min.Y, max.Z), eps) == Sidedness.Negative
                && p.WhichSide(new Vector3(min.X, max.Y, min.Z), eps) == Sidedness.Negative
                && p.WhichSide(new Vector3(max.X, min.Y, min.Z), eps) == Sidedness.Negative
                && p.WhichSide(new Vector3(max.X, min.Y, max.Z), eps) == Sidedness.Negative
                && p.WhichSide(new Vector3(min.X, max.Y, max.Z), eps) == Sidedness.Negative
                && p.WhichSide(new Vector3(max.X, max.Y, min.Z), eps) == Sidedness.Negative)
            {
                return false;
            }

            if (n.PosNode < 0)
            {
                // The decompilation's loop ends in a bare break (the trailing return is lost); the only explicit return
                // is the outside 0, so the end of the chain answers 1 (the box meets the region).
                return true;
            }

            i = n.PosNode;
        }
    }
}
