using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Leashes an object's own motion after a position report (retail <c>ConstraintManager</c>, acclient.h:31529;
/// PORTAL/cpmanager/CConstraintManager.c). It counts the distance the object's substep offsets carry it; past
/// <see cref="ConstraintDistanceStart"/> the offsets are scaled down linearly, and from <see cref="ConstraintDistanceMax"/>
/// on they are zeroed (while in contact).
/// </summary>
/// <remarks>
/// Retail re-arms it on every position report: for a remote object <c>SmartBox::HandleReceivedPosition</c> (acclient.c:145124)
/// calls <c>ConstrainTo(object, object.m_position, start, max)</c> after <c>MoveOrTeleport</c>, so the count starts at 0 and
/// an object whose updates stop dead-reckons 10 m freely and at most 50 m outdoors (5 / 20 indoors).
/// </remarks>
public sealed class ConstraintManager
{
    /// <summary>Fraction of <see cref="ConstraintDistanceMax"/> beyond which the object is fully constrained. Retail: 0.9
    /// (double, acclient.c:389419).</summary>
    public const double FullyConstrainedFraction = 0.9;

    // retail: ConstraintManager::Create (acclient.c:389432)
    internal ConstraintManager(PhysicsObj physicsObj)
    {
        PhysicsObj = physicsObj;
        ConstraintPos = new Position(0, Frame.Identity);
    }

    /// <summary>The constrained object.</summary>
    public PhysicsObj PhysicsObj { get; }

    /// <summary>True while a constraint is in force (retail <c>is_constrained</c>).</summary>
    public bool IsConstrained { get; private set; }

    /// <summary>Distance counted since <see cref="ConstrainTo"/>, metres (retail <c>constraint_pos_offset</c>, float).</summary>
    public float ConstraintPosOffset { get; private set; }

    /// <summary>The position given to <see cref="ConstrainTo"/> (retail <c>constraint_pos</c>; stored, not read again).</summary>
    public Position ConstraintPos { get; private set; }

    /// <summary>Counted distance at which scaling starts, metres (retail <c>constraint_distance_start</c>).</summary>
    public float ConstraintDistanceStart { get; private set; }

    /// <summary>Counted distance at which offsets are zeroed, metres (retail <c>constraint_distance_max</c>).</summary>
    public float ConstraintDistanceMax { get; private set; }

    /// <summary>
    /// Scales the substep's offset by <c>(max − counted) / (max − start)</c> when the count lies between start and max, zeroes
    /// it from max on (only while the object is in contact), then adds the offset's length to the count.
    /// </summary>
    /// <param name="offset">The substep's offset frame.</param>
    /// <param name="quantum">Substep duration, seconds (unused, as in retail).</param>
    // retail: ConstraintManager::adjust_offset (acclient.c:389477)
    internal void AdjustOffset(ref Frame offset, double quantum)
    {
        if (!IsConstrained)
        {
            return;
        }

        if ((PhysicsObj.TransientState & TransientState.Contact) != 0)
        {
            if (ConstraintPosOffset < (double)ConstraintDistanceMax)
            {
                if (ConstraintPosOffset > (double)ConstraintDistanceStart)
                {
                    float rhs = (float)(((double)ConstraintDistanceMax - ConstraintPosOffset)
                        / ((double)ConstraintDistanceMax - ConstraintDistanceStart));
                    Vector3 o = offset.Origin;
                    offset.Origin = new Vector3(o.X * rhs, o.Y * rhs, o.Z * rhs);
                }
            }
            else
            {
                offset.Origin = Vector3.Zero;
            }
        }

        ConstraintPosOffset = (float)(VectorMath.Magnitude(offset.Origin) + ConstraintPosOffset);
    }

    /// <summary>End-of-substep work: none.</summary>
    /// <remarks>Retail's <c>ConstraintManager::UseTime</c> (symbol at 0x694750) is folded by the linker into a shared empty
    /// function; PositionManager::UseTime still calls it between the interpolation and sticky managers.</remarks>
    internal void UseTime()
    {
    }

    /// <summary>Starts a constraint at <paramref name="p"/>; the count starts at the object's distance from it.</summary>
    /// <param name="p">Constraint position.</param>
    /// <param name="startDistance">Count at which scaling starts, metres.</param>
    /// <param name="maxDistance">Count at which offsets are zeroed, metres.</param>
    /// <exception cref="ArgumentException">Unusable position or non-finite distance; nothing changes.</exception>
    // retail: ConstraintManager::ConstrainTo (acclient.c:389513)
    public void ConstrainTo(in Position p, float startDistance, float maxDistance)
    {
        PhysicsObj.Touch();
        if (!InputLimits.IsPositionInDomain(p))
        {
            throw new ArgumentException("Position must have a finite origin and a valid rotation.", nameof(p));
        }

        if (!float.IsFinite(startDistance) || !float.IsFinite(maxDistance))
        {
            throw new ArgumentException("Constraint distances must be finite.", nameof(startDistance));
        }

        IsConstrained = true;
        ConstraintPos = p;
        ConstraintDistanceStart = startDistance;
        ConstraintDistanceMax = maxDistance;
        ConstraintPosOffset = (float)p.DistanceInDouble(PhysicsObj.Position);
    }

    /// <summary>Stops constraining: lifts the constraint (the count is kept). Retail
    /// <c>ConstraintManager::UnConstrain</c>.</summary>
    // retail: ConstraintManager::UnConstrain (acclient.c:389410)
    public void StopConstraining() => IsConstrained = false;

    /// <summary>True when the count exceeds 90 % of the max distance (checked even when not constrained, as retail).</summary>
    // retail: ConstraintManager::IsFullyConstrained (acclient.c:389416)
    public bool IsFullyConstrained => ConstraintDistanceMax * FullyConstrainedFraction < ConstraintPosOffset;
}
