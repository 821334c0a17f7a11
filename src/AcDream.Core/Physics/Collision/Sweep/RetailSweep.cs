using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Math;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Collision.Sweep;

/// <summary>
/// The retail collision sweep plugged into the object tick: <see cref="PhysicsWorld.Sweep"/> set to an instance of
/// this class makes every object move through the cells of <see cref="Cells"/> (outdoor terrain today) exactly as
/// retail's <c>CPhysicsObj::transition</c> moves it, and answers placements and the collision response.
/// </summary>
/// <remarks>One instance per world: it owns the world's <see cref="TransitionPool"/>. Nothing here allocates per call.</remarks>
public sealed partial class RetailSweep : CollisionSweep
{
    private Transition? _committed;

    /// <summary>
    /// How far, in metres (in x and in y, signed), a non-sliding placement may end from the requested spot. Retail:
    /// 0.050000001 in <c>CPhysicsObj::CheckPositionInternal</c> (acclient.c:319172), float bits 0x3D4CCCCD.
    /// </summary>
    public const float PlacementTolerance = 0.050000001f;

    /// <summary>Creates the sweep over <paramref name="cells"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="cells"/> is null.</exception>
    public RetailSweep(ICellSource cells)
    {
        ArgumentNullException.ThrowIfNull(cells);
        Cells = cells;
        Pool = new TransitionPool(cells);
    }

    /// <summary>Where cells are found.</summary>
    public ICellSource Cells { get; }

    /// <inheritdoc />
    /// <remarks>Land and indoor cells hold the shadows of the objects in them (<c>CObjCell::shadow_object_list</c>), so a
    /// <see cref="TerrainWorld"/> (or <see cref="WorldCells"/>) serves exactly one <see cref="PhysicsWorld"/>: sharing it would let
    /// one world's objects collide with the other's. Give each world its own terrain world (the landblock data can be shared).</remarks>
    internal override void AttachTo(PhysicsWorld world)
    {
        PhysicsWorld? owner = Cells switch
        {
            TerrainWorld t => t.OwnerWorld,
            WorldCells c => c.OwnerWorld ?? c.Terrain.OwnerWorld,
            _ => null,
        };
        if (owner is not null && owner != world)
        {
            throw new ArgumentException(
                "These cells already hold another PhysicsWorld's objects (their shadows); give each world its own TerrainWorld.",
                nameof(world));
        }

        switch (Cells)
        {
            case TerrainWorld t:
                t.OwnerWorld = world;
                break;
            case WorldCells c:
                c.OwnerWorld = world;
                c.Terrain.OwnerWorld = world;
                break;
        }
    }

    /// <summary>The ten transitions (retail's static pool, per world here).</summary>
    public TransitionPool Pool { get; }

    /// <summary>Receives environment collision reports (retail: the weenie). Null reports nothing.</summary>
    public ICollisionListener? CollisionListener { get; set; }

    /// <summary>The transition of the last successful sweep or placement; readable until the next sweep.</summary>
    public Transition? LastTransition => _committed;

    /// <summary>
    /// Sweeps <paramref name="obj"/> from <paramref name="oldPos"/> to <paramref name="newPos"/> in a pooled transition.
    /// Returns the transition (already given back to the pool, readable until the next sweep) or null when the sweep
    /// failed or all ten transitions were in use.
    /// </summary>
    /// <exception cref="ArgumentException">A position has a NaN or infinite origin (nothing is changed).</exception>
    // retail: CPhysicsObj::transition (acclient.c:320060)
    public Transition? RunTransition(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove)
    {
        ArgumentNullException.ThrowIfNull(obj);
        if (!VectorMath.IsFinite(oldPos.Frame.Origin) || !VectorMath.IsFinite(newPos.Frame.Origin))
        {
            throw new ArgumentException("Sweep positions must have finite origins.", nameof(newPos));
        }

        Transition? t = Pool.Make();
        if (t is null)
        {
            return null;
        }

        bool ok;
        try
        {
            ObjectInfoState state = obj.GetObjectInfo(t, adminMove);
            t.InitObject(obj, state);
            InitSpheres(t, obj);
            t.InitPath(Cells.GetVisible(obj.CellId), oldPos, newPos);
            TransientState ts = obj.TransientState;
            if ((ts & TransientState.StationaryStuck) != 0)
            {
                t.CollisionInfo.FramesStationaryFall = Collision.Transition.StationaryFallFrames;
            }
            else if ((ts & TransientState.StationaryStop) != 0)
            {
                t.CollisionInfo.FramesStationaryFall = 2;
            }
            else if ((ts & TransientState.StationaryFall) != 0)
            {
                t.CollisionInfo.FramesStationaryFall = 1;
            }

            ok = t.FindValidPosition();
        }
        finally
        {
            Pool.Cleanup();
        }

        return ok ? t : null;
    }

    /// <inheritdoc />
    // retail: CPhysicsObj::transition (acclient.c:320060), result read by UpdateObjectInternal (acclient.c:322718)
    public override bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result)
    {
        Transition? t = RunTransition(obj, oldPos, newPos, adminMove);
        if (t is null)
        {
            return false;
        }

        Fill(t, ref result);
        _committed = t;
        return true;
    }

    /// <inheritdoc />
    /// <remarks>Scatter placement (SCATTER / RANDOMSCATTER) and the weenie's forced cells are not ported; interior cells
    /// arrive with issue 6.</remarks>
    // retail: CPhysicsObj::SetPosition (acclient.c:323289) -> SetPositionInternal(sps) (acclient.c:323166)
    //         -> SetPositionInternal(p, sps, transit) (acclient.c:323034)
    public override SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags)
    {
        ArgumentNullException.ThrowIfNull(obj);
        Transition? t = Pool.Make();
        if (t is null)
        {
            return SetPositionError.GeneralFailure;
        }

        try
        {
            t.InitObject(obj, ObjectInfoState.None);
            InitSpheres(t, obj);
            Position p = pos;
            ObjCell? cell = AdjustPosition(ref p, t.SpherePath.LocalSphere[0].Center);
            if (cell is null)
            {
                obj.GoToLostCell(p);
                return SetPositionError.Ok;
            }

            if ((flags & SetPositionFlags.DoNotCreateCells) != 0)
            {
                t.CellArray.DoNotLoadCells = true;
            }

            if (!CheckPositionInternal(cell, ref p, t, flags))
            {
                _committed = t;
                return HandleAllCollisions(obj, t.CollisionInfo, false, false) ? SetPositionError.Collided : SetPositionError.NoValidPosition;
            }

            if (t.SpherePath.CurrCell is null)
            {
                return SetPositionError.NoCell;
            }

            var result = default(TransitionResult);
            Fill(t, ref result);
            _committed = t;
            obj.CommitTransition(result);
            return SetPositionError.Ok;
        }
        finally
        {
            Pool.Cleanup();
        }
    }

    /// <inheritdoc />
    public override void HandleAllCollisions(PhysicsObj obj, bool prevContact, bool prevOnWalkable)
    {
        ArgumentNullException.ThrowIfNull(obj);
        if (_committed is not null)
        {
            HandleAllCollisions(obj, _committed.CollisionInfo, prevContact, prevOnWalkable);
        }
    }

    /// <summary>
    /// The collision response of a committed sweep: reports a new environment collision (or a landing), bounces the
    /// velocity off the collision normal by the elasticity (an inelastic object stops; an object that walked on stays
    /// unbounced unless sledding), stops an object stuck falling, and records the stationary bits.
    /// </summary>
    /// <returns>True when a collision was reported.</returns>
    // retail: CPhysicsObj::handle_all_collisions (acclient.c:321807)
    public bool HandleAllCollisions(PhysicsObj obj, CollisionInfo collisions, bool prevContact, bool prevOnWalkable)
    {
        ArgumentNullException.ThrowIfNull(obj);
        ArgumentNullException.ThrowIfNull(collisions);
        bool onWalkable = (obj._transientState & TransientState.OnWalkable) != 0;
        bool applyBounce = !prevOnWalkable || !onWalkable || (obj._state & PhysicsState.Sledding) != 0;
        bool reported = false;

        if (HandleObjectCollisions(obj, collisions, prevContact))
        {
            reported = true;
        }

        if (obj.CollidingWithEnvironment)
        {
            obj.CollidingWithEnvironment = collisions.CollidedWithEnvironment;
        }
        else if (collisions.CollidedWithEnvironment || (!prevOnWalkable && onWalkable))
        {
            reported = ReportEnvironmentCollision(obj, prevContact) || reported;
        }

        int fsf = collisions.FramesStationaryFall;
        if (fsf <= 1)
        {
            if (applyBounce && collisions.CollisionNormalValid)
            {
                if ((obj._state & PhysicsState.Inelastic) != 0)
                {
                    obj._velocity = Vector3.Zero;
                }
                else
                {
                    Vector3 v = obj._velocity;
                    Vector3 n = collisions.CollisionNormal;
                    double dot = (double)v.Z * n.Z + (double)v.Y * n.Y + (double)n.X * v.X;
                    if (dot < 0.0)
                    {
                        double k = -(dot * (obj.Elasticity + 1.0));
                        float ky = (float)(k * n.Y);
                        float kz = (float)(k * n.Z);
                        obj._velocity = new Vector3((float)(k * n.X + v.X), ky + v.Y, kz + v.Z);
                    }
                }
            }
        }
        else
        {
            obj._velocity = Vector3.Zero;
            if (fsf == 3)
            {
                obj._transientState &= ~StationaryBits;
                return reported;
            }
        }

        switch (fsf)
        {
            case 0:
                obj._transientState &= ~StationaryBits;
                break;
            case 1:
                obj._transientState |= TransientState.StationaryFall;
                break;
            case 2:
                obj._transientState |= TransientState.StationaryStop;
                break;
            default:
                obj._transientState |= TransientState.StationaryStuck;
                break;
        }

        return reported;
    }

    private const TransientState StationaryBits =
        TransientState.StationaryFall | TransientState.StationaryStop | TransientState.StationaryStuck;

    /// <summary>Reports the start of an environment collision once; a missile loses MISSILE, ALIGNPATH and PATHCLIPPED.</summary>
    // retail: CPhysicsObj::report_environment_collision (acclient.c:320193)
    private bool ReportEnvironmentCollision(PhysicsObj obj, bool prevContact)
    {
        bool result = false;
        if (obj.CollidingWithEnvironment)
        {
            return false;
        }

        if ((obj._state & PhysicsState.ReportCollisions) != 0 && CollisionListener is not null)
        {
            CollisionListener.OnEnvironmentCollision(obj, new EnvCollisionProfile(obj._velocity, prevContact));
            result = true;
        }

        obj.CollidingWithEnvironment = true;
        if ((obj._state & PhysicsState.Missile) != 0)
        {
            obj._state &= ~(PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped);
        }

        return result;
    }

    // retail: the sphere choice shared by transition (acclient.c:320060), check_collision and SetPosition
    private static void InitSpheres(Transition t, PhysicsObj obj)
    {
        IPartArray? parts = obj.PartArray;
        if (parts is not null && parts.NumSpheres != 0)
        {
            t.InitSphere(parts.Spheres, obj.Scale);
        }
        else
        {
            Span<Sphere> dummy = stackalloc Sphere[1];
            dummy[0] = Sphere.Dummy;
            t.InitSphere(dummy, 1.0f);
        }
    }

    // retail: CPhysicsObj::AdjustPosition (acclient.c:319116); indoor branch without the outdoor fallback
    private ObjCell? AdjustPosition(ref Position p, Vector3 spherePoint)
    {
        uint low = p.ObjCellId & 0xFFFF;
        if (!((low >= 1 && low <= 0x40) || (low >= 0x100 && low <= 0xFFFD) || low == 0xFFFF))
        {
            return null;
        }

        if (low >= LandDefs.FirstEnvCell)
        {
            // Indoor: the cell itself or a neighbour that contains the first sphere's centre. Retail (bSearchCells = 1)
            // searches the cell's stab list of visible cells; we search its portal neighbours, and retail's fallback to
            // the outdoors for cells seen from outside is not ported (docs/divergences.md, "Indoor SetPosition").
            if (Cells.GetVisible(p.ObjCellId) is not EnvCell env)
            {
                return null;
            }

            EnvCell? child = env.FindVisibleChildCell(Cells, p.LocalToGlobal(p, spherePoint));
            if (child is not null)
            {
                p.ObjCellId = child.CellId;
            }

            return child;
        }

        LandDefs.AdjustToOutside(ref p.ObjCellId, ref p.Frame.Origin);
        return p.ObjCellId != 0 ? Cells.GetVisible(p.ObjCellId) : null;
    }

    /// <summary>
    /// Places the transition's spheres at <paramref name="p"/>: without SLIDE the placement must end within 5 cm (in x and y,
    /// signed as retail compares) of the request and in the same cell, and then takes the placed origin.
    /// </summary>
    // retail: CPhysicsObj::CheckPositionInternal (acclient.c:319172)
    private static bool CheckPositionInternal(ObjCell cell, ref Position p, Transition t, SetPositionFlags flags)
    {
        t.InitPlacementPath(cell, p);
        bool slide = (flags & SetPositionFlags.Slide) != 0;
        if (!slide)
        {
            t.SpherePath.PlacementAllowsSliding = false;
        }

        if (!t.FindValidPosition())
        {
            return false;
        }

        if (slide)
        {
            return true;
        }

        Position curr = t.SpherePath.CurrPos;
        if (curr.Frame.Origin.X - p.Frame.Origin.X < PlacementTolerance
            && curr.Frame.Origin.Y - p.Frame.Origin.Y < PlacementTolerance
            && curr.ObjCellId == cell.Id)
        {
            p.Frame.Origin = curr.Frame.Origin;
            return true;
        }

        return false;
    }

    private static void Fill(Transition t, ref TransitionResult result)
    {
        SpherePath path = t.SpherePath;
        CollisionInfo ci = t.CollisionInfo;
        result.CurrentPosition = path.CurrPos;
        result.CurrentCellId = path.CurrCell?.Id ?? 0;
        result.ContactPlaneValid = ci.ContactPlaneValid;
        result.ContactPlaneNormal = ci.ContactPlane.N;
        result.ContactPlaneD = ci.ContactPlane.D;
        result.ContactPlaneCellId = ci.ContactPlaneCellId;
        result.ContactPlaneIsWater = ci.ContactPlaneIsWater;
        result.SlidingNormalValid = ci.SlidingNormalValid;
        result.SlidingNormal = ci.SlidingNormal;
    }
}
