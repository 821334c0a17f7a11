using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Sweep;

namespace AcDream.Core.Physics.Objects;

// The object's collision response after a retail sweep: the bounce, the stationary bits and the collision reports to
// the listeners of the RetailSweep.
public sealed partial class PhysicsObj
{
    private const TransientState StationaryBits =
        TransientState.StationaryFall | TransientState.StationaryStop | TransientState.StationaryStuck;

    /// <summary>
    /// The collision response of a committed sweep: reports a new environment collision (or a landing), bounces the
    /// velocity off the collision normal by the elasticity (an inelastic object stops; an object that walked on stays
    /// unbounced unless sledding), stops an object stuck falling, and records the stationary bits.
    /// </summary>
    /// <returns>True when a collision was reported.</returns>
    // retail: CPhysicsObj::handle_all_collisions (acclient.c:321807)
    internal bool HandleAllCollisions(RetailSweep sweep, CollisionInfo collisions, bool prevContact, bool prevOnWalkable)
    {
        ArgumentNullException.ThrowIfNull(collisions);
        bool onWalkable = (_transientState & TransientState.OnWalkable) != 0;
        bool applyBounce = !prevOnWalkable || !onWalkable || (_state & PhysicsState.Sledding) != 0;
        bool reported = false;

        if (HandleObjectCollisions(sweep, collisions, prevContact))
        {
            reported = true;
        }

        if (CollidingWithEnvironment)
        {
            CollidingWithEnvironment = collisions.CollidedWithEnvironment;
        }
        else if (collisions.CollidedWithEnvironment || (!prevOnWalkable && onWalkable))
        {
            reported = ReportEnvironmentCollision(sweep, prevContact) || reported;
        }

        int fsf = collisions.FramesStationaryFall;
        if (fsf <= 1)
        {
            if (applyBounce && collisions.CollisionNormalValid)
            {
                if ((_state & PhysicsState.Inelastic) != 0)
                {
                    _velocity = Vector3.Zero;
                }
                else
                {
                    Vector3 v = _velocity;
                    Vector3 n = collisions.CollisionNormal;
                    double dot = (double)v.Z * n.Z + (double)v.Y * n.Y + (double)n.X * v.X;
                    if (dot < 0.0)
                    {
                        double k = -(dot * (Elasticity + 1.0));
                        float ky = (float)(k * n.Y);
                        float kz = (float)(k * n.Z);
                        _velocity = new Vector3((float)(k * n.X + v.X), ky + v.Y, kz + v.Z);
                    }
                }
            }
        }
        else
        {
            _velocity = Vector3.Zero;
            if (fsf == 3)
            {
                _transientState &= ~StationaryBits;
                return reported;
            }
        }

        switch (fsf)
        {
            case 0:
                _transientState &= ~StationaryBits;
                break;
            case 1:
                _transientState |= TransientState.StationaryFall;
                break;
            case 2:
                _transientState |= TransientState.StationaryStop;
                break;
            default:
                _transientState |= TransientState.StationaryStuck;
                break;
        }

        return reported;
    }

    /// <summary>Reports the start of an environment collision once; a missile loses MISSILE, ALIGNPATH and PATHCLIPPED.</summary>
    // retail: CPhysicsObj::report_environment_collision (acclient.c:320193)
    private bool ReportEnvironmentCollision(RetailSweep sweep, bool prevContact)
    {
        bool result = false;
        if (CollidingWithEnvironment)
        {
            return false;
        }

        if ((_state & PhysicsState.ReportCollisions) != 0 && sweep.CollisionListener is not null)
        {
            sweep.CollisionListener.OnEnvironmentCollision(this, new EnvCollisionProfile(_velocity, prevContact));
            result = true;
        }

        CollidingWithEnvironment = true;
        if ((_state & PhysicsState.Missile) != 0)
        {
            _state &= ~(PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped);
        }

        return result;
    }

    /// <summary>Ends the touches that are over: records older than <see cref="CollisionRecordLifetime"/>, ethereal ones
    /// once the clock moved on, or all of them with <paramref name="forceEnd"/>.</summary>
    // retail: CPhysicsObj::report_collision_end (acclient.c:321712)
    internal void ReportCollisionEnd(RetailSweep sweep, bool forceEnd)
    {
        double now = World.PhysicsTime;
        int i = 0;
        while (i < NumCollisionRecords)
        {
            CollisionRecord r = CollisionRecords[i];
            double age = now - r.TouchedTime;
            if (age > CollisionRecordLifetime || (r.Ethereal && age > 0.0) || forceEnd)
            {
                RemoveCollisionRecordAt(i);
                ReportObjectCollisionEnd(sweep, r.ObjectId);
            }
            else
            {
                i++;
            }
        }
    }

    // retail: CPhysicsObj::handle_all_collisions (acclient.c:321807), the object part: track each object hit, then end
    // the collisions that are over.
    private bool HandleObjectCollisions(RetailSweep sweep, CollisionInfo collisions, bool prevContact)
    {
        bool reported = false;
        ReadOnlySpan<PhysicsObj?> hits = collisions.CollideObjects;
        for (int i = 0; i < hits.Length; i++)
        {
            PhysicsObj? other = hits[i];
            if (other is not null && TrackObjectCollision(sweep, other, prevContact))
            {
                reported = true;
            }
        }

        ReportCollisionEnd(sweep, false);
        return reported;
    }

    /// <summary>Records a touch of <paramref name="other"/> and reports it when it is new (a static object counts as
    /// the environment).</summary>
    // retail: CPhysicsObj::track_object_collision (acclient.c:321216)
    private bool TrackObjectCollision(RetailSweep sweep, PhysicsObj other, bool prevContact)
    {
        if ((other.State & PhysicsState.Static) != 0)
        {
            return ReportEnvironmentCollision(sweep, prevContact);
        }

        bool existed = ClobberCollisionRecord(other.Id, World.PhysicsTime, (other.State & PhysicsState.Ethereal) != 0);
        return !existed && ReportObjectCollision(sweep, other, prevContact);
    }

    /// <summary>Reports a new touch to both objects (each when it reports collisions and the other does not ignore them);
    /// a missile that hits loses MISSILE, ALIGNPATH and PATHCLIPPED.</summary>
    // retail: CPhysicsObj::report_object_collision (acclient.c:320227)
    private bool ReportObjectCollision(RetailSweep sweep, PhysicsObj other, bool prevContact)
    {
        if ((other.State & PhysicsState.ReportCollisionsAsEnvironment) != 0)
        {
            return ReportEnvironmentCollision(sweep, prevContact);
        }

        bool result = false;
        IObjectCollisionListener? listener = sweep.ObjectCollisionListener;
        bool meMissile = (_state & PhysicsState.Missile) != 0;
        var v = new System.Numerics.Vector3(_velocity.X - other._velocity.X, _velocity.Y - other._velocity.Y,
            _velocity.Z - other._velocity.Z);
        if ((other.State & PhysicsState.IgnoreCollisions) == 0)
        {
            if ((_state & PhysicsState.ReportCollisions) != 0 && listener is not null)
            {
                if (meMissile)
                {
                    int q = DetermineQuadrant(other.Position, other.Height, Position);
                    listener.OnAttackCollision(this, new AtkCollisionProfile(other.Id, -1, q));
                }
                else
                {
                    listener.OnObjectCollision(this, new ObjCollisionProfile(other.Id, v, (other.State & PhysicsState.Missile) != 0,
                        (other.TransientState & TransientState.Contact) != 0, prevContact));
                }

                result = true;
            }

            if (meMissile)
            {
                _state &= ~(PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped);
            }
        }

        if ((other.State & PhysicsState.ReportCollisions) != 0 && (_state & PhysicsState.IgnoreCollisions) == 0 && listener is not null)
        {
            if ((other.State & PhysicsState.Missile) != 0)
            {
                int q = DetermineQuadrant(Position, Height, other.Position);
                listener.OnAttackCollision(other, new AtkCollisionProfile(Id, -1, q));
            }
            else
            {
                listener.OnObjectCollision(other, new ObjCollisionProfile(Id, v, meMissile,
                    prevContact, (other.TransientState & TransientState.Contact) != 0));
            }

            result = true;
        }

        return result;
    }

    // retail: CPhysicsObj::report_object_collision_end (acclient.c:317868)
    private bool ReportObjectCollisionEnd(RetailSweep sweep, uint otherId)
    {
        PhysicsObj? other = World.GetObjectById(otherId);
        if (other is null)
        {
            return false;
        }

        IObjectCollisionListener? listener = sweep.ObjectCollisionListener;
        if ((other.State & PhysicsState.ReportCollisionsAsEnvironment) == 0 && listener is not null)
        {
            if ((State & PhysicsState.ReportCollisions) != 0)
            {
                listener.OnObjectCollisionEnd(this, otherId);
            }

            if ((other.State & PhysicsState.ReportCollisions) != 0)
            {
                listener.OnObjectCollisionEnd(other, Id);
            }
        }

        return true;
    }
}
