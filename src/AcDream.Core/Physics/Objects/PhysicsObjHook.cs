using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

/// <summary>
/// A persistent per-object callback run once per simulation step until it reports done (retail <c>PhysicsObjHook</c>,
/// acclient.h:30961). Hooks form a doubly linked list on the object; new hooks are pushed at the head, so the newest
/// runs first (<c>CPhysicsObj::process_hooks</c>, acclient.c:318640).
/// </summary>
/// <remarks>A hook belongs to at most one object at a time. Pooled hooks (<see cref="FPHook"/>) are recycled by their world
/// once removed: do not keep a reference to one after it reports done.</remarks>
public abstract class PhysicsObjHook
{
    /// <summary>What the hook drives.</summary>
    public PhysicsHookType HookType { get; protected set; }

    /// <summary>Physics-clock time at which the hook was created, seconds (retail <c>time_created</c>, a double).</summary>
    public double TimeCreated { get; protected set; }

    /// <summary>Duration of the hook's interpolation, seconds (retail <c>interpolation_time</c>, a double).</summary>
    public double InterpolationTime { get; protected set; }

    /// <summary>Hook-specific data: a part index or a script id (retail <c>user_data</c>).</summary>
    public uint UserData { get; protected set; }

    /// <summary>Previous hook in the owner's list (newer), or null.</summary>
    public PhysicsObjHook? Prev { get; internal set; }

    /// <summary>Next hook in the owner's list (older), or null.</summary>
    public PhysicsObjHook? Next { get; internal set; }

    /// <summary>The object whose list holds this hook, or null.</summary>
    public PhysicsObj? Owner { get; internal set; }

    /// <summary>Runs the hook for one step on <paramref name="obj"/>. Returns true when it is done and must be removed.
    /// Called inside the tick: must not allocate.</summary>
    public abstract bool Execute(PhysicsObj obj);

    /// <summary>Called after the hook was unlinked because it reported done (pooled hooks return to their pool).</summary>
    protected internal virtual void OnRemoved(PhysicsWorld world)
    {
    }
}
