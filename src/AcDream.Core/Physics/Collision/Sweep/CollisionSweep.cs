using System;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
namespace AcDream.Core.Physics.Collision.Sweep;

/// <summary>
/// The one seam through which the collision sweep plugs into the object tick. A world holds one; the built-in
/// <see cref="FreeSpaceSweep"/> sweeps through empty space (a world built without cells); <see cref="RetailSweep"/> is the retail sweep.
/// </summary>
/// <remarks>Every member is called inside the tick and must not allocate.</remarks>
public abstract class CollisionSweep
{
    /// <summary>
    /// Called when a world takes this seam as its <see cref="PhysicsWorld.Sweep"/>. A seam that keeps per-world state
    /// (cells holding the shadows of one world's objects) refuses a second world here.
    /// </summary>
    /// <exception cref="ArgumentException">The seam, or the cells it sweeps, already serve another world.</exception>
    internal virtual void AttachTo(PhysicsWorld world)
    {
    }

    /// <summary>
    /// True when a placement of <paramref name="obj"/> at <paramref name="pos"/> would find a cell (its landblock, or its indoor
    /// cell, is loaded); false when it would send the object to the lost cell. <see cref="PhysicsObj.EnterWorld"/> asks before
    /// it changes anything. The base answers from the id alone (a valid world cell id, outdoor ids re-homed to the cell under the
    /// origin), as <see cref="FreeSpaceSweep"/> places.
    /// </summary>
    internal virtual bool FindsCell(PhysicsObj obj, in Position pos)
    {
        Position p = pos;
        return LandDefs.InboundValidCellId(p.ObjCellId) && ((p.ObjCellId & 0xFFFFu) >= 0x100u || p.TryAdjustToOutside());
    }

    /// <summary>
    /// Called when <paramref name="world"/> replaces this seam by <paramref name="next"/>. A seam that keeps per-world state
    /// takes the world's objects out of its cells and releases them for another world.
    /// </summary>
    internal virtual void DetachFrom(PhysicsWorld world, CollisionSweep next)
    {
    }

    /// <summary>
    /// Sweeps <paramref name="obj"/> from <paramref name="oldPos"/> to <paramref name="newPos"/>. On success fills
    /// <paramref name="result"/> and returns true; on failure (blocked, or no transition available) returns false and
    /// the object keeps its origin.
    /// </summary>
    // retail seam: CPhysicsObj::transition (acclient.c:320060); the retail sweep ports it as PhysicsObj.RunTransition
    public abstract bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result);

    /// <summary>
    /// Places <paramref name="obj"/> at <paramref name="pos"/> (retail <c>CPhysicsObj::SetPosition</c>, acclient.c:323289,
    /// through <c>SetPositionInternal(sps, transit)</c>, acclient.c:323034). An implementation commits the outcome with
    /// <see cref="PhysicsObj.CommitTransition"/> or <see cref="PhysicsObj.GoToLostCell"/>.
    /// </summary>
    public abstract SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags);

    /// <summary>
    /// Reports the collisions of the last committed sweep (retail <c>CPhysicsObj::handle_all_collisions</c>, acclient.c:321807),
    /// called by <see cref="PhysicsObj.CommitTransition"/> after the contact state is updated.
    /// </summary>
    public virtual void HandleAllCollisions(PhysicsObj obj, bool prevContact, bool prevOnWalkable)
    {
    }

    /// <summary>
    /// Updates the object's shadows in the cells it overlaps after a commit (retail <c>calc_cross_cells</c> /
    /// <c>add_shadows_to_cells</c>, end of acclient.c:322503).
    /// </summary>
    public virtual void UpdateCellShadows(PhysicsObj obj)
    {
    }

    /// <summary>Ends the object's collision reports (retail <c>CPhysicsObj::report_collision_end</c>, acclient.c:321712),
    /// called by <see cref="PhysicsObj.TeleportHook"/>.</summary>
    public virtual void ReportCollisionEnd(PhysicsObj obj, bool forceEnd)
    {
    }

    /// <summary>True when a solid <paramref name="obj"/> would overlap another object now
    /// (retail <c>CPhysicsObj::ethereal_check_for_collisions</c>, acclient.c:317831).</summary>
    public virtual bool EtherealCheckForCollisions(PhysicsObj obj) => false;
}
