// PhysicsObj — leave_world (the server's pickup), and the network layer's writes of the update stamps.
using System;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects;

// The object leaving the world without being removed (a pickup), and the stamp writes retail's SmartBox makes directly.
public sealed partial class PhysicsObj
{
    /// <summary>
    /// Takes the object out of the world without removing it (retail's pickup): ends its collisions, leaves its cell (its
    /// shadows too), the cell id becomes 0, and contact, walkable and the other transient bits are cleared. The object
    /// stays in its world's id table and can enter the world again (<see cref="EnterWorld"/>).
    /// </summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::leave_world (acclient.c:322653)
    public void LeaveWorld()
    {
        ThrowIfRemoved();
        Touch();
        World.Sweep.ReportCollisionEnd(this, true);
        _transientState &= ~TransientState.Active;
        RemoveShadowsFromCells();
        LeaveCell();
        StorePositionInternal(new Position(0, _position.Frame));
        // acclient.c:322680-322695: the tail is clear_transient_states' (contact, walkable, sliding, stationary, active).
        ClearTransientStates();
    }

    // SmartBox writes update_times directly: the position stamp restored after a stale teleport, the force-position
    // blip's position stamp, and CPhysicsObj::set_description's copy of all nine.
    internal void SetUpdateTime(PhysicsTimeStamp stamp, ushort value) => _updateTimes[StampIndex(stamp)] = value;

}
