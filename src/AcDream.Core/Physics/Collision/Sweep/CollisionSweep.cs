using System;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
namespace AcDream.Core.Physics.Collision.Sweep;

/// <summary>
/// The one seam through which the collision sweep plugs into the object tick. A world holds one: <see cref="RetailSweep"/>,
/// the retail sweep through a world's cells (the default of a world made with terrain or cells), or
/// <see cref="FreeSpaceSweep"/>, a world with no geometry (the default of a world made without), or a client's own.
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
    /// <remarks>The tick (<see cref="SweepStep"/>) commits the result (<see cref="PhysicsObj.CommitTransition"/>'s work) with no
    /// collision response: a result carries no collisions, so a client sweep reports its own. <see cref="RetailSweep"/> and
    /// <see cref="FreeSpaceSweep"/> are not called through here by the tick: they answer <see cref="SweepStep"/> themselves.</remarks>
    // retail seam: CPhysicsObj::transition (acclient.c:320060); the retail sweep ports it as PhysicsObj.RunTransition
    public abstract bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result);

    /// <summary>
    /// The tick's sweep of one step: moves <paramref name="obj"/> from where it stands to <paramref name="newPos"/> and commits
    /// where it ended, with the step's velocity (<paramref name="quantum"/> seconds) cached. False when the sweep failed: the
    /// tick then keeps the object's origin. The base sweeps through <see cref="SweepObject"/> and commits its result;
    /// <see cref="RetailSweep"/> commits its transition, <see cref="FreeSpaceSweep"/> the free-space answer.
    /// </summary>
    /// <remarks>Called once per swept step, so the tick never asks which sweep it holds.</remarks>
    // retail seam: transit = CPhysicsObj::transition (acclient.c:320060); SetPositionInternal(transit) (acclient.c:322503)
    internal virtual bool SweepStep(PhysicsObj obj, in Position newPos, float quantum)
    {
        ref TransitionResult result = ref obj.World.EnterStepScratch();
        try
        {
            if (!SweepObject(obj, obj._position, newPos, false, ref result))
            {
                return false;
            }

            obj.CommitStep(result, quantum);
            return true;
        }
        finally
        {
            obj.World.LeaveStepScratch();
        }
    }

    /// <summary>Re-shadows <paramref name="obj"/> where it stands after a commit without a transition (a result carries no
    /// cells of its own). The base keeps no shadows and does nothing; <see cref="RetailSweep"/> lists the object in the cells
    /// it overlaps.</summary>
    internal virtual void ShadowInPlace(PhysicsObj obj)
    {
    }

    /// <summary>
    /// Places <paramref name="obj"/> at <paramref name="pos"/> (retail <c>CPhysicsObj::SetPosition</c>, acclient.c:323289,
    /// through <c>SetPositionInternal(sps, transit)</c>, acclient.c:323034). An implementation commits the outcome with
    /// <see cref="PhysicsObj.CommitTransition"/> or <see cref="PhysicsObj.GoToLostCell"/>.
    /// </summary>
    public abstract SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags);

    /// <summary>Ends the object's collision reports (retail <c>CPhysicsObj::report_collision_end</c>, acclient.c:321712),
    /// called by <see cref="PhysicsObj.TeleportHook"/>.</summary>
    public virtual void ReportCollisionEnd(PhysicsObj obj, bool forceEnd)
    {
    }

    /// <summary>True when a solid <paramref name="obj"/> would overlap another object now
    /// (retail <c>CPhysicsObj::ethereal_check_for_collisions</c>, acclient.c:317831).</summary>
    public virtual bool EtherealCheckForCollisions(PhysicsObj obj) => false;
}
