using AcDream.Core.Physics.Scene;

namespace AcDream.Core.Physics.World;

// The scene's entry points: which effects a world simulates and whether dormant objects are skipped. The scene itself
// (which objects a tick visits, dormancy, the 96 m gate) is SceneTicker.
public sealed partial class PhysicsWorld
{
    /// <summary>The scene tick the world runs unless <see cref="VisitEveryObject"/>.</summary>
    internal SceneTicker Scene { get; }

    /// <summary>
    /// The effects this scene simulates; <see cref="SceneEffects.All"/> (retail) by default. Declare fewer to pay for fewer.
    /// </summary>
    public SceneEffects Effects { get; init; } = SceneEffects.All;

    /// <summary>
    /// When true, every object is visited every tick, as retail walks its object table (for comparison and diagnostics).
    /// False by default: dormant objects are skipped, with identical simulated results.
    /// </summary>
    public bool VisitEveryObject { get; init; }

    /// <summary>
    /// How dormant objects follow the player's 96 m gate. <see cref="GateTracking.Exact"/> (the default) keeps their bookkeeping
    /// exactly retail's; <see cref="GateTracking.MovingObjectsOnly"/> re-measures only dormant objects that would move once near.
    /// </summary>
    public GateTracking GateTracking { get; init; } = GateTracking.Exact;

    /// <summary>What the 96 m gate tracking has done since the world was created (re-measurements, crossings applied without a
    /// visit, crossings that woke their object).</summary>
    public GateStatistics GateStatistics => new(Scene.GateRemeasures, Scene.GateFlips, Scene.GateWakes);

    /// <summary>Number of objects visited by the last tick (awake objects).</summary>
    public int LastTickVisitCount { get; private set; }

    /// <summary>Number of objects currently dormant (never visited until an event wakes them).</summary>
    public int DormantCount => _objects.Count - Scene.AwakeCount;

    /// <summary>Dormant objects' copies re-measured against the 96 m gate since the world was created.</summary>
    internal long GateRemeasures => Scene.GateRemeasures;

    /// <summary>Gate crossings handled without a visit since the world was created.</summary>
    internal long GateFlips => Scene.GateFlips;

    /// <summary>Gate crossings that woke their object since the world was created.</summary>
    internal long GateWakes => Scene.GateWakes;

    /// <summary>Entries the gate queues hold, stale ones included.</summary>
    internal int GateEntryCount => Scene.GateEntryCount;
}
