using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision;

internal sealed partial class Transition
{
    /// <summary>
    /// Splits the move into steps no longer than the first sphere's radius: <c>ceil(|offset| / radius)</c> steps of equal
    /// length (one step when the move is shorter than a radius, none when it is zero). The viewer (camera) takes
    /// <c>floor(|offset| / radius) + 1</c> radius-long steps instead. There is no cap on the count (ACE caps at 1000).
    /// </summary>
    /// <param name="offset">The whole movement, begin to end, in the begin position's landblock.</param>
    /// <param name="offsetPerStep">The movement of one step.</param>
    /// <param name="numSteps">The number of steps.</param>
    // retail: CTransition::calc_num_steps (acclient.c:311763)
    public void CalcNumSteps(out Vector3 offset, out Vector3 offsetPerStep, out uint numSteps)
    {
        SpherePath path = SpherePath;
        if (!path.HasBeginPos)
        {
            offset = Vector3.Zero;
            offsetPerStep = Vector3.Zero;
            numSteps = 1;
            return;
        }

        offset = path.BeginPos.GetOffset(path.EndPos);
        double radius = path.LocalSphere[0].Radius;
        double dist = VectorMath.Magnitude(offset);
        if ((ObjectInfo.State & ObjectInfoState.IsViewer) != 0)
        {
            if (dist <= PhysicsGlobals.Epsilon)
            {
                offsetPerStep = Vector3.Zero;
                numSteps = 0;
            }
            else
            {
                double steps = dist / radius;
                double inv = 1.0 / steps;
                offsetPerStep = new Vector3((float)(inv * offset.X), (float)(inv * offset.Y), (float)(inv * offset.Z));
                numSteps = unchecked((uint)(ulong)Math.Floor(steps)) + 1;
            }

            return;
        }

        // non-retail: fidelity switch PhysicsProfile.SweepStepScale (retail divides by 1.0 * radius; the default scale is 1)
        double s = dist / (StepScale() * radius);
        if (s > 1.0)
        {
            double n = Math.Ceiling(s);
            double inv = 1.0 / n;
            offsetPerStep = new Vector3((float)(inv * offset.X), (float)(inv * offset.Y), (float)(inv * offset.Z));
            numSteps = unchecked((uint)(ulong)n);
        }
        else if (offset.X != 0f || offset.Y != 0f || offset.Z != 0f)
        {
            offsetPerStep = offset;
            numSteps = 1;
        }
        else
        {
            offsetPerStep = Vector3.Zero;
            numSteps = 0;
        }
    }

    // The world's PhysicsProfile.SweepStepScale (retail 1.0); 1.0 when the sweep has no object.
    private double StepScale() => ObjectInfo.Object is { } o ? o.World.Profile.SweepStepScale : 1.0;

    /// <summary>
    /// Adjusts one step's movement to the surfaces the object touches: against a sliding normal the movement is kept only
    /// along the wall (and along the crease with the contact plane); on a contact plane a downhill or level move is
    /// projected onto the plane and an uphill move is snapped onto it along z; a sphere found sunk into the contact plane
    /// is lifted out (the check position is moved, the returned offset is not).
    /// </summary>
    /// <param name="offset">The step's movement.</param>
    /// <returns>The adjusted movement.</returns>
    // retail: CTransition::adjust_offset (acclient.c:311863)
    public Vector3 AdjustOffset(Vector3 offset)
    {
        CollisionInfo ci = CollisionInfo;
        Vector3 result = offset;
        bool sliding = false;
        if (ci.SlidingNormalValid)
        {
            Vector3 s = ci.SlidingNormal;
            if ((double)result.Z * s.Z + (double)result.Y * s.Y + (double)result.X * s.X < 0.0)
            {
                sliding = true;
            }
            else
            {
                ci.SlidingNormalValid = false;
            }
        }

        if (ci.ContactPlaneValid)
        {
            Vector3 n = ci.ContactPlane.N;
            float along = (float)((double)result.Z * n.Z + (double)result.Y * n.Y + (double)result.X * n.X);
            if (sliding)
            {
                Vector3 s = ci.SlidingNormal;
                var crease = new Vector3(
                    (float)((double)s.Z * n.Y - (double)s.Y * n.Z),
                    (float)((double)s.X * n.Z - (double)s.Z * n.X),
                    (float)((double)s.Y * n.X - (double)s.X * n.Y));
                if (VectorMath.NormalizeCheckSmall(ref crease))
                {
                    result = Vector3.Zero;
                }
                else
                {
                    double d = (double)crease.Z * result.Z + (double)crease.Y * result.Y + (double)crease.X * result.X;
                    result = new Vector3((float)(crease.X * d), (float)(crease.Y * d), (float)(crease.Z * d));
                }
            }
            else if (along <= 0.0f)
            {
                double nx = (double)along * n.X;
                double ny = (double)along * n.Y;
                float nz = along * n.Z;
                result = new Vector3((float)(result.X - nx), (float)(result.Y - ny), result.Z - nz);
            }
            else
            {
                SnapToPlane(ci.ContactPlane, ref result);
            }

            if (!ci.ContactPlaneIsWater && ci.ContactPlaneCellId != 0)
            {
                Vector3 blockOffset = LandDefs.GetBlockOffset(SpherePath.CheckPos.ObjCellId, ci.ContactPlaneCellId);
                Sphere g = SpherePath.GlobalSphere[0];
                double dist = ((double)g.Center.Z - blockOffset.Z) * n.Z
                              + ((double)g.Center.Y - blockOffset.Y) * n.Y
                              + ((double)g.Center.X - blockOffset.X) * n.X
                              + ci.ContactPlane.D;
                if (dist < (double)g.Radius - PhysicsGlobals.Epsilon)
                {
                    double lift = (g.Radius - dist) / n.Z;
                    if (g.Radius > Math.Abs(lift))
                    {
                        SpherePath.AddOffsetToCheckPos(new Vector3(0f, 0f, (float)lift));
                    }
                }
            }
        }
        else if (sliding)
        {
            Vector3 s = ci.SlidingNormal;
            double d = (double)result.X * s.X + (double)result.Z * s.Z + (double)result.Y * s.Y;
            double sx = d * s.X;
            float sy = (float)(d * s.Y);
            float sz = (float)(d * s.Z);
            result = new Vector3((float)(result.X - sx), result.Y - sy, result.Z - sz);
        }

        return result;
    }

    /// <summary>Moves <paramref name="offset"/> onto the plane along z (skipped for a near-vertical plane).</summary>
    // retail: Plane::snap_to_plane (acclient.c:311526)
    internal static void SnapToPlane(in CollisionPlane plane, ref Vector3 offset)
    {
        Vector3 n = plane.N;
        if (Math.Abs(n.Z) > PhysicsGlobals.Epsilon)
        {
            offset.Z = 0f;
            double invZ = 1.0 / n.Z;
            offset.Z = (float)(-((double)offset.Y * n.Y + (double)offset.X * n.X + n.Z * 0.0 + plane.D) * invZ - invZ * -(double)plane.D);
        }
    }

    /// <summary>
    /// The sweep: steps the spheres from the begin to the end position, inserting and validating each step, and stops at
    /// the first step that cannot move (a stationary fall, a clipped missile, or an adjusted movement too small to count).
    /// Returns true when the last step ended OK; <see cref="SpherePath.CurrPos"/> holds the last valid position.
    /// </summary>
    // retail: CTransition::find_transitional_position (acclient.c:313170)
    public bool FindTransitionalPosition()
    {
        SpherePath path = SpherePath;
        if (path.BeginCell is null)
        {
            return false;
        }

        TransitionState ts = TransitionState.Ok;
        CalcNumSteps(out Vector3 offset, out Vector3 offsetPerStep, out uint numSteps);
        bool freeRotate = (ObjectInfo.State & ObjectInfoState.FreeRotate) != 0;
        if (freeRotate)
        {
            Frame end = path.EndPos.Frame;
            path.CurrPos.Frame.SetRotate(end.Qw, end.Qx, end.Qy, end.Qz);
        }

        path.CheckPos = path.CurrPos;
        path.CheckCell = path.CurrCell;
        path.CellArrayValid = false;
        if (freeRotate)
        {
            path.CacheGlobalSphere();
        }
        else
        {
            // The current centres were cached from this frame by init_path.
            path.CacheGlobalSphereFromCurrCenter(path.CurrPos.Frame);
        }

        if (numSteps == 0)
        {
            if (!freeRotate)
            {
                Frame end = path.EndPos.Frame;
                path.CurrPos.Frame.SetRotate(end.Qw, end.Qx, end.Qy, end.Qz);
            }

            path.SetCheckPos(path.CurrPos, path.CurrCell);
            path.CellArrayValid = true;
            path.HitsInteriorCell = false;
            CellList.FindCellList(Cells, CellArray, path, false);
            return true;
        }

        bool viewer = (ObjectInfo.State & ObjectInfoState.IsViewer) != 0;
        for (uint step = 0; step < numSteps; step++)
        {
            if (viewer && step == numSteps - 1)
            {
                double dist = Math.Sqrt((double)offset.Z * offset.Z + (double)offset.Y * offset.Y + (double)offset.X * offset.X);
                if (dist > PhysicsGlobals.Epsilon)
                {
                    double k = (dist - path.LocalSphere[0].Radius * (double)(numSteps - 1)) / dist;
                    offsetPerStep = new Vector3((float)(offset.X * k), (float)(offset.Y * k), (float)(offset.Z * k));
                }
            }

            path.GlobalOffset = AdjustOffset(offsetPerStep);
            if (!viewer && IsNegligibleOffset(path.GlobalOffset))
            {
                return step != 0 && ts == TransitionState.Ok;
            }

            if (!freeRotate)
            {
                float t = (float)((double)(step + 1) / numSteps);
                path.CheckPos.Frame.InterpolateRotation(path.BeginPos.Frame, path.EndPos.Frame, t);
            }

            CollisionInfo.SlidingNormalValid = false;
            CollisionInfo.ContactPlaneValid = false;
            CollisionInfo.ContactPlaneIsWater = false;
            if (path.InsertType != InsertType.Transition)
            {
                ts = ValidatePlacementTransition(TransitionalInsert(3));
                if (ts == TransitionState.Ok)
                {
                    return true;
                }

                if (!path.PlacementAllowsSliding)
                {
                    return false;
                }

                path.AddOffsetToCheckPos(path.GlobalOffset);
            }
            else
            {
                path.CellArrayValid = false;
                Vector3 o = path.CheckPos.Frame.Origin;
                Vector3 g = path.GlobalOffset;
                path.CheckPos.Frame.Origin = new Vector3(g.X + o.X, g.Y + o.Y, g.Z + o.Z);
                path.CacheGlobalSphere(g);
                ts = ValidateTransition(TransitionalInsert(3));
                if (CollisionInfo.FramesStationaryFall != 0)
                {
                    break;
                }
            }

            if (CollisionInfo.CollisionNormalValid && (ObjectInfo.State & ObjectInfoState.PathClipped) != 0)
            {
                break;
            }
        }

        return ts == TransitionState.Ok;
    }

    /// <summary>
    /// True when an adjusted step movement is too small to attempt: <c>|offset|² &lt; EPSILON²</c>.
    /// </summary>
    /// <remarks>Retail ambiguity: the decompiler lost this x87 comparison in <c>find_transitional_position</c> and
    /// <c>find_placement_pos</c> (only the flags test survives). We read it as the squared length against EPSILON squared
    /// (equivalently |offset| &lt; EPSILON). The other candidate, |offset|² &lt; EPSILON (1.4 cm), would make every step
    /// under 1.4 cm fail and freeze slow movers. See docs/divergences.md.</remarks>
    internal static bool IsNegligibleOffset(Vector3 offset) =>
        (double)offset.X * offset.X + (double)offset.Y * offset.Y + (double)offset.Z * offset.Z
        < (double)PhysicsGlobals.Epsilon * PhysicsGlobals.Epsilon;
}
