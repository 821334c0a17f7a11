using System;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Scenery;

// obj_within_block: the test a scenery object passes, at scale 1, before it is added to its cell.
public static partial class SceneryGenerator
{
    /// <summary>
    /// True when an object with this shape, at block-local <paramref name="frame"/> and scale 1, lies within its landblock
    /// as retail's scenery requires (a failed object is deleted, acclient.c:352721):
    /// <list type="bullet">
    /// <item>with a physics BSP (<paramref name="hasPhysicsBsp"/>, state bit <c>HAS_PHYSICS_BSP</c> 0x10000): the sorting
    /// sphere's centre through the frame must satisfy <c>r ≤ x &lt; 192 − r</c> and <c>r ≤ y &lt; 192 − r</c>;</item>
    /// <item>else with cylinder spheres: each cylinder's low point through the frame, against its radius, the same way;</item>
    /// <item>else with spheres (<paramref name="hasSpheres"/>): the sorting sphere through the frame, by
    /// <c>LandDefs::within_block</c>;</item>
    /// <item>else the origin, with radius 0.</item>
    /// </list>
    /// Call it with <see cref="ScenePlacement.Frame"/> before applying <see cref="ScenePlacement.Scale"/>, as retail does.
    /// </summary>
    /// <param name="frame">The object's block-local frame.</param>
    /// <param name="hasPhysicsBsp">The object has a part with a physics BSP.</param>
    /// <param name="sortingSphere">The object's sorting sphere (its part array's; a GfxObj's simple setup takes the physics
    /// sphere, else the drawing sphere). Retail's dummy sphere for an object without a part array.</param>
    /// <param name="cylSpheres">The setup's cylinder spheres (unscaled).</param>
    /// <param name="hasSpheres">The setup has collision spheres.</param>
    // retail: CPhysicsObj::obj_within_block (acclient.c:318306)
    public static bool ObjWithinBlock(in Frame frame, bool hasPhysicsBsp, Sphere sortingSphere, ReadOnlySpan<CylSphere> cylSpheres,
        bool hasSpheres)
    {
        if (hasPhysicsBsp)
        {
            return SphereWithinBlock(frame.LocalToGlobal(sortingSphere.Center), sortingSphere.Radius);
        }

        if (cylSpheres.Length > 0)
        {
            foreach (CylSphere c in cylSpheres)
            {
                System.Numerics.Vector3 p = c.LowPt;
                double gx = (double)frame.M21 * p.Y + (double)p.Z * frame.M31 + (double)frame.M11 * p.X + frame.Origin.X;
                float gy = (float)((double)frame.M22 * p.Y + (double)frame.M12 * p.X + (double)frame.M32 * p.Z + frame.Origin.Y);
                float r = c.Radius;
                if (gx < r || gy < r)
                {
                    return false;
                }

                float far = LandDefs.BlockLength - r;
                if (gx >= far || gy >= (double)far)
                {
                    return false;
                }
            }

            return true;
        }

        if (hasSpheres)
        {
            return LandDefs.WithinBlock(frame.LocalToGlobal(sortingSphere.Center), sortingSphere.Radius);
        }

        return LandDefs.WithinBlock(frame.Origin, 0f);
    }

    // The HAS_PHYSICS_BSP branch of obj_within_block: r <= x, y and x, y < 192 - r, the far bound kept in double.
    private static bool SphereWithinBlock(System.Numerics.Vector3 center, float radius)
    {
        if (center.X >= (double)radius && center.Y >= (double)radius)
        {
            double far = LandDefs.BlockLength - (double)radius;
            return center.X < far && center.Y < far;
        }

        return false;
    }
}
