using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision;

internal sealed partial class Transition
{
    /// <summary>
    /// Lowers the check position by <paramref name="stepDownHeight"/> (unless a step up already placed it) and inserts it;
    /// succeeds when it lands on a contact plane at least as flat as <paramref name="zVal"/> (and, for an edge-sliding
    /// walker, on walkable ground) and the landing position is confirmed.
    /// </summary>
    // retail: CTransition::step_down (acclient.c:312628)
    public bool StepDown(float stepDownHeight, float zVal)
    {
        SpherePath path = SpherePath;
        CollisionInfo ci = CollisionInfo;
        path.NegPolyHit = false;
        path.StepDown = true;
        path.StepDownAmt = stepDownHeight;
        path.WalkInterp = 1f;
        if (!path.StepUp)
        {
            path.CellArrayValid = false;
            float dz = -stepDownHeight;
            Vector3 o = path.CheckPos.Frame.Origin;
            path.CheckPos.Frame.Origin = new Vector3(o.X, o.Y, dz + o.Z);
            path.CacheGlobalSphere(new Vector3(0f, 0f, dz));
        }

        TransitionState ts = TransitionalInsert(5);
        path.StepDown = false;
        if (ts == TransitionState.Ok
            && ci.ContactPlaneValid
            && ci.ContactPlane.N.Z >= (double)zVal
            && ((ObjectInfo.State & ObjectInfoState.EdgeSlide) == 0 || path.StepUp || CheckWalkable(zVal)))
        {
            path.Backup = path.InsertType;
            path.InsertType = InsertType.Placement;
            TransitionState confirm = TransitionalInsert(1);
            path.InsertType = path.Backup;
            return confirm == TransitionState.Ok;
        }

        return false;
    }

    /// <summary>
    /// Tries to climb onto what the sphere hit: a step down from the raised position a BSP computed, by the step-up height
    /// on walkable ground (0.04 m otherwise); on failure the check position is restored.
    /// </summary>
    // retail: CTransition::step_up (acclient.c:312793)
    public bool StepUp(Vector3 collisionNormal)
    {
        SpherePath path = SpherePath;
        CollisionInfo.ContactPlaneValid = false;
        CollisionInfo.ContactPlaneIsWater = false;
        path.StepUp = true;
        path.StepUpNormal = collisionNormal;
        float stepDownHeight = NotWalkingStepHeight;
        float zVal = PhysicsGlobals.LandingZ;
        if ((ObjectInfo.State & ObjectInfoState.OnWalkable) != 0)
        {
            zVal = ObjectInfo.GetWalkableZ();
            stepDownHeight = ObjectInfo.StepUpHeight;
        }

        path.WalkableAllowance = zVal;
        path.SaveCheckPos();
        bool ok = StepDown(stepDownHeight, zVal);
        path.StepUp = false;
        path.Walkable = null;
        if (ok)
        {
            return true;
        }

        path.RestoreCheckPos();
        return false;
    }

    /// <summary>
    /// For a walker: probes below the check position (by the step-down height, halved for a small sphere) and reports
    /// whether there is ground to stand on there. Always true when not on walkable ground or when the walkable polygon
    /// still holds the sphere. The check position is restored.
    /// </summary>
    // retail: CTransition::check_walkable (acclient.c:312474)
    public bool CheckWalkable(float zCheck)
    {
        SpherePath path = SpherePath;
        if ((ObjectInfo.State & ObjectInfoState.OnWalkable) == 0 || path.CheckWalkables())
        {
            return true;
        }

        Position backup = path.CheckPos;
        ObjCell? backupCell = path.CheckCell;
        float height = ObjectInfo.StepDownHeight;
        path.WalkableAllowance = zCheck;
        path.CheckWalkable = true;
        float radius = path.GlobalSphere[0].Radius;
        if (path.NumSphere < 2 && height > (double)radius + radius)
        {
            height = (float)(radius * 0.5);
        }

        radius = path.GlobalSphere[0].Radius;
        if (height > (double)radius + radius)
        {
            height = (float)(height * 0.5);
        }

        path.AddOffsetToCheckPos(new Vector3(0f, 0f, -height));
        TransitionState ts = TransitionalInsert(1);
        path.CheckWalkable = false;
        path.SetCheckPos(backup, backupCell);
        return ts != TransitionState.Ok;
    }
}
