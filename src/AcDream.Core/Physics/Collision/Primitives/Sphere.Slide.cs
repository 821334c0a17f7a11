using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Primitives;

public partial struct Sphere
{
    /// <summary>
    /// Slides the swept sphere along a surface it hit: the movement since the current position is projected onto the
    /// crease between the hit surface and the contact plane (the cross product of the two normals), or, when the two are
    /// parallel, onto the hit surface itself; the check position is moved to the slid place.
    /// </summary>
    /// <param name="path">The sphere path whose check position is moved.</param>
    /// <param name="collisions">Receives the collision normal; supplies the contact plane (or the last known one).</param>
    /// <param name="collisionNormal">The normal of the surface hit. Retail overwrites the caller's vector with the reversed
    /// movement on the last (stuck) branch; so does this port.</param>
    /// <param name="currPos">The sphere's centre at the current (last valid) position.</param>
    /// <returns><see cref="TransitionState.Slid"/> after a slide, <see cref="TransitionState.Adjusted"/> for a zero normal
    /// (halfway back to the current position), <see cref="TransitionState.Collided"/> when nothing is left of the move.</returns>
    // retail: CSphere::slide_sphere (acclient.c:358898)
    internal readonly TransitionState SlideSphere(SpherePath path, CollisionInfo collisions, ref Vector3 collisionNormal, Vector3 currPos)
    {
        Vector3 n = collisionNormal;
        if (n.X == 0f && n.Y == 0f && n.Z == 0f)
        {
            double hx = (double)currPos.X - Center.X;
            float hy = currPos.Y - Center.Y;
            float hz = currPos.Z - Center.Z;
            hz = (float)(hz * 0.5);
            var back = new Vector3((float)(hx * 0.5), (float)(hy * 0.5), hz);
            path.AddOffsetToCheckPos(back);
            return TransitionState.Adjusted;
        }

        collisions.SetCollisionNormal(n);
        Vector3 blockOffset = LandDefs.GetBlockOffset(path.CurrPos.ObjCellId, path.CheckPos.ObjCellId);
        double dx = (double)Center.X - currPos.X;
        double dy = (double)Center.Y - currPos.Y;
        float dz = Center.Z - currPos.Z;
        float mx = (float)(blockOffset.X + dx);
        float my = (float)(blockOffset.Y + dy);
        float mz = blockOffset.Z + dz;

        Vector3 planeN = collisions.ContactPlaneValid ? collisions.ContactPlane.N : collisions.LastKnownContactPlane.N;

        // direction = collision normal x contact plane normal: the crease between the two surfaces.
        float dirX = (float)((double)n.Y * planeN.Z - (double)n.Z * planeN.Y);
        double dirY = (double)planeN.X * n.Z - (double)planeN.Z * n.X;
        double dirZd = (double)planeN.Y * n.X - (double)planeN.X * n.Y;
        float dirZ = (float)dirZd;
        double len2 = dirZd * dirZ + dirY * dirY + (double)dirX * dirX;
        float len2f = (float)len2;
        if (len2 >= PhysicsGlobals.Epsilon)
        {
            double along = (double)dirZ * mz + dirY * my + (double)dirX * mx;
            float py = (float)(dirY * along);
            float pz = (float)(dirZ * along);
            double inv = 1.0 / len2f;
            float invf = (float)inv;
            double px = dirX * along * inv;
            float projY = py * invf;
            float projZ = pz * invf;
            if ((double)projZ * projZ + (double)projY * projY + px * px < PhysicsGlobals.Epsilon)
            {
                return TransitionState.Collided;
            }

            var slide = new Vector3((float)(px - mx), projY - my, projZ - mz);
            path.AddOffsetToCheckPos(slide);
            return TransitionState.Slid;
        }

        if ((double)n.Z * planeN.Z + (double)n.Y * planeN.Y + (double)planeN.X * n.X >= 0.0)
        {
            // The hit surface faces the same way as the contact plane: take the movement off along its normal.
            float into = (float)((double)mx * n.X + (double)mz * n.Z + (double)my * n.Y);
            var push = new Vector3((float)(-(double)n.X * into), -n.Y * into, -n.Z * into);
            path.AddOffsetToCheckPos(push);
            return TransitionState.Slid;
        }

        collisionNormal = new Vector3(-mx, -my, -mz);
        if (!VectorMath.NormalizeCheckSmall(ref collisionNormal))
        {
            collisions.SetCollisionNormal(collisionNormal);
        }

        return TransitionState.Collided;
    }
}
