using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Scene;

/// <summary>
/// How a scene tracks dormant objects against the 96 m player gate (<see cref="PhysicsWorld.GateTracking"/>).
/// </summary>
public enum GateTracking
{
    /// <summary>
    /// Every dormant object whose side of the gate the player's movement could change is re-measured when that becomes possible,
    /// and crossings by idle objects are applied without a visit. Bookkeeping stays exactly retail's. The cost grows with the
    /// number of objects within a few metres of the player's 96 m circle and with the player's speed: about ln(8 m / step)
    /// re-measurements per object the circle passes, each a few arithmetic operations on a queue entry.
    /// </summary>
    Exact = 0,

    /// <summary>
    /// Only dormant objects that would move once near (far-away movers retail freezes) are re-measured; idle objects are not,
    /// which saves the re-measurements near the 96 m circle.
    /// Not retail: an idle object's ACTIVE bit and update_time (and so the tick on which a fade added to it next advances) may
    /// follow the gate side it had when it fell asleep. Positions, velocities and cells are unaffected.
    /// </summary>
    MovingObjectsOnly = 1,
}
