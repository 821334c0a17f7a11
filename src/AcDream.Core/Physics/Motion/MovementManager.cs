using System;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion.MoveTo;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// An object's movement manager (retail <c>MovementManager</c>, PORTAL/canim/CMovementManager.c): it owns the motion
/// interpreter (created on first use, in its default state) and the move-to manager (<see cref="MoveTo.MoveToManager"/>,
/// created on the first move-to), routes the ground events and target reports to both, runs the player's motion commands
/// and the server's move-tos (<see cref="MoveToObject"/>, <see cref="MoveToPosition"/>, <see cref="TurnToObject"/>,
/// <see cref="TurnToHeading"/>: retail <c>PerformMovement</c> types 6–9). This is what an object gets when the physics
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

    /// <summary>The move-to manager, or null until the first move-to (retail <c>moveto_manager</c>).</summary>
    public MoveToManager? MoveToManager { get; private set; }

    /// <summary>Creates the move-to manager when absent (engine: <c>unpack_movement</c> before a move-to of types 6–9).</summary>
    /// <returns>The move-to manager.</returns>
    // retail: MovementManager::MakeMoveToManager (acclient.c:339100)
    internal MoveToManager MakeMoveToManager() => MoveToManager ??= MoveTo.MoveToManager.Create(PhysicsObj, WeenieObj);

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
        MoveToManager?.SetWeenieObject(weenieObj);
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
    /// <exception cref="ArgumentException">The state runs forward at a speed outside the run rate's domain
    /// (see <see cref="MotionInterp.MoveToInterpretedState"/>); nothing changes, no interpreter is created.</exception>
    // retail: MovementManager::move_to_interpreted_state (acclient.c:339220)
    public void MoveToInterpretedState(InterpretedMotionState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        MotionChecks.CheckState(state, nameof(state));
        GetOrCreateMotionInterpreter().MoveToInterpretedState(state);
    }

    /// <summary>Starts a command as the player gives it (<see cref="MotionInterp.DoMotion"/>), then takes the finished motions.</summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
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
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
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
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
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
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
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

    /// <summary>
    /// Walks or runs to object <paramref name="objectId"/> and follows it (its top-level object <paramref name="topLevelId"/>
    /// is tracked through the world's object table: the steps are planned at its first report, and each later report, sent
    /// when the target moves more than 0.5 m from its last predicted position, retargets). Ends within
    /// <see cref="MovementParameters.DistanceToObject"/> (between the cylinders of radius and height with
    /// <see cref="MovementParameterFlags.UseSpheres"/>), sticking to the target with <see cref="MovementParameterFlags.Sticky"/>.
    /// Retail <c>MovementManager::PerformMovement</c> type 6 (<c>MoveToManager::MoveToObject</c>); a running move-to is
    /// cancelled first (<see cref="MotionError.ActionCancelled"/>) and the object unsticks. <see cref="PhysicsObj.MoveToObject"/>
    /// looks the radius, height and top-level object up.
    /// </summary>
    /// <param name="objectId">The target's id (not 0).</param>
    /// <param name="topLevelId">The object tracked: the target or the object it is attached to (not 0). The object's own id
    /// only stops it.</param>
    /// <param name="radius">The target's radius, metres: finite, not negative.</param>
    /// <param name="height">The target's height, metres: finite, not negative.</param>
    /// <param name="p">The parameters (<c>new MovementParameters()</c> for retail's defaults): every float finite.</param>
    /// <exception cref="ArgumentException">An id is 0, a float is not finite, a size is negative, or <paramref name="p"/> is
    /// <c>default(MovementParameters)</c>; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The manager has no object, or its object was removed from its world.</exception>
    // retail: MovementManager::PerformMovement (acclient.c:339174), type 6
    public void MoveToObject(uint objectId, uint topLevelId, float radius, float height, in MovementParameters p)
    {
        if (objectId == 0 || topLevelId == 0)
        {
            throw new ArgumentException("A move-to-object needs a target id and a top-level id (not 0).", nameof(objectId));
        }

        if (!float.IsFinite(radius) || !float.IsFinite(height) || radius < 0f || height < 0f)
        {
            throw new ArgumentException("The target's radius and height must be finite and not negative.", nameof(radius));
        }

        p.CheckFiniteForMoveTo(nameof(p));
        PhysicsObj obj = RequireObject();
        MovementStruct mvs = MovementStruct.Of(MovementType.MoveToObject, p);
        mvs.ObjectId = objectId;
        mvs.TopLevelId = topLevelId;
        mvs.Radius = radius;
        mvs.Height = height;
        obj.Touch();
        PerformMovement(mvs);
    }

    /// <summary>
    /// Walks or runs to <paramref name="position"/>: turns to face it first when it is farther than
    /// <see cref="MovementParameters.DistanceToObject"/> (nearer than <see cref="MovementParameters.MinDistance"/> with
    /// <see cref="MovementParameterFlags.MoveAway"/>), moves (running when <see cref="MovementParameterFlags.CanRun"/> and
    /// farther than distance + <see cref="MovementParameters.WalkRunThreshold"/>, or when it may not walk), stops within the
    /// distance, then turns to <see cref="MovementParameters.DesiredHeading"/> with
    /// <see cref="MovementParameterFlags.UseFinalHeading"/>. Cancels with <see cref="MotionError.YouChargedTooFar"/> beyond
    /// <see cref="MovementParameters.FailDistance"/> from the start. Runs only while the object is on the ground. Retail
    /// <c>MovementManager::PerformMovement</c> type 7 (<c>MoveToManager::MoveToPosition</c>).
    /// </summary>
    /// <param name="position">The destination: the position domain of <see cref="PhysicsObj.StorePosition"/>.</param>
    /// <param name="p">The parameters: every float finite, not <c>default(MovementParameters)</c>.</param>
    /// <exception cref="ArgumentException">The position is outside the domain or the parameters are refused; nothing
    /// changes.</exception>
    /// <exception cref="InvalidOperationException">The manager has no object, or its object was removed from its world.</exception>
    // retail: MovementManager::PerformMovement (acclient.c:339174), type 7
    public void MoveToPosition(in Position position, in MovementParameters p)
    {
        if (!InputLimits.IsPositionInDomain(position))
        {
            throw new ArgumentException("Position must be in the position domain (InputLimits).", nameof(position));
        }

        p.CheckFiniteForMoveTo(nameof(p));
        PhysicsObj obj = RequireObject();
        MovementStruct mvs = MovementStruct.Of(MovementType.MoveToPosition, p);
        mvs.Pos = position;
        obj.Touch();
        PerformMovement(mvs);
    }

    /// <summary>
    /// Turns to face object <paramref name="objectId"/> (its top-level object <paramref name="topLevelId"/> is tracked; the
    /// turn is planned at its first report). Retail <c>MovementManager::PerformMovement</c> type 8
    /// (<c>MoveToManager::TurnToObject</c>).
    /// </summary>
    /// <param name="objectId">The target's id (not 0).</param>
    /// <param name="topLevelId">The object tracked (not 0); the object's own id only stops it.</param>
    /// <param name="p">The parameters: every float finite, not <c>default(MovementParameters)</c>.</param>
    /// <exception cref="ArgumentException">An id is 0 or the parameters are refused; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The manager has no object, or its object was removed from its world.</exception>
    // retail: MovementManager::PerformMovement (acclient.c:339174), type 8
    public void TurnToObject(uint objectId, uint topLevelId, in MovementParameters p)
    {
        if (objectId == 0 || topLevelId == 0)
        {
            throw new ArgumentException("A turn-to-object needs a target id and a top-level id (not 0).", nameof(objectId));
        }

        p.CheckFiniteForMoveTo(nameof(p));
        PhysicsObj obj = RequireObject();
        MovementStruct mvs = MovementStruct.Of(MovementType.TurnToObject, p);
        mvs.ObjectId = objectId;
        mvs.TopLevelId = topLevelId;
        obj.Touch();
        PerformMovement(mvs);
    }

    /// <summary>
    /// Turns to <see cref="MovementParameters.DesiredHeading"/> (degrees clockwise from north): right when it is at most
    /// 180° clockwise, else left; ends with the heading set exactly. Runs only while the object is on the ground. Retail
    /// <c>MovementManager::PerformMovement</c> type 9 (<c>MoveToManager::TurnToHeading</c>).
    /// </summary>
    /// <param name="p">The parameters: every float finite, not <c>default(MovementParameters)</c>.</param>
    /// <exception cref="ArgumentException">The parameters are refused; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The manager has no object, or its object was removed from its world.</exception>
    // retail: MovementManager::PerformMovement (acclient.c:339174), type 9
    public void TurnToHeading(in MovementParameters p)
    {
        p.CheckFiniteForMoveTo(nameof(p));
        PhysicsObj obj = RequireObject();
        MovementStruct mvs = MovementStruct.Of(MovementType.TurnToHeading, p);
        obj.Touch();
        PerformMovement(mvs);
    }

    private PhysicsObj RequireObject()
    {
        PhysicsObj obj = PhysicsObj ?? throw new InvalidOperationException("The movement manager has no object.");
        if (obj.RemovedFromWorld)
        {
            throw new InvalidOperationException("The object was removed from its world.");
        }

        return obj;
    }

    /// <summary>Runs one movement request: types 1–5 through the motion interpreter (created in its default state), 6–9
    /// through the move-to manager (created); the object is activated first. Engine entry (<c>unpack_movement</c>, the
    /// object's wrappers); unchecked.</summary>
    /// <returns>The interpreter's result (types 1–5), <see cref="MotionError.None"/> (6–9), or
    /// <see cref="MotionError.GeneralMovementFailure"/> (0x47) for another type.</returns>
    // retail: MovementManager::PerformMovement (acclient.c:339174)
    internal MotionError PerformMovement(in MovementStruct mvs)
    {
        PhysicsObj?.SetActiveInternal(true);
        switch (mvs.Type)
        {
            case MovementType.RawCommand:
            case MovementType.InterpretedCommand:
            case MovementType.StopRawCommand:
            case MovementType.StopInterpretedCommand:
            case MovementType.StopCompletely:
                return GetOrCreateMotionInterpreter().PerformMovement(mvs);
            case MovementType.MoveToObject:
            case MovementType.MoveToPosition:
            case MovementType.TurnToObject:
            case MovementType.TurnToHeading:
                return MakeMoveToManager().PerformMovement(mvs);
            default:
                return MotionError.GeneralMovementFailure;
        }
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

    /// <inheritdoc />
    // retail: MovementManager::HandleUpdateTarget (acclient.c:339630)
    void IMovementManager.HandleUpdateTarget(in Managers.TargetInfo info) => MoveToManager?.HandleUpdateTarget(info);

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
