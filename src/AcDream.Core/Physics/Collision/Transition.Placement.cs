using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision;

internal sealed partial class Transition
{
    /// <summary>
    /// Places the object at <see cref="SpherePath.CurrPos"/>: an initial test (objects ignored), then the placement search
    /// (<see cref="FindPlacementPos"/>), then, for an object that follows the ground, a step down onto it.
    /// </summary>
    // retail: CTransition::find_placement_position (acclient.c:313340)
    public bool FindPlacementPosition()
    {
        SpherePath path = SpherePath;
        path.CheckPos = path.CurrPos;
        path.CheckCell = path.CurrCell;
        path.CellArrayValid = false;
        path.CacheGlobalSphere();
        path.InsertType = InsertType.InitialPlacement;
        TransitionState ts;
        if (path.CheckCell is not null)
        {
            ts = InsertIntoCell(path.CheckCell, 3);
            if (ts == TransitionState.Ok)
            {
                ts = CheckOtherCells(path.CheckCell);
            }
        }
        else
        {
            ts = TransitionState.Collided;
        }

        if (ValidatePlacement(ts, true) != TransitionState.Ok)
        {
            return false;
        }

        path.InsertType = InsertType.Placement;
        if (!FindPlacementPos())
        {
            return false;
        }

        if (ObjectInfo.StepDown)
        {
            float stepDownHeight = ObjectInfo.StepDownHeight;
            path.WalkableAllowance = PhysicsGlobals.LandingZ;
            path.SaveCheckPos();
            path.Backup = path.InsertType;
            path.InsertType = InsertType.Transition;
            float radius = path.GlobalSphere[0].Radius;
            if (path.NumSphere < 2 && (double)radius + radius < stepDownHeight)
            {
                stepDownHeight = (float)(radius * 0.5);
            }

            bool landed;
            if ((double)path.GlobalSphere[0].Radius + path.GlobalSphere[0].Radius >= stepDownHeight)
            {
                landed = StepDown(stepDownHeight, PhysicsGlobals.LandingZ);
            }
            else
            {
                float half = (float)(stepDownHeight * 0.5);
                landed = StepDown(half, PhysicsGlobals.LandingZ) || StepDown(half, PhysicsGlobals.LandingZ);
            }

            if (!landed)
            {
                path.RestoreCheckPos();
                CollisionInfo.ContactPlaneValid = false;
                CollisionInfo.ContactPlaneIsWater = false;
            }

            path.InsertType = path.Backup;
            path.Walkable = null;
        }

        return ValidatePlacement(TransitionState.Ok, true) == TransitionState.Ok;
    }

    /// <summary>
    /// Tests the placement at the current position; when it does not fit and sliding is allowed, searches outward on
    /// rings: <c>n = ceil(4 / r)</c> rings (r clamped to at least 0.48 m; half as many, 2 m out, for spheres under
    /// 0.125 m), ring k at distance <c>k * 4/n</c> with <c>2 * ceil(k * (4/n) / r * 3.1416)</c> headings evenly spaced
    /// clockwise from north. The first position that fits becomes current.
    /// </summary>
    // retail: CTransition::find_placement_pos (acclient.c:313014)
    public bool FindPlacementPos()
    {
        SpherePath path = SpherePath;
        CollisionInfo ci = CollisionInfo;
        path.CheckPos = path.CurrPos;
        path.CheckCell = path.CurrCell;
        path.CellArrayValid = false;
        path.CacheGlobalSphere();
        ci.SlidingNormalValid = false;
        ci.ContactPlaneValid = false;
        ci.ContactPlaneIsWater = false;
        if (ValidatePlacementTransition(TransitionalInsert(3)) == TransitionState.Ok)
        {
            return true;
        }

        if (!path.PlacementAllowsSliding)
        {
            return false;
        }

        float radius = path.LocalSphere[0].Radius;
        bool small = false;
        float adjustRad = PlacementSearchDistance;
        if (radius >= PlacementSmallRadius)
        {
            if (radius < PlacementMinRadius)
            {
                radius = PlacementMinRadius;
            }
        }
        else
        {
            small = true;
            adjustRad = PlacementSmallSearchDistance;
        }

        double steps = PlacementSearchDistance / (1.0 * radius);
        if (small)
        {
            steps *= 0.5;
        }

        if (steps <= 1.0)
        {
            return false;
        }

        double ceilSteps = Math.Ceiling(steps);
        float distPerStep = (float)(adjustRad / ceilSteps);
        uint numSteps = unchecked((uint)(ulong)ceilSteps);
        float distance = 0f;
        float adjust = 0f;
        float radialPerStep = (float)((double)distPerStep / radius * PlacementPi);
        for (uint i = 0; i < numSteps; i++)
        {
            distance += distPerStep;
            double radial = (double)radialPerStep + adjust;
            adjust = (float)radial;
            uint numRad = 2u * unchecked((uint)(ulong)Math.Ceiling(radial));
            Frame heading = Frame.Identity;
            float angleOffset = (float)(360.0 / numRad);
            for (uint j = 0; j < numRad; j++)
            {
                path.CheckPos = path.CurrPos;
                path.CheckCell = path.CurrCell;
                path.CellArrayValid = false;
                path.CacheGlobalSphere();
                heading.SetHeading((float)((double)j * angleOffset));
                Vector3 dir = heading.GetVectorHeading();
                var offset = new Vector3(distance * dir.X, distance * dir.Y, distance * dir.Z);
                path.GlobalOffset = AdjustOffset(offset);
                if (IsNegligibleOffset(path.GlobalOffset))
                {
                    continue;
                }

                path.CellArrayValid = false;
                Vector3 o = path.CheckPos.Frame.Origin;
                Vector3 g = path.GlobalOffset;
                path.CheckPos.Frame.Origin = new Vector3(o.X + g.X, g.Y + o.Y, g.Z + o.Z);
                path.CacheGlobalSphere(g);
                ci.SlidingNormalValid = false;
                ci.ContactPlaneValid = false;
                ci.ContactPlaneIsWater = false;
                if (ValidatePlacementTransition(TransitionalInsert(3)) == TransitionState.Ok)
                {
                    return true;
                }
            }
        }

        return false;
    }

    /// <summary>
    /// Validates one placement test: OK makes the check position current; a blocked test that may slide clears the
    /// collision record.
    /// </summary>
    // retail: CTransition::validate_placement_transition (acclient.c:312354)
    public TransitionState ValidatePlacementTransition(TransitionState ts)
    {
        SpherePath path = SpherePath;
        if (path.CheckCell is null)
        {
            return TransitionState.Collided;
        }

        if (ts == TransitionState.Ok)
        {
            path.CurrPos = path.CheckPos;
            path.CurrCell = path.CheckCell;
            path.CacheGlobalCurrCenter();
        }
        else if (ts > TransitionState.Ok && ts <= TransitionState.Slid && path.PlacementAllowsSliding)
        {
            CollisionInfo.Init();
        }

        return ts;
    }

    /// <summary>
    /// Validates a placement: OK makes the check position current; with <paramref name="adjust"/>, an Adjusted or Slid
    /// result is re-inserted once.
    /// </summary>
    // retail: CTransition::validate_placement (acclient.c:312600)
    public TransitionState ValidatePlacement(TransitionState ts, bool adjust)
    {
        SpherePath path = SpherePath;
        if (path.CheckCell is null)
        {
            return TransitionState.Collided;
        }

        if (ts == TransitionState.Ok)
        {
            path.CurrPos = path.CheckPos;
            path.CurrCell = path.CheckCell;
            path.CacheGlobalCurrCenter();
        }
        else if (ts > TransitionState.Collided && ts <= TransitionState.Slid && adjust)
        {
            return ValidatePlacement(PlacementInsert(), false);
        }

        return ts;
    }

    /// <summary>Inserts the check position into its cell (3 attempts) and then the other cells.</summary>
    // retail: CTransition::placement_insert (acclient.c:312578)
    public TransitionState PlacementInsert()
    {
        ObjCell? cell = SpherePath.CheckCell;
        if (cell is null)
        {
            return TransitionState.Collided;
        }

        TransitionState ts = InsertIntoCell(cell, 3);
        if (ts == TransitionState.Ok)
        {
            ts = CheckOtherCells(SpherePath.CheckCell);
        }

        return ts;
    }
}
