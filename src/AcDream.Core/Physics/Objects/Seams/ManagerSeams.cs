namespace AcDream.Core.Physics.Objects.Seams;

/// <summary>
/// Seam to an object's movement manager (retail <c>MovementManager</c>: motion interpreter and move-to manager), held in
/// <see cref="PhysicsObj.Movement"/>. The engine calls these members (the ground events, the per-step update, finished
/// motions); a client implements them for its own movement manager, and does not call them. The retail
/// <see cref="Motion.MovementManager"/> implements the engine callbacks explicitly, so they do not show on the class.
/// Implementations are called inside the tick and must not allocate.
/// </summary>
public interface IMovementManager
{
    /// <summary>Per-step update (retail <c>MovementManager::UseTime</c>).</summary>
    void UseTime();

    /// <summary>The object left the ground (retail <c>MovementManager::LeaveGround</c>).</summary>
    void LeaveGround();

    /// <summary>The object landed on walkable ground (retail <c>MovementManager::HitGround</c>).</summary>
    void HitGround();

    /// <summary>True while a move-to is in progress (retail <c>MovementManager::IsMovingTo</c>).</summary>
    bool IsMovingTo();

    /// <summary>The object entered the world (retail <c>MovementManager::HandleEnterWorld</c>).</summary>
    void HandleEnterWorld();

    /// <summary>The motion interpreter, or null while there is none. Must not create one.</summary>
    IMotionInterpreter? MotionInterpreter { get; }

    /// <summary>The motion interpreter, created first when absent (retail <c>MovementManager::get_minterp</c>); by default
    /// <see cref="MotionInterpreter"/>.</summary>
    IMotionInterpreter? GetOrCreateMotionInterpreter() => MotionInterpreter;

    /// <summary>Cancels a move-to with a weenie error (retail <c>MovementManager::CancelMoveTo</c>; a teleport gives
    /// <see cref="Motion.MotionError.ITeleported"/>, an unstick <see cref="Motion.MotionError.ActionCancelled"/>).</summary>
    void CancelMoveTo(Motion.MotionError error)
    {
    }

    /// <summary>A report of the object's tracked target (retail <c>MovementManager::HandleUpdateTarget</c>, reached from
    /// <c>CPhysicsObj::HandleUpdateTarget</c>): the retail manager passes it to its move-to manager.</summary>
    void HandleUpdateTarget(in Managers.TargetInfo info)
    {
    }

    /// <summary>The part array's motion table finished <paramref name="motion"/> (retail <c>MovementManager::MotionDone</c>,
    /// reached from <c>CPhysicsObj::MotionDone</c>).</summary>
    void MotionDone(Motion.MotionCommand motion, bool success)
    {
    }
}

/// <summary>Seam to the motion interpreter's speed queries (retail <c>CMotionInterp</c>).</summary>
public interface IMotionInterpreter
{
    /// <summary>Largest speed the motion state allows, m/s (retail <c>CMotionInterp::get_max_speed</c>, acclient.c:343485).</summary>
    double MaxSpeed { get; }

    /// <summary>Largest speed adjusted for the current run command, m/s (retail <c>CMotionInterp::get_adjusted_max_speed</c>, acclient.c:343511).</summary>
    double AdjustedMaxSpeed { get; }
}

/// <summary>Creates movement managers on demand, as retail's <c>MovementManager::Create</c> in <c>get_minterp</c>.</summary>
public interface IMovementManagerFactory
{
    /// <summary>Creates the movement manager of <paramref name="obj"/> in its default state.</summary>
    IMovementManager Create(PhysicsObj obj);
}

/// <summary>Seam to an object's detection manager (retail <c>DetectionManager::CheckDetection</c>), for a client's own;
/// retail's is <see cref="Managers.DetectionManager"/>. Called in the object's step: must not allocate.</summary>
public interface IDetectionManager
{
    /// <summary>Per-step detection check.</summary>
    void CheckDetection();
}

/// <summary>Seam to an object's particle manager (retail <c>ParticleManager::UpdateParticles</c>).</summary>
public interface IParticleManager
{
    /// <summary>Per-step particle update (runs for active and inactive objects).</summary>
    void UpdateParticles();
}

/// <summary>Seam to an object's script manager (retail <c>ScriptManager</c>).</summary>
public interface IScriptManager
{
    /// <summary>Per-step script update (runs for active and inactive objects).</summary>
    void UpdateScripts();
}

/// <summary>Client callback that starts a physics script (retail <c>CPhysicsObj::play_script_internal</c>, acclient.c:318034).</summary>
public interface IScriptPlayer
{
    /// <summary>Plays script <paramref name="scriptId"/> on <paramref name="obj"/>. Called from the tick: must not allocate.</summary>
    void PlayScript(PhysicsObj obj, uint scriptId);
}
