using System;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Collision.Sweep;

/// <summary>
/// The retail collision sweep plugged into the object tick: <see cref="PhysicsWorld.Sweep"/> set to an instance of
/// this class makes every object move through the cells of <see cref="Cells"/> (the outdoor terrain of a
/// <see cref="TerrainWorld"/>; with a <see cref="WorldCells"/> also the indoor cells and buildings) exactly as
/// retail's <c>CPhysicsObj::transition</c> moves it, and answers placements and the collision response.
/// </summary>
/// <remarks>One instance per world: it owns the world's pool of ten transitions (retail's <c>CTransition::transit</c>). Nothing here allocates per call.</remarks>
public sealed class RetailSweep : CollisionSweep
{
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

    /// <inheritdoc />
    /// <remarks>Answers from <see cref="Cells"/>: the cell <c>AdjustPosition</c> would start the placement from.</remarks>
    internal override bool FindsCell(PhysicsObj obj, in Position pos) => obj.FindsPlacementCell(this, pos);

    /// <inheritdoc />
    /// <remarks>The world's objects' shadows leave the cells, and the cells (a <see cref="TerrainWorld"/>, or a
    /// <see cref="WorldCells"/> and its terrain) are released so that another world may take them. Nothing happens when
    /// <paramref name="next"/> sweeps the same cells.</remarks>
    internal override void DetachFrom(PhysicsWorld world, CollisionSweep next)
    {
        // non-retail: retail has one world; here the cells change hands between worlds
        if (next is RetailSweep r && ReferenceEquals(r.Cells, Cells))
        {
            return;
        }

        for (int i = 0; i < world.ObjectCount; i++)
        {
            world.GetObject(i).RemoveShadowsFromCells();
        }

        switch (Cells)
        {
            case TerrainWorld t when t.OwnerWorld == world:
                t.OwnerWorld = null;
                break;
            case WorldCells c:
                if (c.OwnerWorld == world)
                {
                    c.OwnerWorld = null;
                }

                if (c.Terrain.OwnerWorld == world)
                {
                    c.Terrain.OwnerWorld = null;
                }

                break;
        }
    }

    /// <summary>The ten transitions (retail's static pool, per world here).</summary>
    internal TransitionPool Pool { get; }

    /// <summary>Sweep the plain retail way, without the port's exact shortcuts (for tests that compare both; off by
    /// default). See <see cref="Transition.ReferencePaths"/>.</summary>
    internal bool ReferencePaths
    {
        get => Pool.ReferencePaths;
        set => Pool.ReferencePaths = value;
    }

    /// <summary>The scratch cell array of <see cref="PhysicsObj.CalcCrossCells"/>.</summary>
    internal CellArray CrossCells { get; } = new();

    /// <summary>Receives environment collision reports (retail: the weenie). Null reports nothing.</summary>
    public ICollisionListener? CollisionListener { get; set; }

    /// <summary>Receives object collision reports (retail: the objects' weenies). Null reports nothing; the collision
    /// table is kept either way.</summary>
    public IObjectCollisionListener? ObjectCollisionListener { get; set; }

    /// <summary>Sweeps <paramref name="obj"/> in a pooled transition (see <see cref="PhysicsObj.RunTransition"/>).</summary>
    /// <exception cref="ArgumentException">A position is outside the position domain (<see cref="InputLimits"/>; nothing is
    /// changed).</exception>
    internal Transition? RunTransition(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove)
    {
        ArgumentNullException.ThrowIfNull(obj);
        return obj.RunTransition(this, oldPos, newPos, adminMove);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentNullException"><paramref name="obj"/> is null.</exception>
    /// <exception cref="ArgumentException">A position is outside the position domain (<see cref="InputLimits"/>: unit
    /// quaternion; origin finite, within ±65,536 m, outdoor x, y in [−192, 384]) or the sweep is longer than
    /// <see cref="InputLimits.MaxSweepDistance"/> (192 m); nothing is changed. A position in no world cell (id 0,
    /// 0xFFFFFFFF, a landblock outside the world) makes the sweep fail (false).</exception>
    // retail seam: CPhysicsObj::transition (acclient.c:320060), ported as PhysicsObj.RunTransition
    public override bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result)
    {
        Transition? t = RunTransition(obj, oldPos, newPos, adminMove);
        if (t is null)
        {
            return false;
        }

        Fill(t, ref result);
        return true;
    }

    /// <inheritdoc />
    /// <remarks>The transition itself is committed (its collisions reported, its cells shadowed); it keeps its pool slot until
    /// the commit is done.</remarks>
    // retail part: transit = transition(...); SetPositionInternal(transit) of CPhysicsObj::UpdateObjectInternal (acclient.c line 322718)
    internal override bool SweepStep(PhysicsObj obj, in Position newPos, float quantum)
    {
        Transition? transit = obj.SweepHoldingTransition(this, obj._position, newPos, false);
        if (transit is null)
        {
            return false;
        }

        // non-retail: the transition keeps its pool slot until the commit is done (retail gives it back first), so a sweep or
        // placement started from a collision report takes another slot
        try
        {
            obj.CommitStep(this, transit, quantum);
        }
        finally
        {
            Pool.Cleanup();
        }

        return true;
    }

    /// <inheritdoc />
    /// <remarks>Scatter placement (SCATTER / RANDOMSCATTER) and the weenie's forced cells are not ported.</remarks>
    /// <exception cref="ArgumentNullException"><paramref name="obj"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="pos"/> is outside the position domain (<see cref="InputLimits"/>);
    /// nothing is changed.</exception>
    public override SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags)
    {
        ArgumentNullException.ThrowIfNull(obj);
        // non-retail: the position domain, checked before the object can be sent to the lost cell
        InputLimits.ThrowIfOutside(pos, nameof(pos));
        return obj.SetPositionInternal(this, pos, flags);
    }

    /// <summary>
    /// Re-shadows <paramref name="obj"/> where it stands: in the cells its cylinder spheres overlap, or, without them (or
    /// with a physics BSP), the cells of its sorting sphere (plus its own cell for a BSP object).
    /// </summary>
    internal void CalcCrossCells(PhysicsObj obj)
    {
        ArgumentNullException.ThrowIfNull(obj);
        obj.CalcCrossCells(this);
    }

    /// <inheritdoc />
    internal override void ShadowInPlace(PhysicsObj obj) => obj.CalcCrossCells(this);

    /// <inheritdoc />
    public override bool EtherealCheckForCollisions(PhysicsObj obj)
    {
        ArgumentNullException.ThrowIfNull(obj);
        return obj.EtherealCheckForCollisions();
    }

    /// <inheritdoc />
    public override void ReportCollisionEnd(PhysicsObj obj, bool forceEnd)
    {
        ArgumentNullException.ThrowIfNull(obj);
        obj.ReportCollisionEnd(this, forceEnd);
    }

    /// <summary>Copies what <see cref="PhysicsObj.CommitTransition"/> commits out of <paramref name="t"/>.</summary>
    internal static void Fill(Transition t, ref TransitionResult result)
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
