using AcDream.Core.Physics.Collision.Primitives;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision;

internal sealed partial class Transition
{
    /// <summary>
    /// What to do when a walker's step left the ground and no step down found any: an object without edge sliding simply
    /// goes on (it will fall); an edge-sliding walker is held back — slid along a cliff (a too-steep contact plane) or
    /// along the edge of the walkable polygon, or stopped.
    /// </summary>
    /// <param name="ts">Receives the state to continue with.</param>
    /// <param name="stepDownHeight">The step-down height used.</param>
    /// <param name="zVal">The walkable threshold used.</param>
    /// <returns>True when <see cref="TransitionalInsert"/> should return <paramref name="ts"/> at once; false to retry.</returns>
    /// <remarks>Retail restores the saved check position FIRST and then slides from it, so the slide offset is kept.
    /// (ACE slides and then restores, losing the offset.)</remarks>
    // retail: CTransition::edge_slide (acclient.c:312684)
    public bool EdgeSlide(ref TransitionState ts, float stepDownHeight, float zVal)
    {
        SpherePath path = SpherePath;
        CollisionInfo ci = CollisionInfo;
        ObjectInfoState state = ObjectInfo.State;
        if ((state & ObjectInfoState.OnWalkable) == 0 || (state & ObjectInfoState.EdgeSlide) == 0)
        {
            path.Walkable = null;
            path.RestoreCheckPos();
            ci.ContactPlaneValid = false;
            ci.ContactPlaneIsWater = false;
            path.CellArrayValid = true;
            ts = TransitionState.Ok;
            return true;
        }

        if (ci.ContactPlaneValid && ci.ContactPlane.N.Z < (double)zVal)
        {
            path.Walkable = null;
            path.RestoreCheckPos();
            ts = CliffSlide(ci.ContactPlane);
            ci.ContactPlaneValid = false;
            ci.ContactPlaneIsWater = false;
            return false;
        }

        if (path.Walkable is not null)
        {
            path.RestoreCheckPos();
            ci.ContactPlaneValid = false;
            ci.ContactPlaneIsWater = false;
            ts = path.PrecipiceSlide(ci);
            return ts == TransitionState.Collided;
        }

        if (ci.ContactPlaneValid)
        {
            path.Walkable = null;
            path.RestoreCheckPos();
            path.CellArrayValid = true;
            ci.ContactPlaneValid = false;
            ci.ContactPlaneIsWater = false;
            ts = TransitionState.Ok;
            return true;
        }

        // No contact at all: probe down from the current position to find the walkable polygon whose edge was crossed.
        Vector3 curr = path.GlobalCurrCenter[0];
        Vector3 check = path.GlobalSphere[0].Center;
        var back = new Vector3((float)((double)curr.X - check.X), (float)((double)curr.Y - check.Y), (float)((double)curr.Z - check.Z));
        path.AddOffsetToCheckPos(back);
        StepDown(stepDownHeight, zVal);
        ci.ContactPlaneValid = false;
        ci.ContactPlaneIsWater = false;
        path.RestoreCheckPos();
        if (path.Walkable is not null)
        {
            ci.ContactPlaneValid = false;
            ci.ContactPlaneIsWater = false;
            path.CacheLocalSpaceSphere(path.WalkablePos, path.WalkableScale);
            path.SetWalkableCheckPos(path.LocalSpaceSphere[0]);
            ts = path.PrecipiceSlide(ci);
            return ts == TransitionState.Collided;
        }

        path.Walkable = null;
        ts = TransitionState.Collided;
        path.CellArrayValid = true;
        return true;
    }

    /// <summary>
    /// Slides the check position along the crease between a too-steep contact plane and the last known (walkable) one:
    /// the movement is taken off along the horizontal normal of the crease.
    /// </summary>
    /// <returns><see cref="TransitionState.Adjusted"/>, or <see cref="TransitionState.Ok"/> when the planes are parallel.</returns>
    // retail: CTransition::cliff_slide (acclient.c:312004)
    public TransitionState CliffSlide(in CollisionPlane contactPlane)
    {
        SpherePath path = SpherePath;
        CollisionInfo ci = CollisionInfo;
        Vector3 c = contactPlane.N;
        Vector3 lk = ci.LastKnownContactPlane.N;
        double cx = (double)c.Y * lk.Z - (double)c.Z * lk.Y;
        double cy = (double)lk.X * c.Z - (double)lk.Z * c.X;
        double cz0 = ((double)c.X * lk.Y - (double)c.Y * lk.X) * 0.0;
        var normal = new Vector3((float)(cz0 - cy), (float)(cx - cz0), (float)(cy * 0.0 - cx * 0.0));
        if (VectorMath.NormalizeCheckSmall(ref normal))
        {
            return TransitionState.Ok;
        }

        Vector3 blockOffset = LandDefs.GetBlockOffset(path.CurrPos.ObjCellId, path.CheckPos.ObjCellId);
        Vector3 g = path.GlobalSphere[0].Center;
        Vector3 curr = path.GlobalCurrCenter[0];
        double mx = (double)g.X - curr.X;
        double my = (double)g.Y - curr.Y;
        float mz = (float)((double)g.Z - curr.Z);
        float mxf = (float)(blockOffset.X + mx);
        double along = ((double)blockOffset.Z + mz) * normal.Z + ((double)blockOffset.Y + my) * normal.Y + (double)mxf * normal.X;
        if (along <= 0.0)
        {
            var offset = new Vector3((float)(normal.X * along), (float)(normal.Y * along), (float)(normal.Z * along));
            path.AddOffsetToCheckPos(offset);
            ci.SetCollisionNormal(normal);
        }
        else
        {
            double away = -along;
            var offset = new Vector3((float)(normal.X * away), (float)(normal.Y * away), (float)(normal.Z * away));
            path.AddOffsetToCheckPos(offset);
            ci.SetCollisionNormal(new Vector3(-normal.X, -normal.Y, -normal.Z));
        }

        return TransitionState.Adjusted;
    }
}
