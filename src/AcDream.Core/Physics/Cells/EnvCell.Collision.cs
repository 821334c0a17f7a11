using System;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Bsp;

namespace AcDream.Core.Physics.Cells;

// The indoor cell as a collision cell of the sweep.
public sealed partial class EnvCell
{
    /// <summary>The cell's walls and floors, then the objects in it (the shadows of the objects that overlap it).</summary>
    // retail: CEnvCell::find_collisions (acclient.c:347809)
    internal override TransitionState FindCollisions(Transition transition)
    {
        TransitionState ts = FindEnvCollisions(transition);
        if (ts == TransitionState.Ok)
        {
            ts = FindObjCollisions(transition);
        }

        return ts;
    }

    /// <summary>
    /// The check spheres, moved into the cell's space, against its physics BSP: placement for an initial placement,
    /// the sweep's BSP collision otherwise. A blocked airborne object records an environment collision.
    /// </summary>
    // retail: CEnvCell::find_env_collisions (acclient.c:347822)
    internal override TransitionState FindEnvCollisions(Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        TransitionState ts = CheckEntryRestrictions(transition);
        if (ts != TransitionState.Ok)
        {
            return ts;
        }

        SpherePath path = transition.SpherePath;
        path.ObstructionEthereal = false;
        BspTree? bsp = Structure.PhysicsBsp;
        if (bsp is null)
        {
            return ts;
        }

        path.CacheLocalSpaceSphere(_pos, 1.0f);
        ts = path.InsertType == InsertType.InitialPlacement ? bsp.PlacementInsert(transition) : bsp.FindCollisions(transition, 1.0f);
        if (ts != TransitionState.Ok && (transition.ObjectInfo.State & ObjectInfoState.Contact) == 0)
        {
            transition.CollisionInfo.CollidedWithEnvironment = true;
        }

        return ts;
    }
}
