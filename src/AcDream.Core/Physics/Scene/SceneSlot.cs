using System.Numerics;

namespace AcDream.Core.Physics.Scene;

/// <summary>How a dormant object's retail bookkeeping evolves while the scene does not visit it.</summary>
internal enum Dormancy : byte
{
    /// <summary>Visited every world tick.</summary>
    Awake = 0,

    /// <summary>update_object bails out at once (parented, no cell, frozen): nothing changes.</summary>
    Bailed,

    /// <summary>Each tick only update_time advances, by retail's consumed-time arithmetic (the world's consumed clock), and the
    /// player vector is re-measured. ACTIVE stays as it is (clear: static, far, or no player; set: idle but never on walkable).</summary>
    ConsumedClock,

    /// <summary>Near the player, idle on walkable ground: retail re-activates it every other tick (set_active restarts its
    /// clock) and it deactivates itself on the next step. ACTIVE and update_time alternate.</summary>
    PingPong,
}

/// <summary>
/// What the scene keeps in each object (<see cref="Objects.PhysicsObj"/> holds one): its dormancy, its place in the visiting
/// list and in a gate queue, and the retail fields the scene evaluates lazily while the object is dormant.
/// </summary>
/// <remarks>Not retail. Only the scene (<see cref="SceneTicker"/>, <see cref="GateQueue"/>) writes the dormancy and list
/// fields; the object reads and writes the three retail fields through its properties, which materialise them first when the
/// object is dormant (<see cref="SceneTicker.Materialize"/>).</remarks>
internal struct SceneSlot
{
    /// <summary>How the object's bookkeeping evolves while it is not visited; <see cref="Dormancy.Awake"/> when visited.</summary>
    internal Dormancy Dormancy;

    /// <summary>The scene tick after which the object was put to sleep.</summary>
    internal long SleepTick;

    /// <summary>The object's ACTIVE bit when it was put to sleep.</summary>
    internal bool SleepPhaseActive;

    /// <summary>True while the object is in the scene's visiting list.</summary>
    internal bool InActiveList;

    /// <summary>True while the object waits in the scene's pending list (woken, joins the visiting list at the next tick).</summary>
    internal bool PendingWake;

    /// <summary>The gate queue holding the object's position copy, or null.</summary>
    internal GateQueue? GateQueue;

    /// <summary>The object's slot in <see cref="GateQueue"/>; -1 when none.</summary>
    internal int GateSlot;

    /// <summary>Retail <c>update_time</c> (as of the last materialisation while dormant).</summary>
    internal double UpdateTime;

    /// <summary>Retail <c>player_vector</c> (as of the last materialisation while dormant).</summary>
    internal Vector3 PlayerVector;

    /// <summary>Retail <c>player_distance</c> (as of the last materialisation while dormant).</summary>
    internal float PlayerDistance;

    public SceneSlot()
    {
        GateSlot = -1;
    }

    /// <summary>True when the object's bookkeeping is evaluated lazily (dormant with a clock-driven kind).</summary>
    internal readonly bool IsLazy => Dormancy is Dormancy.ConsumedClock or Dormancy.PingPong;
}
