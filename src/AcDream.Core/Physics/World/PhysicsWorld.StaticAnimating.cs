using System.Collections.Generic;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.World;

// Retail's list of static objects that animate (windmills, flags): CPhysics::static_animating_objects.
public sealed partial class PhysicsWorld
{
    private readonly List<PhysicsObj> _staticAnimating = new();

    /// <summary>The static objects whose setup names a default animation or script (<see cref="PhysicsState.HasDefaultAnim"/>,
    /// <see cref="PhysicsState.HasDefaultScript"/>): windmills and flags. Retail: <c>CPhysics::static_animating_objects</c>,
    /// which its client animates each frame; the library lists them for the client's renderer (their parts' animation does
    /// not move their collision shapes here).</summary>
    public IReadOnlyList<PhysicsObj> StaticAnimatingObjects => _staticAnimating;

    /// <summary>Appends <paramref name="obj"/> to the list, moving it to the end when already there (the slot it leaves takes
    /// the last entry).</summary>
    // retail: CPhysics::AddStaticAnimatingObject (acclient.c:311439)
    internal void AddStaticAnimatingObject(PhysicsObj obj)
    {
        int i = _staticAnimating.IndexOf(obj);
        if (i >= 0)
        {
            _staticAnimating[i] = _staticAnimating[^1];
            _staticAnimating.RemoveAt(_staticAnimating.Count - 1);
        }

        _staticAnimating.Add(obj);
    }

    /// <summary>Takes <paramref name="obj"/> off the list (when it leaves the world).</summary>
    internal void RemoveStaticAnimatingObject(PhysicsObj obj) => _staticAnimating.Remove(obj);
}
