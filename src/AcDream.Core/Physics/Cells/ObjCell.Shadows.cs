using System;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Cells;

// The cell's list of object shadows: the objects a sweep through the cell must test.
public abstract partial class ObjCell
{
    // Allocated with the cell (one growth step), so that the first objects to walk in do not allocate inside a tick.
    private ShadowObj[] _shadowObjects = new ShadowObj[ShadowListGrowth];

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
        if (NumShadowObjects >= _shadowObjects.Length)
        {
            // non-retail: doubling capacity (retail: + 5); unobservable but in allocations
            Array.Resize(ref _shadowObjects, Math.Max(_shadowObjects.Length * 2, ShadowListGrowth));
        }

        _shadowObjects[NumShadowObjects++] = shadow;
        shadow.Cell = this;
    }

    /// <summary>Removes <paramref name="shadow"/> (the last shadow takes its slot) and clears its cell.</summary>
    // retail: CObjCell::remove_shadow_object (acclient.c:346823)
    internal void RemoveShadowObject(ShadowObj shadow)
    {
        ArgumentNullException.ThrowIfNull(shadow);
        for (int i = 0; i < NumShadowObjects; i++)
        {
            if (ReferenceEquals(_shadowObjects[i], shadow))
            {
                shadow.Cell = null;
                NumShadowObjects--;
                _shadowObjects[i] = _shadowObjects[NumShadowObjects];
                _shadowObjects[NumShadowObjects] = null!;
                return;
            }
        }
    }

    /// <summary>
    /// Every object shadowed in the cell (except the mover itself and attached objects) against the transition, until
    /// one answers other than OK. An initial placement tests no objects.
    /// </summary>
    // retail: CObjCell::find_obj_collisions (acclient.c:347141)
    private protected TransitionState FindShadowObjCollisions(Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        TransitionState result = TransitionState.Ok;
        if (transition.SpherePath.InsertType == InsertType.InitialPlacement)
        {
            return result;
        }

        PhysicsObj? mover = transition.ObjectInfo.Object;
        bool skipFar = !transition.ReferencePaths;
        bool reachValid = false;
        ObjectReach reach = default;
        for (int i = 0; i < NumShadowObjects; i++)
        {
            PhysicsObj obj = _shadowObjects[i].PhysObj;
            if (obj.Parent is null && !ReferenceEquals(obj, mover))
            {
                if (skipFar)
                {
                    // non-retail: an obstacle whose spheres cannot reach the check spheres is skipped with the exact
                    // effect of testing it (ObjectReach); the box is rebuilt after every obstacle really tested, since a
                    // test that answers OK may still have moved the check position (a step up).
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

                result = obj.FindObjCollisions(transition);
                if (result != TransitionState.Ok)
                {
                    break;
                }
            }
        }

        return result;
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
