using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Collision;

internal sealed partial class Transition
{
    /// <summary>
    /// Tests the check position in its cell and the cells around it, up to <paramref name="numInsertionAttempts"/> times
    /// (each test may adjust or slide the check position), and follows the ground down when the object walked off it:
    /// a step down (twice at half height for a small sphere), else an edge slide.
    /// </summary>
    /// <param name="numInsertionAttempts">How many tests to make (3 for a step, 5 for a step down, 1 for a confirmation).</param>
    /// <returns>The final state; <see cref="TransitionState.Invalid"/> when asked for no attempt.</returns>
    // retail: CTransition::transitional_insert (acclient.c:312833)
    public TransitionState TransitionalInsert(int numInsertionAttempts)
    {
        SpherePath path = SpherePath;
        CollisionInfo ci = CollisionInfo;
        if (path.CheckCell is null)
        {
            return TransitionState.Ok;
        }

        TransitionState ts = TransitionState.Invalid;
        for (int attempt = 0; attempt < numInsertionAttempts; attempt++)
        {
            ts = InsertIntoCell(path.CheckCell, numInsertionAttempts);
            switch (ts)
            {
                case TransitionState.Ok:
                    ts = CheckOtherCells(path.CheckCell);
                    if (ts != TransitionState.Ok)
                    {
                        path.NegPolyHit = false;
                    }

                    if (ts == TransitionState.Collided)
                    {
                        return TransitionState.Collided;
                    }

                    break;
                case TransitionState.Slid:
                    ci.ContactPlaneValid = false;
                    ci.ContactPlaneIsWater = false;
                    path.NegPolyHit = false;
                    break;
                case TransitionState.Adjusted:
                    path.NegPolyHit = false;
                    break;
                case TransitionState.Collided:
                    path.NegPolyHit = false;
                    return TransitionState.Collided;
            }

            if (ts != TransitionState.Ok)
            {
                continue;
            }

            if (path.Collide)
            {
                return ResolveCollideRequest(numInsertionAttempts);
            }

            if (path.NegPolyHit && !path.StepDown && !path.StepUp)
            {
                path.NegPolyHit = false;
                if (!path.NegStepUp)
                {
                    ts = path.GlobalSphere[0].SlideSphere(path, ci, ref path.NegCollisionNormal, path.GlobalCurrCenter[0]);
                }
                else if (!StepUp(path.NegCollisionNormal))
                {
                    ts = path.StepUpSlide(ci);
                }

                continue;
            }

            if (ci.ContactPlaneValid)
            {
                return TransitionState.Ok;
            }

            if ((ObjectInfo.State & ObjectInfoState.Contact) == 0 || path.StepDown || path.CheckCell is null || !ObjectInfo.StepDown)
            {
                return TransitionState.Ok;
            }

            // The object was on the ground and this step left it: follow the ground down.
            float stepDownHeight = NotWalkingStepHeight;
            float zVal = PhysicsGlobals.LandingZ;
            if ((ObjectInfo.State & ObjectInfoState.OnWalkable) != 0)
            {
                zVal = ObjectInfo.GetWalkableZ();
                stepDownHeight = ObjectInfo.StepDownHeight;
            }

            path.WalkableAllowance = zVal;
            path.SaveCheckPos();
            float radius = path.GlobalSphere[0].Radius;
            if (path.NumSphere < 2 && (double)radius + radius < stepDownHeight)
            {
                stepDownHeight = (float)(radius * 0.5);
            }

            bool slid;
            if ((double)radius + radius >= stepDownHeight)
            {
                if (StepDown(stepDownHeight, zVal))
                {
                    path.Walkable = null;
                    return TransitionState.Ok;
                }

                slid = EdgeSlide(ref ts, stepDownHeight, zVal);
            }
            else
            {
                float half = (float)(stepDownHeight * 0.5);
                if (StepDown(half, zVal) || StepDown(half, zVal))
                {
                    path.Walkable = null;
                    return TransitionState.Ok;
                }

                slid = EdgeSlide(ref ts, half, zVal);
            }

            if (slid)
            {
                return ts;
            }
        }

        return ts;
    }

    /// <summary>
    /// The collide branch of <see cref="TransitionalInsert"/>: a BSP asked for a step-up check. On walkable ground
    /// the position is confirmed as a placement; otherwise the check position is restored and the step collides.
    /// </summary>
    // retail: CTransition::transitional_insert (acclient.c:312833), sphere_path.collide branch
    private TransitionState ResolveCollideRequest(int numInsertionAttempts)
    {
        SpherePath path = SpherePath;
        CollisionInfo ci = CollisionInfo;
        path.Collide = false;
        TransitionState result = TransitionState.Ok;
        bool failed = true;
        if (ci.ContactPlaneValid && CheckWalkable(PhysicsGlobals.LandingZ))
        {
            path.Backup = path.InsertType;
            path.InsertType = InsertType.Placement;
            result = TransitionalInsert(numInsertionAttempts);
            path.InsertType = path.Backup;
            failed = result != TransitionState.Ok;
            if (failed)
            {
                result = TransitionState.Ok;
            }
        }

        path.Walkable = null;
        if (!failed)
        {
            return result;
        }

        path.RestoreCheckPos();
        ci.ContactPlaneValid = false;
        ci.ContactPlaneIsWater = false;
        if (ci.LastKnownContactPlaneValid)
        {
            ObjectInfo.KillVelocity();
            ci.LastKnownContactPlaneValid = false;
        }
        else
        {
            ci.SetCollisionNormal(path.StepUpNormal);
        }

        return TransitionState.Collided;
    }

    /// <summary>
    /// Asks <paramref name="cell"/> for collisions up to <paramref name="numInsertionAttempts"/> times; stops at OK or
    /// Collided, retries after Adjusted or Slid (a slide drops the contact plane).
    /// </summary>
    // retail: CTransition::insert_into_cell (acclient.c:311631)
    public TransitionState InsertIntoCell(ObjCell? cell, int numInsertionAttempts)
    {
        if (cell is null)
        {
            return TransitionState.Collided;
        }

        TransitionState result = TransitionState.Ok;
        for (int i = 0; i < numInsertionAttempts; i++)
        {
            result = cell.FindCollisions(this);
            switch (result)
            {
                case TransitionState.Ok:
                case TransitionState.Collided:
                    return result;
                case TransitionState.Slid:
                    CollisionInfo.ContactPlaneValid = false;
                    CollisionInfo.ContactPlaneIsWater = false;
                    break;
            }
        }

        return result;
    }

    /// <summary>
    /// Rebuilds the cell array at the check position, tests every other cell in it, then moves the check position into
    /// the cell that contains it (re-homing it into that cell's landblock). Outside every loaded cell the outdoor cell id
    /// is computed from the position; past the world edge (or during a step down) the step collides.
    /// </summary>
    // retail: CTransition::check_other_cells (acclient.c:312380)
    public TransitionState CheckOtherCells(ObjCell? currCell)
    {
        SpherePath path = SpherePath;
        TransitionState result = TransitionState.Ok;
        path.CellArrayValid = true;
        path.HitsInteriorCell = false;
        ObjCell? newCell = CellList.FindCellList(Cells, CellArray, path, true);
        for (int i = 0; i < CellArray.NumCells; i++)
        {
            ObjCell? cell = CellArray.CellAt(i);
            if (cell is null || ReferenceEquals(cell, currCell))
            {
                continue;
            }

            result = cell.FindCollisions(this);
            switch (result)
            {
                case TransitionState.Slid:
                    CollisionInfo.ContactPlaneValid = false;
                    CollisionInfo.ContactPlaneIsWater = false;
                    return result;
                case TransitionState.Collided:
                case TransitionState.Adjusted:
                    return result;
            }
        }

        path.CheckCell = newCell;
        if (newCell is not null)
        {
            path.AdjustCheckPos(newCell.Id);
            return result;
        }

        if (path.StepDown)
        {
            return TransitionState.Collided;
        }

        Position p = path.CheckPos;
        if ((p.ObjCellId & 0xFFFF) < LandDefs.FirstEnvCell)
        {
            LandDefs.AdjustToOutside(ref p.ObjCellId, ref p.Frame.Origin);
        }

        if (p.ObjCellId != 0)
        {
            path.AdjustCheckPos(p.ObjCellId);
            path.CheckPos = p;
            path.CheckCell = null;
            path.CellArrayValid = false;
            path.CacheGlobalSphere();
            path.CellArrayValid = true;
            return result;
        }

        return TransitionState.Collided;
    }

    /// <summary>
    /// Accepts or rejects a step: an OK step becomes the current position; a blocked step returns to the current position
    /// (re-establishing the last known contact plane when the sphere still touches it) and records the collision normal.
    /// Then updates the sliding normal, the stationary-fall counter and the object's contact/walkable state bits.
    /// </summary>
    // retail: CTransition::validate_transition (acclient.c:312193)
    public TransitionState ValidateTransition(TransitionState ts)
    {
        SpherePath path = SpherePath;
        CollisionInfo ci = CollisionInfo;
        bool redo = ts == TransitionState.Ok
                    && (path.CheckPos.ObjCellId != path.CurrPos.ObjCellId || !path.CheckPos.Frame.IsEqual(path.CurrPos.Frame));
        if (ts == TransitionState.Ok)
        {
            path.CurrPos = path.CheckPos;
            path.CurrCell = path.CheckCell;
            path.CacheGlobalCurrCenter(path.CheckPos.Frame);

            // Retail then copies the current position and cell back into the check ones: the same bits, so not redone.
            path.CellArrayValid = false;
            path.CacheGlobalSphereFromCurrCenter(path.CheckPos.Frame);
        }
        else if (ts > TransitionState.Ok && ts <= TransitionState.Slid)
        {
            if (ci.LastKnownContactPlaneValid)
            {
                ObjectInfo.KillVelocity();
                Vector3 c = path.GlobalCurrCenter[0];
                CollisionPlane lk = ci.LastKnownContactPlane;
                double dist = (double)c.Z * lk.N.Z + (double)c.Y * lk.N.Y + (double)c.X * lk.N.X + lk.D;
                if ((double)path.GlobalSphere[0].Radius + PhysicsGlobals.Epsilon > Math.Abs(dist))
                {
                    ci.SetContactPlane(lk, ci.LastKnownContactPlaneIsWater);
                    ci.ContactPlaneCellId = ci.LastKnownContactPlaneCellId;
                    if ((ObjectInfo.State & ObjectInfoState.OnWalkable) != 0)
                    {
                        redo = true;
                    }
                }
            }

            if (!ci.CollisionNormalValid)
            {
                ci.SetCollisionNormal(new Vector3(0f, 0f, 1f));
            }

            path.SetCheckPos(path.CurrPos, path.CurrCell);
            BuildCellArray(false);
            ts = TransitionState.Ok;
        }

        if (ci.CollisionNormalValid)
        {
            ci.SetSlidingNormal(ci.CollisionNormal);
        }

        PhysicsObj? obj = ObjectInfo.Object;
        if ((ObjectInfo.State & ObjectInfoState.IsViewer) == 0 && obj is not null && (obj.State & PhysicsState.Gravity) != 0)
        {
            if (redo)
            {
                ci.FramesStationaryFall = 0;
            }
            else if (ci.FramesStationaryFall == 0)
            {
                ci.FramesStationaryFall = 1;
            }
            else if (ci.FramesStationaryFall == 1)
            {
                ci.FramesStationaryFall = 2;
            }
            else
            {
                // Third frame without progress: stand the object on a flat plane at its sphere's bottom.
                Sphere g = path.GlobalSphere[0];
                ci.FramesStationaryFall = StationaryFallFrames;
                double xy = (double)g.Center.Y + g.Center.X;
                double z = xy * 0.0 + g.Center.Z;
                var plane = new CollisionPlane(new Vector3(0f, 0f, 1f), (float)(g.Radius - z));
                ci.SetContactPlane(plane, false);
                ci.ContactPlaneCellId = path.CheckPos.ObjCellId;
                if ((ObjectInfo.State & ObjectInfoState.Contact) == 0)
                {
                    ci.SetCollisionNormal(plane.N);
                    ci.CollidedWithEnvironment = true;
                }
            }
        }

        ci.LastKnownContactPlaneValid = ci.ContactPlaneValid;
        if (ci.ContactPlaneValid)
        {
            ci.LastKnownContactPlane = ci.ContactPlane;
            ci.LastKnownContactPlaneCellId = ci.ContactPlaneCellId;
            ci.LastKnownContactPlaneIsWater = ci.ContactPlaneIsWater;
            ObjectInfo.State |= ObjectInfoState.Contact;
            if (ObjectInfo.IsValidWalkable(ci.ContactPlane.N))
            {
                ObjectInfo.State |= ObjectInfoState.OnWalkable;
            }
            else
            {
                ObjectInfo.State &= ~ObjectInfoState.OnWalkable;
            }
        }
        else
        {
            ObjectInfo.State &= ~(ObjectInfoState.Contact | ObjectInfoState.OnWalkable);
        }

        return ts;
    }
}
