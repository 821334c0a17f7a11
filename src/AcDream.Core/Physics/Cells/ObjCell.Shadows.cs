using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Cells;

// The cell's list of object shadows: the objects a sweep through the cell must test.
public abstract partial class ObjCell
{
    // Allocated with the cell (one growth step), so that the first objects to walk in do not allocate inside a tick.
    private ShadowObj[] _shadowObjects = new ShadowObj[ShadowListGrowth];

    // The summary of each listed shadow's object, at the shadow's index (room for the list's capacity).
    // non-retail: the packed copies from which the object loop passes over obstacles out of reach (ObstacleSummary)
    private ObstacleTable _obstacles = new(ShadowListGrowth);

    /// <summary>Growth step of the shadow list. Retail grows by 5 (<c>add_shadow_object</c>, acclient.c:346804).</summary>
    internal const int ShadowListGrowth = 5;

    /// <summary>Number of shadows in the cell. Retail: <c>num_shadow_objects</c>.</summary>
    internal int NumShadowObjects { get; private set; }

    /// <summary>The shadows in the cell, <see cref="NumShadowObjects"/> long, in retail's list order.</summary>
    internal ReadOnlySpan<ShadowObj> ShadowObjects => _shadowObjects.AsSpan(0, NumShadowObjects);

    /// <summary>Slots of the shadow list (its capacity).</summary>
    internal int ShadowCapacity => _shadowObjects.Length;

    /// <summary>Largest shadow capacity <see cref="ReserveShadowCapacity"/> accepts: 65,536, far above any real cell's crowd.</summary>
    public const int MaxShadowCapacity = 65536;

    /// <summary>
    /// Makes room for <paramref name="capacity"/> shadows without growing later (for a client that knows how crowded a cell
    /// will be, e.g. when its landblock loads). The list otherwise doubles only past its largest size so far, and never
    /// shrinks.
    /// </summary>
    /// <param name="capacity">Shadows to make room for: 0 ..= <see cref="MaxShadowCapacity"/> (65,536).</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="capacity"/> is negative or above
    /// <see cref="MaxShadowCapacity"/> (state unchanged).</exception>
    public void ReserveShadowCapacity(int capacity)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(capacity);
        // non-retail: a bound on the reservation (int.MaxValue ran out of memory)
        ArgumentOutOfRangeException.ThrowIfGreaterThan(capacity, MaxShadowCapacity);
        if (capacity > _shadowObjects.Length)
        {
            Array.Resize(ref _shadowObjects, capacity);
            _obstacles.EnsureCapacity(capacity);
        }
    }

    /// <summary>Lists <paramref name="shadow"/> in the cell and points it at the cell.</summary>
    /// <remarks>When full the list doubles (at least <see cref="ShadowListGrowth"/>) and it never shrinks (retail grows by 5
    /// and shrinks a list with more than 10 spare slots). Only the capacity differs: the shadows and their order are
    /// retail's, and a crowd that keeps reaching new densities allocates a logarithmic number of times instead of once per
    /// five walkers.</remarks>
    // retail: CObjCell::add_shadow_object (acclient.c:346804)
    internal void AddShadowObject(ShadowObj shadow)
    {
        ArgumentNullException.ThrowIfNull(shadow);
        AddShadowObject(shadow, shadow.PhysObj.ComputeObstacleSummary());
    }

    /// <summary><see cref="AddShadowObject(ShadowObj)"/> with the summary of the shadow's object, computed by the caller
    /// (<see cref="PhysicsObj.ComputeObstacleSummary"/>: once for all the object's shadows).</summary>
    // retail: CObjCell::add_shadow_object (acclient.c:346804)
    internal void AddShadowObject(ShadowObj shadow, in ObstacleSummary summary)
    {
        if (NumShadowObjects >= _shadowObjects.Length)
        {
            // non-retail: doubling capacity (retail: + 5); unobservable but in allocations
            int capacity = Math.Max(_shadowObjects.Length * 2, ShadowListGrowth);
            Array.Resize(ref _shadowObjects, capacity);
            _obstacles.EnsureCapacity(capacity);
        }

        int i = NumShadowObjects++;
        _shadowObjects[i] = shadow;
        _obstacles.Set(i, summary, Id >> 16);
        shadow.Slot = i;
        shadow.Cell = this;
    }

    /// <summary>Removes <paramref name="shadow"/> (the last shadow takes its slot) and clears its cell.</summary>
    // retail: CObjCell::remove_shadow_object (acclient.c:346823)
    internal void RemoveShadowObject(ShadowObj shadow)
    {
        ArgumentNullException.ThrowIfNull(shadow);
        int i = IndexOfShadow(shadow);
        if (i < 0)
        {
            return;
        }

        shadow.Cell = null;
        int last = --NumShadowObjects;
        ShadowObj moved = _shadowObjects[last];
        _shadowObjects[i] = moved;
        _obstacles.Move(last, i);
        moved.Slot = i;
        _shadowObjects[last] = null!;
    }

    /// <summary>True when the entry of the shadow at <paramref name="index"/> (0 ..&lt; <see cref="NumShadowObjects"/>) is
    /// what this cell stores for <paramref name="summary"/>, bit for bit (<see cref="ObstacleSummary.ReachIn"/>).</summary>
    internal bool HoldsObstacleSummary(int index, in ObstacleSummary summary)
    {
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual((uint)index, (uint)NumShadowObjects, nameof(index));
        return _obstacles.Holds(index, summary, Id >> 16);
    }

    /// <summary>Writes <paramref name="summary"/> as the summary of <paramref name="shadow"/>, listed in this cell.</summary>
    // non-retail: keeps ObstacleSummary in step with its object
    internal void SetObstacleSummary(ShadowObj shadow, in ObstacleSummary summary)
    {
        int i = IndexOfShadow(shadow);
        if (i >= 0)
        {
            _obstacles.Set(i, summary, Id >> 16);
        }
    }

    // The shadow's index in the list (its slot; the list is searched, as retail does, should the slot not name it), or -1.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private int IndexOfShadow(ShadowObj shadow)
    {
        int i = shadow.Slot;
        if ((uint)i < (uint)NumShadowObjects && ReferenceEquals(_shadowObjects[i], shadow))
        {
            return i;
        }

        return IndexOfShadowBySearch(shadow);
    }

    private int IndexOfShadowBySearch(ShadowObj shadow)
    {
        for (int i = 0; i < NumShadowObjects; i++)
        {
            if (ReferenceEquals(_shadowObjects[i], shadow))
            {
                return i;
            }
        }

        return -1;
    }

    /// <summary>
    /// Every object shadowed in the cell (except the mover itself and attached objects) against the transition, until
    /// one answers other than OK. An initial placement tests no objects.
    /// </summary>
    // retail: CObjCell::find_obj_collisions (acclient.c:347141)
    private protected TransitionState FindShadowObjCollisions(Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        if (transition.SpherePath.InsertType == InsertType.InitialPlacement)
        {
            return TransitionState.Ok;
        }

        bool skipFar = !transition.ReferencePaths;
        return skipFar && NumShadowObjects > ShortShadowList ? FindShadowObjCollisionsSkipping(transition)
            : FindShadowObjCollisionsOneByOne(transition, skipFar);
    }

    // The longest shadow list decided one entry at a time without the table's vector pass: a list of one group of four or
    // fewer (the mover alone, or a few neighbours) costs less read directly than the pass's setup (the box, the margins and the
    // landblock offset broadcast to eleven vectors), and its few objects are a few cache lines.
    internal const int ShortShadowList = 4;

    // retail: CObjCell::find_obj_collisions (acclient.c:347141), entry by entry: retail's loop with skipFar false
    // (RetailSweep.ReferencePaths); with it (a short list), non-retail: the exact early-out of ObjectReach, an obstacle whose
    // spheres cannot reach the check spheres skipped with the exact effect of testing it. The box is made when the first
    // obstacle is met and again after every obstacle really tested, since a test that answers OK may still have moved the
    // check position (a step up).
    private TransitionState FindShadowObjCollisionsOneByOne(Transition transition, bool skipFar)
    {
        PhysicsObj? mover = transition.ObjectInfo.Object;
        bool reachValid = false;
        ObjectReach reach = default;
        for (int i = 0; i < NumShadowObjects; i++)
        {
            if (ObstacleSummary.Verify)
            {
                VerifyEntry(i);
            }

            PhysicsObj obj = _shadowObjects[i].PhysObj;
            if (obj.Parent is not null || ReferenceEquals(obj, mover))
            {
                continue;
            }

            if (skipFar)
            {
                if (!reachValid)
                {
                    reach = new ObjectReach(transition.SpherePath);
                    reachValid = true;
                }

                if (obj.IsOutOfReach(reach))
                {
                    // Skipping can only clear the obstruction flag: nothing to do when it is clear.
                    if (transition.SpherePath.ObstructionEthereal)
                    {
                        obj.SkipOutOfReach(transition);
                    }

                    continue;
                }

                reachValid = false;
            }

            TransitionState result = obj.FindObjCollisions(transition);
            if (result != TransitionState.Ok)
            {
                return result;
            }
        }

        return TransitionState.Ok;
    }

    // non-retail: CObjCell::find_obj_collisions (acclient.c:347141) with the exact early-out of ObjectReach: an obstacle whose
    // spheres cannot reach the check spheres is skipped with the exact effect of testing it. While the obstruction flag is
    // clear (skipping then has no effect at all) the table's vector test passes over, four at a time, the obstacles its
    // summaries show out of reach (their stored reach is never short of the exact one, so the exact test agrees) and the
    // attached ones, without reading them; every other entry is decided from its object in order, as the reference loop
    // does. The box is rebuilt after every obstacle really tested, since a test that answers OK may still have moved the
    // check position (a step up), and the rest of the group is decided again against it.
    private TransitionState FindShadowObjCollisionsSkipping(Transition transition)
    {
        SpherePath path = transition.SpherePath;
        var reach = new ObjectReach(path);
        uint block = Id >> 16;
        int i = 0;
        while (true)
        {
            // The next group with entries to decide one by one (from i on): those the vector test keeps, or all of them
            // while the obstruction flag is set.
            int group;
            uint kept;
            if (path.ObstructionEthereal)
            {
                group = i & ~3;
                kept = (0xFu << (i - group)) & 0xFu;
            }
            else
            {
                group = _obstacles.NextKept(i, NumShadowObjects, reach, BoxToCellOffset(reach, block), out kept);
            }

            bool tested = false;
            for (; kept != 0; kept &= kept - 1)
            {
                int k = group + BitOperations.TrailingZeroCount(kept);
                if (k >= NumShadowObjects)
                {
                    break;
                }

                if (ObstacleSummary.Verify)
                {
                    VerifyPassedOver(i, k, transition, reach);
                    VerifyEntry(k);
                }

                i = k + 1;
                PhysicsObj obj = _shadowObjects[k].PhysObj;
                if (obj.Parent is not null || ReferenceEquals(obj, transition.ObjectInfo.Object))
                {
                    continue;
                }

                if (obj.IsOutOfReach(reach))
                {
                    // Skipping can only clear the obstruction flag: nothing to do when it is clear.
                    if (path.ObstructionEthereal)
                    {
                        obj.SkipOutOfReach(transition);
                    }

                    continue;
                }

                TransitionState result = obj.FindObjCollisions(transition);
                if (result != TransitionState.Ok)
                {
                    return result;
                }

                // A new box: the rest of the group is decided again against it.
                reach = new ObjectReach(path);
                tested = true;
                break;
            }

            if (!tested)
            {
                int next = Math.Min(group + 4, NumShadowObjects);
                if (ObstacleSummary.Verify)
                {
                    VerifyPassedOver(i, next, transition, reach);
                }

                if (next >= NumShadowObjects)
                {
                    return TransitionState.Ok;
                }

                i = next;
            }
        }
    }

    // The offset that carries an origin of this cell's landblock into the box's, as IsOutOfReach computes it for an object of
    // this landblock (GetBlockOffset, after its own same-landblock test).
    private static Vector3 BoxToCellOffset(in ObjectReach reach, uint block) =>
        (reach.CellId >> 16) == block ? Vector3.Zero : LandDefs.GetBlockOffset(reach.CellId, block << 16 | 1u);

    // The check of ObstacleSummary.Verify: the entry is what this cell stores for its object as it stands.
    [MethodImpl(MethodImplOptions.NoInlining)]
    private void VerifyEntry(int i)
    {
        PhysicsObj obj = _shadowObjects[i].PhysObj;
        ObstacleSummary fresh = obj.ComputeObstacleSummary();
        if (!_obstacles.Holds(i, fresh, Id >> 16))
        {
            throw new InvalidOperationException(
                $"Stale obstacle summary of object 0x{obj.Id:X8} in cell 0x{Id:X8}: stored {_obstacles.Describe(i)}, fresh {fresh}.");
        }
    }

    // The check of ObstacleSummary.Verify for the entries [from, to) the vector test passed over: each entry is fresh, and
    // each is one the reference loop skips without effect (an attached object, the mover, or one out of reach by the object's
    // own IsOutOfReach, with the obstruction flag clear).
    [MethodImpl(MethodImplOptions.NoInlining)]
    private void VerifyPassedOver(int from, int to, Transition transition, in ObjectReach reach)
    {
        for (int k = from; k < to; k++)
        {
            VerifyEntry(k);
            PhysicsObj obj = _shadowObjects[k].PhysObj;
            bool skipped = obj.Parent is not null || ReferenceEquals(obj, transition.ObjectInfo.Object) || obj.IsOutOfReach(reach);
            if (!skipped || transition.SpherePath.ObstructionEthereal)
            {
                throw new InvalidOperationException(
                    $"The vector test passed over 0x{obj.Id:X8} (shadow {k} of cell 0x{Id:X8}), which the loop would test.");
            }
        }
    }

    /// <summary>True when <paramref name="obj"/>, where it stands, overlaps an object shadowed in this cell.</summary>
    // retail: CObjCell::check_collisions (acclient.c:347173)
    internal bool CheckCollisions(PhysicsObj obj)
    {
        ArgumentNullException.ThrowIfNull(obj);
        for (int i = 0; i < NumShadowObjects; i++)
        {
            PhysicsObj other = _shadowObjects[i].PhysObj;
            if (other.Parent is null && !ReferenceEquals(other, obj) && other.CheckCollision(obj))
            {
                return true;
            }
        }

        return false;
    }
}
