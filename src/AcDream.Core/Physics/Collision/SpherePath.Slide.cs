using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision;

internal sealed partial class SpherePath
{
    /// <summary>
    /// True when the sphere, halved, still stands on the walkable polygon (or when there is none, as on terrain).
    /// </summary>
    /// <remarks>Retail quirk kept: the radius of <see cref="WalkableCheckPos"/> is halved in place on every call.</remarks>
    // retail: SPHEREPATH::check_walkables (acclient.c:313467)
    public bool CheckWalkables()
    {
        if (Walkable is null)
        {
            return true;
        }

        WalkableCheckPos.Radius = (float)(WalkableCheckPos.Radius * 0.5);
        return Walkable.CheckWalkable(WalkableCheckPos, WalkableUp);
    }

    /// <summary>
    /// Slides the sphere along the edge of the walkable polygon it is about to leave (a precipice): the crossed edge's
    /// normal, lifted to landblock space and turned to oppose the movement, is handed to <see cref="Sphere.SlideSphere"/>.
    /// </summary>
    /// <returns>The slide's state, or <see cref="TransitionState.Collided"/> when no edge is crossed.</returns>
    // retail: SPHEREPATH::precipice_slide (acclient.c:313979)
    public TransitionState PrecipiceSlide(CollisionInfo collisions)
    {
        if (Walkable is null || !Walkable.FindCrossedEdge(WalkableCheckPos, WalkableUp, out Vector3 normal))
        {
            Walkable = null;
            return TransitionState.Collided;
        }

        Walkable = null;
        StepUp = false;
        ref readonly Frame f = ref WalkablePos.Frame;
        float gx = (float)((double)normal.Z * f.M31 + (double)normal.X * f.M11 + (double)normal.Y * f.M21);
        float gy = (float)((double)normal.Z * f.M32 + (double)normal.X * f.M12 + (double)normal.Y * f.M22);
        float gz = (float)((double)normal.Z * f.M33 + (double)normal.X * f.M13 + (double)normal.Y * f.M23);
        var n = new Vector3(gx, gy, gz);

        Vector3 blockOffset = LandDefs.GetBlockOffset(CurrPos.ObjCellId, CheckPos.ObjCellId);
        Sphere s = GlobalSphere[0];
        Vector3 curr = GlobalCurrCenter[0];
        double mx = (double)s.Center.X - curr.X;
        double my = (double)s.Center.Y - curr.Y;
        float mz = s.Center.Z - curr.Z;
        float mxf = (float)(blockOffset.X + mx);
        if ((double)gz * ((double)blockOffset.Z + mz) + ((double)blockOffset.Y + my) * gy + (double)mxf * gx > 0.0)
        {
            n = new Vector3((float)(gx * -1.0), (float)(gy * -1.0), (float)(gz * -1.0));
        }

        return s.SlideSphere(this, collisions, ref n, curr);
    }

    /// <summary>A failed step up becomes a slide along the surface that blocked it.</summary>
    // retail: SPHEREPATH::step_up_slide (acclient.c:313455)
    public TransitionState StepUpSlide(CollisionInfo collisions)
    {
        collisions.ContactPlaneValid = false;
        collisions.ContactPlaneIsWater = false;
        StepUp = false;
        return GlobalSphere[0].SlideSphere(this, collisions, ref StepUpNormal, GlobalCurrCenter[0]);
    }
}
