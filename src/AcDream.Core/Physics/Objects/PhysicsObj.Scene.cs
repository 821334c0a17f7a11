// PhysicsObj — the scene's slot, the wake and the lazily evaluated bookkeeping (not retail; no retail function).
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Scene;

namespace AcDream.Core.Physics.Objects;

// What the object keeps for the scene (SceneTicker): its slot, the wake, and the lazily evaluated bookkeeping behind
// UpdateTime, PlayerVector, PlayerDistance and TransientState. Not retail.
public sealed partial class PhysicsObj
{
    /// <summary>The scene's record of this object (dormancy, visiting list, gate queue) and the retail fields it evaluates lazily.</summary>
    internal SceneSlot _scene = new();

    /// <summary>True while the scene skips this object because its retail update would change nothing but bookkeeping.</summary>
    public bool IsDormant => _scene.Dormancy != Dormancy.Awake;

    /// <summary>
    /// Wakes the object if it is dormant: its bookkeeping (ACTIVE bit, update time, player vector) is brought to the values retail
    /// would hold now, and the scene visits it again from the next point in the tick order.
    /// </summary>
    /// <remarks>
    /// <para>The wake rule. An object is dormant only while its retail update would change nothing but the bookkeeping the scene
    /// evaluates lazily (<see cref="SceneTicker.ClassifyForSleep"/>, <see cref="SceneTicker.IsIdle"/>). Every public member that
    /// may change what that update does therefore calls <c>Touch</c> before it changes anything: velocity, omega, acceleration,
    /// state bits, transient state, placement (position, frame, heading, cell, parent and children), hooks and anim hooks,
    /// translucency and the other fades, scripts, interpolation and constraints, the part array and every manager seam, network
    /// events, collision commits, and a direct call of <see cref="UpdateObject"/> (which would otherwise run on stale
    /// bookkeeping that the next lazy read overwrites). Waking is always bit-identical (a visit of an object with nothing to
    /// do repeats retail's visit exactly); it only costs visits. Managers and part arrays that change their own idleness call
    /// it for their owner too.</para>
    /// <para>Mutators that deliberately do not wake (public ones and the internal shadow steps), each safe because a dormant
    /// object's retail update never reads the value, nor does the scene's classification or lazy bookkeeping:</para>
    /// <list type="bullet">
    /// <item><see cref="Friction"/>: read only by calc_friction, which runs only in an active step with a non-zero velocity; a
    /// dormant object either takes no active step (bailed, far, static) or is idle with a +0 velocity, and one that must move
    /// once near is woken before its first active step, so it reads the value then, as retail does.</item>
    /// <item><see cref="Elasticity"/>: read only by the collision response of the object's own sweep; a dormant object never
    /// sweeps (idle steps leave its origin unchanged, which takes the no-sweep branch of UpdateObjectInternal).</item>
    /// <item><see cref="TranslucencyOriginal"/>: read only by <see cref="SetTranslucencyInternal"/>, which wakes the object
    /// before it reads it.</item>
    /// <item><see cref="Weenie"/>: read only during sweeps (the object's own, which a dormant object never runs, or another
    /// object's sweep against it, which reads the field as it is whether or not the object is dormant) and when a movement
    /// manager is created (which wakes the object).</item>
    /// <item><see cref="LastMoveWasAutonomous"/>: read only by the motion interpreter, inside calls that wake the object
    /// themselves (its commands and ground events), never by update_object.</item>
    /// <item><see cref="NewerEvent"/>: writes only the network timestamps (update_times), read only by the network handlers,
    /// never by update_object; the handlers that act on a newer event wake the object.</item>
    /// <item><see cref="AddShadowsToCells"/>, <see cref="RemoveShadowsFromCells"/>: the cells' shadow lists, read only by
    /// sweeps: other objects' sweeps find the object through them and read its fields as they are, dormant or not; its own
    /// ethereal check runs only in an active step with CHECK_ETHEREAL set, which keeps an object awake.</item>
    /// </list>
    /// <para>A new public mutator must either call <c>Touch</c> or be added here with its reason; the wake-rule tests
    /// (tests/AcDream.Core.Tests/Scene/WakeRuleTests.cs) enumerate the public members and fail on one that is in neither list.</para>
    /// </remarks>
    internal void Touch()
    {
        if (_scene.Dormancy != Dormancy.Awake)
        {
            World.Scene.WakeDormant(this);
        }
        else if (!_scene.InActiveList && !_scene.PendingWake && InWorld)
        {
            World.Scene.EnqueueWake(this);
        }
    }

    /// <summary>Reads the object's first fields and its part array's type (the memory a visit starts with), so that a walk
    /// can bring the next objects' memory in while it visits this one; returns a value only so the reads are not dropped.</summary>
    internal int TouchForVisit() =>
        (int)_state + (int)_position.ObjCellId + (int)_position.Frame.M33 + (int)_scene.Dormancy + (int)_scene.UpdateTime + (int)CellId
        + (int)_velocity.X + (int)_omega.Z + (int)CachedVelocity.X + (int)ContactPlaneNormal.Z + (int)SlidingNormal.X + (int)Scale
        + _updateTimes[0] + NumShadowObjects + (Hooks is null ? 0 : 1) + (_partArray is null ? 0 : 1);

    /// <summary>Reads what a visit reads next, once the object itself is in cache: its part array's frame and motion.</summary>
    internal int TouchComponentsForVisit() =>
        _partArray is SimplePartArray p ? (int)p.SequenceVelocity.X + (int)p.SequenceOmega.Z + p.NumSpheres + (int)p.Scale
            + (int)p.GetPartFrame(0).M33 + (int)p.StepUpHeight : 0;

    // The dormant getters: bring the lazily evaluated bookkeeping to the values retail would hold now, then read the field.
    private void MaterializeIfLazy()
    {
        if (_scene.IsLazy)
        {
            SceneTicker scene = World.Scene;
            scene.Materialize(this, scene.IsVisitedThisTick(this));
        }
    }

    private double LazyUpdateTime()
    {
        MaterializeIfLazy();
        return _scene.UpdateTime;
    }

    private TransientState LazyTransientState()
    {
        MaterializeIfLazy();
        return _transientState;
    }

    private System.Numerics.Vector3 LazyPlayerVector()
    {
        MaterializeIfLazy();
        return _scene.PlayerVector;
    }

    private float LazyPlayerDistance()
    {
        MaterializeIfLazy();
        return _scene.PlayerDistance;
    }

    /// <summary>Writes the ACTIVE bit the scene's lazy bookkeeping evaluated for a dormant object (the bit retail's visits would
    /// have left); nothing else of the transient state changes.</summary>
    internal void SetLazyActive(bool active) =>
        _transientState = active ? _transientState | TransientState.Active : _transientState & ~TransientState.Active;
}
