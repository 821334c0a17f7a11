using System;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// An object's movement manager (retail <c>MovementManager</c>, PORTAL/canim/CMovementManager.c): it owns the motion
/// interpreter (created on first use, in its default state) and the move-to manager (a seam, <see cref="IMoveToManager"/>),
/// routes the ground events to both, and runs the player's motion commands. This is what an object gets when the physics
/// first needs one (<see cref="PhysicsObj.GetOrCreateMotionInterpreter"/>, <see cref="PhysicsObj.MakeMovementManager"/>),
/// unless the world has a <see cref="Objects.Seams.IMovementManagerFactory"/>; <see cref="PhysicsObj.Movement"/> holds it.
/// The engine's callbacks (<see cref="IMovementManager"/>'s ground events, per-step update and finished motions) are
/// implemented explicitly: a client does not call them.
/// </summary>
public sealed class MovementManager : IMovementManager
{
    private MotionInterp? _motionInterpreter;

    private MovementManager(PhysicsObj? physicsObj, IMotionWeenie? weenieObj)
    {
        PhysicsObj = physicsObj;
        WeenieObj = weenieObj;
    }

    /// <summary>The object moved.</summary>
    public PhysicsObj? PhysicsObj { get; }

    /// <summary>The character the interpreter asks, or null.</summary>
    public IMotionWeenie? WeenieObj { get; private set; }

    /// <summary>The move-to manager, or null (retail creates one for a move-to; not ported).</summary>
    public IMoveToManager? MoveToManager { get; set; }

    /// <summary>The motion interpreter, or null until created (by <see cref="GetOrCreateMotionInterpreter"/>,
    /// <see cref="EnterDefaultState"/> or any motion call). Never creates it.</summary>
    public MotionInterp? MotionInterpreter => _motionInterpreter;

    /// <inheritdoc />
    IMotionInterpreter? IMovementManager.MotionInterpreter => _motionInterpreter;

    /// <inheritdoc />
    IMotionInterpreter? IMovementManager.GetOrCreateMotionInterpreter() => GetOrCreateMotionInterpreter();

    /// <summary>Creates the movement manager of <paramref name="physicsObj"/> (no interpreter yet).</summary>
    // retail: MovementManager::Create (acclient.c:339131)
    public static MovementManager Create(PhysicsObj? physicsObj, IMotionWeenie? weenieObj) => new(physicsObj, weenieObj);

    /// <summary>The movement manager of <paramref name="obj"/>, creating it (in its default state) when it has none.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="obj"/> is null.</exception>
    /// <exception cref="InvalidOperationException">The object's movement manager is a client's own.</exception>
    public static MovementManager Of(PhysicsObj obj)
    {
        ArgumentNullException.ThrowIfNull(obj);
        return obj.MakeMovementManager(true) as MovementManager
               ?? throw new InvalidOperationException("The object's movement manager is not the retail MovementManager.");
    }

    /// <summary>The motion interpreter, creating it (in its default state when the manager has an object) when absent
    /// (retail <c>MovementManager::get_minterp</c>).</summary>
    /// <returns>The interpreter, never null.</returns>
    // retail: MovementManager::get_minterp (acclient.c:339329)
    public MotionInterp GetOrCreateMotionInterpreter()
    {
        if (_motionInterpreter is null)
        {
            _motionInterpreter = MotionInterp.Create(PhysicsObj, WeenieObj);
            if (PhysicsObj is not null)
            {
                _motionInterpreter.EnterDefaultState();
            }
        }

        return _motionInterpreter;
    }

    /// <summary>Sets the character for the interpreter.</summary>
    // retail: MovementManager::SetWeenieObject (acclient.c:339114)
    public void SetWeenieObject(IMotionWeenie? weenieObj)
    {
        PhysicsObj?.Touch();
        WeenieObj = weenieObj;
        _motionInterpreter?.SetWeenieObject(weenieObj);
    }

    /// <summary>Puts the interpreter in its default state (creating it).</summary>
    // retail: MovementManager::EnterDefaultState (acclient.c:339249)
    public void EnterDefaultState()
    {
        if (PhysicsObj is null)
        {
            return;
        }

        // A new interpreter enters its default state in get_minterp, then again here (retail does both).
        GetOrCreateMotionInterpreter().EnterDefaultState();
    }

    /// <summary>The raw motion state (creating the interpreter).</summary>
    // retail: MovementManager::InqRawMotionState (acclient.c:339273)
    public RawMotionState InqRawMotionState() => GetOrCreateMotionInterpreter().RawState;

    /// <summary>The interpreted motion state (creating the interpreter).</summary>
    // retail: MovementManager::InqInterpretedMotionState (acclient.c:339292)
    public InterpretedMotionState InqInterpretedMotionState() => GetOrCreateMotionInterpreter().InterpretedState;

    /// <summary>Applies a whole interpreted state from the server (creating the interpreter).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="state"/> is null.</exception>
    // retail: MovementManager::move_to_interpreted_state (acclient.c:339220)
    public void MoveToInterpretedState(InterpretedMotionState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        GetOrCreateMotionInterpreter().MoveToInterpretedState(state);
    }

    /// <summary>Starts a command as the player gives it (<see cref="MotionInterp.DoMotion"/>), then takes the finished motions.</summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN or infinite (nothing changes).</exception>
    /// <remarks>The object's <see cref="Objects.PhysicsObj.LastMoveWasAutonomous"/> becomes true first, as
    /// <c>CPhysicsObj::DoMotion</c> (acclient.c:317314) sets it: this client's own commands.</remarks>
    // retail: MovementManager::PerformMovement (acclient.c:339174), type 1 -> CMotionInterp::PerformMovement (acclient.c:344669)
    public MotionError DoMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        MarkAutonomous();
        Activate();
        MotionError r = GetOrCreateMotionInterpreter().DoMotion(motion, p);
        PhysicsObj?.CheckForCompletedMotions();
        return r;
    }

    /// <summary>Starts an interpreted motion (<see cref="MotionInterp.DoInterpretedMotion"/>), then takes the finished motions.</summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN or infinite (nothing changes).</exception>
    // retail: MovementManager::PerformMovement (acclient.c:339174), type 2
    public MotionError DoInterpretedMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        Activate();
        MotionError r = GetOrCreateMotionInterpreter().DoInterpretedMotion(motion, p);
        PhysicsObj?.CheckForCompletedMotions();
        return r;
    }

    /// <summary>Stops a command as the player gives it (<see cref="MotionInterp.StopMotion"/>), then takes the finished motions.</summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN or infinite (nothing changes).</exception>
    /// <remarks>Marks the move autonomous first, as <c>CPhysicsObj::StopMotion</c> (acclient.c:317353) does.</remarks>
    // retail: MovementManager::PerformMovement (acclient.c:339174), type 3
    public MotionError StopMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        MarkAutonomous();
        Activate();
        MotionError r = GetOrCreateMotionInterpreter().StopMotion(motion, p);
        PhysicsObj?.CheckForCompletedMotions();
        return r;
    }

    /// <summary>Stops an interpreted motion, then takes the finished motions.</summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN or infinite (nothing changes).</exception>
    // retail: MovementManager::PerformMovement (acclient.c:339174), type 4
    public MotionError StopInterpretedMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        Activate();
        MotionError r = GetOrCreateMotionInterpreter().StopInterpretedMotion(motion, p);
        PhysicsObj?.CheckForCompletedMotions();
        return r;
    }

    /// <summary>Stops everything (<see cref="MotionInterp.StopCompletely"/>), then takes the finished motions.</summary>
    // retail: MovementManager::PerformMovement (acclient.c:339174), type 5
    public void StopCompletely()
    {
        Activate();
        GetOrCreateMotionInterpreter().StopCompletely();
        PhysicsObj?.CheckForCompletedMotions();
    }

    private void Activate() => PhysicsObj?.SetActive(true);

    private void MarkAutonomous()
    {
        if (PhysicsObj is not null)
        {
            PhysicsObj.LastMoveWasAutonomous = true;
        }
    }

    /// <inheritdoc />
    // retail: MovementManager::IsMovingTo (acclient.c:339311)
    public bool IsMovingTo() => MoveToManager is not null && MoveToManager.IsMovingTo();

    /// <summary>True while the interpreter has unfinished motions.</summary>
    // retail: MovementManager::motions_pending (acclient.c:339320)
    public bool MotionsPending() => _motionInterpreter is not null && _motionInterpreter.MotionsPending();

    /// <inheritdoc />
    // retail: MovementManager::MotionDone (acclient.c:339348)
    void IMovementManager.MotionDone(MotionCommand motion, bool success) => _motionInterpreter?.MotionDone(success);

    /// <inheritdoc />
    // retail: MovementManager::UseTime (acclient.c:339358)
    void IMovementManager.UseTime() => MoveToManager?.UseTime();

    /// <inheritdoc />
    // retail: MovementManager::HitGround (acclient.c:339368)
    void IMovementManager.HitGround()
    {
        _motionInterpreter?.HitGround();
        MoveToManager?.HitGround();
    }

    /// <inheritdoc />
    // retail: MovementManager::LeaveGround (acclient.c:339384); the move-to manager's LeaveGround is empty
    void IMovementManager.LeaveGround() => _motionInterpreter?.LeaveGround();

    /// <inheritdoc />
    // retail: MovementManager::HandleEnterWorld (acclient.c:339400): the interpreter's HandleEnterWorld is empty
    void IMovementManager.HandleEnterWorld()
    {
    }

    /// <summary>The object left the world: the interpreter finishes its pending motions (engine callback).</summary>
    // retail: MovementManager::HandleExitWorld (acclient.c:339410)
    internal void HandleExitWorld() => _motionInterpreter?.HandleExitWorld();

    /// <summary>The stamina ran out or came back: the interpreter re-applies its movement.</summary>
    // retail: MovementManager::ReportExhaustion (acclient.c:339420)
    public void ReportExhaustion() => _motionInterpreter?.ReportExhaustion();

    /// <inheritdoc />
    // retail: MovementManager::CancelMoveTo (acclient.c:339239)
    void IMovementManager.CancelMoveTo(MotionError error) => MoveToManager?.CancelMoveTo(error);
}
