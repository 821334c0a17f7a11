using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Primitives;

public partial struct CylSphere
{
    /// <summary>
    /// A path-clipped missile's sphere hits the cylinder. With PERFECT_CLIP the check sphere moves back along the step to
    /// the time of impact on the side, top or bottom and the surface normal there is recorded (Adjusted); otherwise only
    /// the normal is recorded (Collided: the sweep stops at the last valid step).
    /// </summary>
    /// <remarks>As in retail the movement and the impact point are measured from the FIRST sphere's current centre,
    /// whichever sphere hit.</remarks>
    // retail: CCylSphere::collide_with_point (acclient.c:361704)
    private readonly TransitionState CollideWithPoint(ObjectInfo obj, SpherePath path, CollisionInfo collisions, in Sphere checkPos,
        Vector3 disp, float radsum, int sphereNum)
    {
        bool definite = NormalOfCollision(path, checkPos, disp, radsum, sphereNum, out Vector3 cn);
        if (VectorMath.NormalizeCheckSmall(ref cn))
        {
            return TransitionState.Collided;
        }

        if ((obj.State & ObjectInfoState.PerfectClip) == 0)
        {
            collisions.SetCollisionNormal(cn);
            return TransitionState.Collided;
        }

        Vector3 gcc = path.GlobalCurrCenter[0];
        Vector3 block = LandDefs.GetBlockOffset(path.CurrPos.ObjCellId, path.CheckPos.ObjCellId);
        double dx = (double)checkPos.Center.X - gcc.X;
        double dy = (double)checkPos.Center.Y - gcc.Y;
        float dz = checkPos.Center.Z - gcc.Z;
        float mx = (float)(block.X + dx);
        float my = (float)(block.Y + dy);
        float mz = block.Z + dz;
        float oldX = gcc.X - LowPt.X;
        float oldY = gcc.Y - LowPt.Y;
        float oldZ = gcc.Z - LowPt.Z;
        float r = (float)(radsum + EpsD);
        double time;
        Vector3 offset;
        if (!definite)
        {
            if (Math.Abs(mz) < EpsD)
            {
                return TransitionState.Collided;
            }

            // Not yet level with the cylinder: the time the sphere reaches the bottom (moving up) or the top (moving down).
            float sign;
            if (mz > 0f)
            {
                sign = -1f;
                time = -(((double)oldZ + checkPos.Radius) / mz);
            }
            else
            {
                sign = 1f;
                time = ((double)checkPos.Radius + Height - oldZ) / mz;
            }

            cn = new Vector3(0f, 0f, sign);
            offset = new Vector3((float)(mx * time), (float)(my * time), (float)(time * mz));
            float rr = r * r;
            double sy = (double)offset.Y + oldY;
            double sx = (double)offset.X + oldX;
            if (sy * sy + sx * sx >= rr)
            {
                // Outside the radius at that height: the side is hit first.
                double a = (double)my * my + (double)mx * mx;
                if (Math.Abs(a) < EpsD)
                {
                    return TransitionState.Collided;
                }

                double b = -((double)my * oldY + (double)mx * oldX);
                double disc = b * b - ((double)oldY * oldY + (double)oldX * oldX - rr) * a;
                if (disc >= 0.0 && a > EpsD)
                {
                    double s = Math.Sqrt(disc);
                    time = b - s < 0.0 ? (s - ((double)my * oldY + (double)mx * oldX)) / a : (b - s) / a;
                    float tf = (float)time;
                    offset = new Vector3(mx * tf, my * tf, mz * tf);
                }

                cn = Sphere.DivideByFloat(new Vector3(gcc.X + offset.X - LowPt.X, gcc.Y + offset.Y - LowPt.Y, 0f), r);
            }
        }
        else if (cn.Z != 0f)
        {
            if (Math.Abs(mz) < EpsD)
            {
                return TransitionState.Collided;
            }

            time = mz > 0f
                ? -(((double)oldZ + checkPos.Radius) / mz)
                : ((double)checkPos.Radius + Height - oldZ) / mz;
            float tf = (float)time;
            offset = new Vector3(mx * tf, my * tf, mz * tf);
        }
        else
        {
            double a = (double)my * my + (double)mx * mx;
            double b = -((double)my * oldY + (double)mx * oldX);
            double disc = b * b - ((double)oldY * oldY + (double)oldX * oldX - (double)r * r) * a;
            if (!(disc >= 0.0 && a >= EpsD))
            {
                return TransitionState.Collided;
            }

            double s = Math.Sqrt(disc);
            time = b - s < 0.0 ? (s - ((double)my * oldY + (double)mx * oldX)) / a : (b - s) / a;
            float tf = (float)time;
            offset = new Vector3(mx * tf, my * tf, mz * tf);
            if (!(time >= 0.0 && time <= 1.0))
            {
                return TransitionState.Collided;
            }

            cn = Sphere.DivideByFloat(new Vector3(gcc.X + offset.X - LowPt.X, gcc.Y + offset.Y - LowPt.Y, 0f), r);
        }

        if (!(time >= 0.0) || time > 1.0)
        {
            return TransitionState.Collided;
        }

        // The impact point relative to the check sphere (retail ignores the block offset here).
        var back = new Vector3(gcc.X + offset.X - checkPos.Center.X, gcc.Y + offset.Y - checkPos.Center.Y, gcc.Z + offset.Z - checkPos.Center.Z);
        collisions.SetCollisionNormal(cn);
        path.AddOffsetToCheckPos(back);
        return TransitionState.Adjusted;
    }
}
