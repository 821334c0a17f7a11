// PhysicsObj — collision response: get_object_info, check_contact, handle_all_collisions, report_*_collision, the collision table.
using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects;

// The object's side of the collision sweep: its sweep flags and its collision response.
public sealed partial class PhysicsObj
{
    /// <summary>The object is in an ongoing collision with the environment (reported once until it ends). Retail:
    /// <c>colliding_with_environment</c>.</summary>
    public bool CollidingWithEnvironment { get; internal set; }

    /// <summary>
    /// The object's contact as seen by a sweep: false when it moves away from its contact plane faster than EPSILON.
    /// </summary>
    // retail: CPhysicsObj::check_contact (acclient.c:316535)
    internal bool CheckContact(bool contact)
    {
        if ((_transientState & TransientState.Contact) != 0)
        {
            Vector3 n = ContactPlaneNormal;
            if ((double)_velocity.Z * n.Z + (double)_velocity.Y * n.Y + (double)_velocity.X * n.X > PhysicsGlobals.Epsilon)
            {
                return false;
            }
        }

        return contact;
    }

    /// <summary>
    /// Seeds a transition with the object's contact state (unless <paramref name="adminMove"/>) and returns its sweep flags:
    /// EDGE_SLIDE from <see cref="PhysicsState.EdgeSlide"/>, CONTACT / ON_WALKABLE while in contact and not lifting off,
    /// PATH_CLIPPED for a missile.
    /// </summary>
    /// <remarks>FREE_ROTATE comes from the part array's <c>AllowsFreeHeading</c>, which the core's part array does not model
    /// (always false).</remarks>
    // retail: CPhysicsObj::get_object_info (acclient.c:319073)
    internal ObjectInfoState GetObjectInfo(Transition transition, bool adminMove)
    {
        System.ArgumentNullException.ThrowIfNull(transition);
        ObjectInfoState state = ObjectInfoState.None;
        if ((_state & PhysicsState.EdgeSlide) != 0)
        {
            state = ObjectInfoState.EdgeSlide;
        }

        if (!adminMove)
        {
            if ((_transientState & TransientState.Contact) != 0)
            {
                bool isWater = (_transientState & TransientState.WaterContact) != 0;
                var plane = new CollisionPlane(ContactPlaneNormal, ContactPlaneD);
                if (CheckContact(true))
                {
                    transition.InitContactPlane(ContactPlaneCellId, plane, isWater);
                    state |= ObjectInfoState.Contact;
                    if ((_transientState & TransientState.OnWalkable) != 0)
                    {
                        state |= ObjectInfoState.OnWalkable;
                    }
                }
                else
                {
                    transition.InitLastKnownContactPlane(ContactPlaneCellId, plane, isWater);
                }
            }

            if ((_transientState & TransientState.Sliding) != 0)
            {
                transition.InitSlidingNormal(SlidingNormal);
            }
        }

        if ((_state & PhysicsState.Missile) != 0)
        {
            state |= ObjectInfoState.PathClipped;
        }

        return state;
    }

    // The object's collision response after a retail sweep: the bounce, the stationary bits and the collision reports to
    // the listeners of the RetailSweep.
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

    /// <summary>Every object the collision table still holds is reported as a new touch (the object reports collisions
    /// again).</summary>
    // retail: CPhysicsObj::report_collision_start (acclient.c:321262)
    internal void ReportCollisionStart(RetailSweep sweep)
    {
        bool contact = (_transientState & TransientState.Contact) != 0;
        for (int i = 0; i < NumCollisionRecords; i++)
        {
            PhysicsObj? other = World.GetObjectById(CollisionRecords[i].ObjectId);
            if (other is not null)
            {
                ReportObjectCollision(sweep, other, contact);
            }
        }
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

    // The object's collision table: the objects it is touching, for once-per-contact reports.
    private CollisionRecord[] _collisionTable = Array.Empty<CollisionRecord>();

    /// <summary>How long a touch stays in the collision table without being refreshed, seconds of physics time (an ethereal
    /// object's touch ends as soon as the clock moves on). Retail: the <c>&gt; 1.0</c> test of
    /// <c>report_collision_end</c> (acclient.c:321712).</summary>
    public const double CollisionRecordLifetime = 1.0;

    /// <summary>Number of entries in the collision table.</summary>
    public int NumCollisionRecords { get; private set; }

    /// <summary>The objects this object is touching (or touched within the last second), in insertion order (retail keeps
    /// a hash table, <c>collision_table</c>; its iteration order is not reproduced).</summary>
    public ReadOnlySpan<CollisionRecord> CollisionRecords => _collisionTable.AsSpan(0, NumCollisionRecords);

    /// <summary>Adds or refreshes the record for <paramref name="objectId"/>. Returns true when it already existed.</summary>
    // retail: LongNIValHash<CollisionRecord>::clobber, as called by track_object_collision (acclient.c:321216)
    internal bool ClobberCollisionRecord(uint objectId, double touchedTime, bool ethereal)
    {
        for (int i = 0; i < NumCollisionRecords; i++)
        {
            if (_collisionTable[i].ObjectId == objectId)
            {
                _collisionTable[i].TouchedTime = touchedTime;
                _collisionTable[i].Ethereal = ethereal;
                return true;
            }
        }

        if (NumCollisionRecords == _collisionTable.Length)
        {
            // Retail's table starts with 4 buckets; growth allocates only when more objects touch than ever before (the first
            // touch makes the table, as retail's first track_object_collision does).
            Array.Resize(ref _collisionTable, _collisionTable.Length == 0 ? 4 : _collisionTable.Length * 2);
        }

        _collisionTable[NumCollisionRecords++] = new CollisionRecord { ObjectId = objectId, TouchedTime = touchedTime, Ethereal = ethereal };
        return false;
    }

    /// <summary>Removes the record at <paramref name="index"/>, keeping the order of the others.</summary>
    internal void RemoveCollisionRecordAt(int index)
    {
        NumCollisionRecords--;
        Array.Copy(_collisionTable, index + 1, _collisionTable, index, NumCollisionRecords - index);
    }

    /// <summary>
    /// Where <paramref name="p"/> lies around this object of height <paramref name="height"/>: bit 0x10 in front (local
    /// x &gt;= 0) else 0x8; 0x20 right (y &gt;= 0) else 0x40; 0x1 high (z &gt;= 2/3 h), 0x2 middle, 0x4 low (z &lt; h/3).
    /// </summary>
    // retail: Position::determine_quadrant (acclient.c:467065)
    public static int DetermineQuadrant(in Position self, float height, in Position p)
    {
        Vector3 hit = self.LocalToLocal(p, Vector3.Zero);
        int q = hit.X >= 0.0 ? 16 : 8;
        q |= hit.Y >= 0.0 ? 0x20 : 0x40;
        if (height * 0.333333333 <= hit.Z)
        {
            return q | (height * 0.66666667 <= hit.Z ? 1 : 2);
        }

        return q | 4;
    }
}
