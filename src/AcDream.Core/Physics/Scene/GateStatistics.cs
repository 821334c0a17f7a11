using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Scene;

/// <summary>
/// What the scene's 96 m gate tracking has done since the world was created (<see cref="PhysicsWorld.GateStatistics"/>): a
/// diagnostic for what dormant objects cost while the player moves (see docs/scene.md).
/// </summary>
/// <param name="Remeasures">Dormant objects re-measured against the gate: copies tested in the gate queues' SIMD passes (the
/// ring at each tick the player moved, the band or the grid cells near the circle at a rebuild; no object read).</param>
/// <param name="Crossings">Crossings by idle dormant objects applied without a visit.</param>
/// <param name="Wakes">Crossings that woke the object (a far mover that must move, or a tick after a stall that left time
/// unconsumed).</param>
public readonly record struct GateStatistics(long Remeasures, long Crossings, long Wakes);
