using System;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Math;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Core.Physics.Collision.Sweep;

/// <summary>The object-collision half of the retail sweep: shadows, overlap checks and the object collision reports.</summary>
public sealed partial class RetailSweep
{
    private readonly CellArray _crossCells = new();

    /// <summary>Receives object collision reports (retail: the objects' weenies). Null reports nothing; the collision
    /// table is kept either way.</summary>
    public IObjectCollisionListener? ObjectCollisionListener { get; set; }

    /// <inheritdoc />
    /// <remarks>An object with a physics BSP is shadowed in its own cell and the cells of its sorting sphere (retail: its
    /// parts' bounding boxes).</remarks>
    // retail: CPhysicsObj::SetPositionInternal(CTransition*) (acclient.c:322503), the shadow update at its end
    public override void UpdateCellShadows(PhysicsObj obj)
    {
        ArgumentNullException.ThrowIfNull(obj);
        if ((obj.State & PhysicsState.HasPhysicsBsp) != 0)
        {
            CalcCrossCells(obj);
        }
        else if (LastTransition is not null && LastTransition.CellArray.NumCells != 0)
        {
            obj.RemoveShadowsFromCells();
            obj.AddShadowsToCells(LastTransition.CellArray, Cells.GetVisible(obj.CellId));
        }
    }

    /// <summary>
    /// Re-shadows <paramref name="obj"/> where it stands: in the cells its cylinder spheres overlap, or, without them (or
    /// with a physics BSP), the cells of its sorting sphere (plus its own cell for a BSP object).
    /// </summary>
    // retail: CPhysicsObj::calc_cross_cells (acclient.c:322446)
    public void CalcCrossCells(PhysicsObj obj)
    {
        ArgumentNullException.ThrowIfNull(obj);
        CellArray ca = _crossCells;
        ca.Clear();
        Position p = obj.Position;
        IPartCollision? parts = obj.PartArray as IPartCollision;
        ReadOnlySpan<CylSphere> cyl = parts is null ? default : parts.CylSpheres;
        Span<Sphere> spheres = stackalloc Sphere[10];
        int n = 0;
        if ((obj.State & PhysicsState.HasPhysicsBsp) == 0 && cyl.Length != 0)
        {
            n = cyl.Length <= 10 ? cyl.Length : 10;
            for (int i = 0; i < n; i++)
            {
                spheres[i] = new Sphere(p.LocalToGlobal(p, cyl[i].LowPt), cyl[i].Radius);
            }
        }
        else
        {
            // Retail: an object with a physics BSP is listed by its parts' bounding boxes (find_bbox_cell_list,
            // acclient.c:318275, via the cells' part tests); the port uses the sorting sphere for it too (divergences.md).
            Sphere sorting = parts is null ? Sphere.Dummy : parts.SortingSphere;
            spheres[0] = new Sphere(p.LocalToGlobal(p, sorting.Center), sorting.Radius);
            n = 1;
        }

        CellList.FindCellList(Cells, p, spheres[..n], ca, false, null);
        if ((obj.State & PhysicsState.HasPhysicsBsp) != 0)
        {
            ca.AddCell(obj.CellId, Cells.GetVisible(obj.CellId));
        }

        obj.RemoveShadowsFromCells();
        obj.AddShadowsToCells(ca, Cells.GetVisible(obj.CellId));
    }

    /// <inheritdoc />
    public override bool EtherealCheckForCollisions(PhysicsObj obj)
    {
        ArgumentNullException.ThrowIfNull(obj);
        return obj.EtherealCheckForCollisions();
    }

    /// <summary>
    /// True when <paramref name="mover"/>, where it stands, overlaps <paramref name="self"/>: a placement test of the
    /// mover's shapes against <paramref name="self"/>'s spheres at rest. False when no transition is free.
    /// </summary>
    // retail: CPhysicsObj::check_collision (acclient.c:320127) -> CTransition::check_collisions (acclient.c:312174)
    internal bool CheckCollision(PhysicsObj self, PhysicsObj mover)
    {
        Transition? t = Pool.Make();
        if (t is null)
        {
            return false;
        }

        try
        {
            t.InitObject(self, self.GetObjectInfo(t, false));
            InitSpheres(t, self);
            Position pos = self.Position;
            t.InitPath(Cells.GetVisible(self.CellId), pos, pos);
            SpherePath path = t.SpherePath;
            path.InsertType = InsertType.Placement;
            path.CheckPos = path.CurrPos;
            path.CheckCell = path.CurrCell;
            path.CellArrayValid = false;
            path.CacheGlobalSphere();
            return mover.FindObjCollisions(t) != TransitionState.Ok;
        }
        finally
        {
            Pool.Cleanup();
        }
    }

    /// <inheritdoc />
    // retail: CPhysicsObj::report_collision_end (acclient.c:321712)
    public override void ReportCollisionEnd(PhysicsObj obj, bool forceEnd)
    {
        ArgumentNullException.ThrowIfNull(obj);
        double now = obj.World.PhysicsTime;
        int i = 0;
        while (i < obj.NumCollisionRecords)
        {
            CollisionRecord r = obj.CollisionRecords[i];
            double age = now - r.TouchedTime;
            if (age > PhysicsObj.CollisionRecordLifetime || (r.Ethereal && age > 0.0) || forceEnd)
            {
                obj.RemoveCollisionRecordAt(i);
                ReportObjectCollisionEnd(obj, r.ObjectId);
            }
            else
            {
                i++;
            }
        }
    }

    // retail: CPhysicsObj::handle_all_collisions (acclient.c:321807), the object part: track each object hit, then end
    // the collisions that are over.
    private bool HandleObjectCollisions(PhysicsObj obj, CollisionInfo collisions, bool prevContact)
    {
        bool reported = false;
        ReadOnlySpan<PhysicsObj?> hits = collisions.CollideObjects;
        for (int i = 0; i < hits.Length; i++)
        {
            PhysicsObj? other = hits[i];
            if (other is not null && TrackObjectCollision(obj, other, prevContact))
            {
                reported = true;
            }
        }

        ReportCollisionEnd(obj, false);
        return reported;
    }

    /// <summary>Records a touch of <paramref name="other"/> and reports it when it is new (a static object counts as
    /// the environment).</summary>
    // retail: CPhysicsObj::track_object_collision (acclient.c:321216)
    private bool TrackObjectCollision(PhysicsObj obj, PhysicsObj other, bool prevContact)
    {
        if ((other.State & PhysicsState.Static) != 0)
        {
            return ReportEnvironmentCollision(obj, prevContact);
        }

        bool existed = obj.ClobberCollisionRecord(other.Id, obj.World.PhysicsTime, (other.State & PhysicsState.Ethereal) != 0);
        return !existed && ReportObjectCollision(obj, other, prevContact);
    }

    /// <summary>Reports a new touch to both objects (each when it reports collisions and the other does not ignore them);
    /// a missile that hits loses MISSILE, ALIGNPATH and PATHCLIPPED.</summary>
    // retail: CPhysicsObj::report_object_collision (acclient.c:320227)
    private bool ReportObjectCollision(PhysicsObj obj, PhysicsObj other, bool prevContact)
    {
        if ((other.State & PhysicsState.ReportCollisionsAsEnvironment) != 0)
        {
            return ReportEnvironmentCollision(obj, prevContact);
        }

        bool result = false;
        IObjectCollisionListener? listener = ObjectCollisionListener;
        bool meMissile = (obj._state & PhysicsState.Missile) != 0;
        var v = new System.Numerics.Vector3(obj._velocity.X - other._velocity.X, obj._velocity.Y - other._velocity.Y,
            obj._velocity.Z - other._velocity.Z);
        if ((other.State & PhysicsState.IgnoreCollisions) == 0)
        {
            if ((obj._state & PhysicsState.ReportCollisions) != 0 && listener is not null)
            {
                if (meMissile)
                {
                    int q = PhysicsObj.DetermineQuadrant(other.Position, (float)other.GetHeight(), obj.Position);
                    listener.OnAttackCollision(obj, new AtkCollisionProfile(other.Id, -1, q));
                }
                else
                {
                    listener.OnObjectCollision(obj, new ObjCollisionProfile(other.Id, v, (other.State & PhysicsState.Missile) != 0,
                        (other.TransientState & TransientState.Contact) != 0, prevContact));
                }

                result = true;
            }

            if (meMissile)
            {
                obj._state &= ~(PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped);
            }
        }

        if ((other.State & PhysicsState.ReportCollisions) != 0 && (obj._state & PhysicsState.IgnoreCollisions) == 0 && listener is not null)
        {
            if ((other.State & PhysicsState.Missile) != 0)
            {
                int q = PhysicsObj.DetermineQuadrant(obj.Position, (float)obj.GetHeight(), other.Position);
                listener.OnAttackCollision(other, new AtkCollisionProfile(obj.Id, -1, q));
            }
            else
            {
                listener.OnObjectCollision(other, new ObjCollisionProfile(obj.Id, v, meMissile,
                    prevContact, (other.TransientState & TransientState.Contact) != 0));
            }

            result = true;
        }

        return result;
    }

    // retail: CPhysicsObj::report_object_collision_end (acclient.c:317868)
    private bool ReportObjectCollisionEnd(PhysicsObj obj, uint otherId)
    {
        PhysicsObj? other = obj.World.GetObjectById(otherId);
        if (other is null)
        {
            return false;
        }

        IObjectCollisionListener? listener = ObjectCollisionListener;
        if ((other.State & PhysicsState.ReportCollisionsAsEnvironment) == 0 && listener is not null)
        {
            if ((obj.State & PhysicsState.ReportCollisions) != 0)
            {
                listener.OnObjectCollisionEnd(obj, otherId);
            }

            if ((other.State & PhysicsState.ReportCollisions) != 0)
            {
                listener.OnObjectCollisionEnd(other, obj.Id);
            }
        }

        return true;
    }
}
