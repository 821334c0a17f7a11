namespace AcDream.Core.Physics;

/// <summary>
/// How a scene tracks dormant objects against the 96 m player gate (<see cref="PhysicsWorld.GateTracking"/>).
/// </summary>
public enum GateTracking
{
    /// <summary>
    /// Every dormant object whose side of the gate the player's travel could change is re-measured when that becomes possible
    /// (an odometer queue). Bookkeeping stays exactly retail's. The cost grows with the number of objects near the player's
    /// 96 m circle and the player's speed (about ln(96 / 0.002) re-measurements per object the circle passes).
    /// </summary>
    Exact = 0,

    /// <summary>
    /// Only dormant objects that would move once near (far-away movers retail freezes) are re-measured; idle objects are not.
    /// Not retail: an idle object's ACTIVE bit and update_time (and so the tick on which a fade added to it next advances) may
    /// follow the gate side it had when it fell asleep. Positions, velocities and cells are unaffected.
    /// </summary>
    MovingObjectsOnly = 1,
}
