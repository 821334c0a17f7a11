using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// An object's move-to manager (retail <c>MoveToManager</c>, acclient.h:31473, PORTAL/canim/CMoveToManager.c): walks or
/// runs the object to a position or an object (following it through target tracking), or turns it to a heading or an
/// object, by playing interpreted motions (walk, run, turn) step by step from a list of pending steps (turn to the target's
/// heading, move, turn to the final heading). Owned by the retail <see cref="MovementManager"/>, created on the first move-to
/// (<see cref="MovementManager.MoveToManager"/>); driven by the object's step (<c>UseTime</c>, on the ground only) and by its
/// target reports (<c>HandleUpdateTarget</c>).
/// </summary>
/// <remarks>
/// Entry points: <see cref="MovementManager.MoveToObject"/>, <see cref="MovementManager.MoveToPosition"/>,
/// <see cref="MovementManager.TurnToObject"/>, <see cref="MovementManager.TurnToHeading"/> (retail
/// <c>MovementManager::PerformMovement</c>, types 6–9), or <see cref="PhysicsObj.MoveToObject"/>,
/// <see cref="PhysicsObj.TurnToObject"/>, <see cref="PhysicsObj.TurnToHeading"/> (which look the target up in the world).
/// The state below is read-only for clients.
/// </remarks>
public sealed partial class MoveToManager
{
    /// <summary>Radius a move-to or turn-to tracks its target with, metres: 0.5 (<c>MoveToObject</c>, <c>TurnToObject</c>).</summary>
    internal const float TargetTrackRadius = 0.5f;

    /// <summary>Report look-ahead a move-to or turn-to starts tracking with, seconds: 0.0 (<c>MoveToObject</c>, <c>TurnToObject</c>).</summary>
    internal const double TargetTrackQuantum = 0.0;

    /// <summary>Heading error beyond which a move corrects with a turn, degrees: 20 (<c>HandleMoveToPosition</c>).</summary>
    internal const double AuxTurnThreshold = 20.0;

    /// <summary>Time between progress checks, seconds of client time: more than 1.0 (<c>CheckProgressMade</c>).</summary>
    internal const double ProgressCheckInterval = 1.0;

    /// <summary>Least closing (or opening) rate a move counts as progress, m/s: 0.25 (<c>CheckProgressMade</c>).</summary>
    internal const double MinProgressRate = 0.25;

    /// <summary>Speed above which a move-to-object sets its target's report look-ahead, m/s: 0.1 (<c>HandleMoveToPosition</c>).</summary>
    internal const double QuantumMinSpeed = 0.1;

    /// <summary>Change of the time to get there that resets the look-ahead, seconds: more than 1.0 (<c>HandleMoveToPosition</c>).</summary>
    internal const double QuantumChangeThreshold = 1.0;

    private readonly MoveToNodeList _pendingActions = new();
    private MovementParameters _movementParams;

    /// <summary>Creates a manager with no object (retail constructor: default parameters, then
    /// <c>InitializeLocalVariables</c>).</summary>
    // retail: MoveToManager::MoveToManager (acclient.c:344977)
    private MoveToManager()
    {
        SoughtPosition = new Position(0, Frame.Identity);
        CurrentTargetPosition = new Position(0, Frame.Identity);
        StartingPosition = new Position(0, Frame.Identity);
        _movementParams = new MovementParameters();
        PhysicsObj = null;
        WeenieObj = null;
        InitializeLocalVariables();
    }

    /// <summary>Creates the manager of <paramref name="physicsObj"/>.</summary>
    // retail: MoveToManager::Create (acclient.c:345028)
    internal static MoveToManager Create(PhysicsObj? physicsObj, IMotionWeenie? weenieObj)
    {
        var m = new MoveToManager();
        m.PhysicsObj = physicsObj;
        m.WeenieObj = weenieObj;
        return m;
    }

    /// <summary>The object moved.</summary>
    public PhysicsObj? PhysicsObj { get; private set; }

    /// <summary>The object's character (kept, as retail; the move-to does not ask it).</summary>
    public IMotionWeenie? WeenieObj { get; private set; }

    /// <summary>The running move-to, or <see cref="MovementType.Invalid"/> when idle (retail <c>movement_type</c>).</summary>
    public MovementType MovementType { get; private set; }

    /// <summary>Where the move-to goes (a target's predicted position; a turn's heading in its frame).</summary>
    public Position SoughtPosition { get; private set; }

    /// <summary>The target's position the distance is measured to.</summary>
    public Position CurrentTargetPosition { get; private set; }

    /// <summary>The object's position when the move-to started (the fail distance is measured from it).</summary>
    public Position StartingPosition { get; private set; }

    /// <summary>The running move-to's parameters (the sticky bit is cleared for move-to-position and turn-to-heading).</summary>
    public MovementParameters MovementParams => _movementParams;

    /// <summary>The heading (or, right after a turn starts, the heading error) last seen while turning, degrees.</summary>
    public float PreviousHeading { get; private set; }

    /// <summary>The distance at the last progress check, metres (float.MaxValue before the first).</summary>
    public float PreviousDistance { get; private set; }

    /// <summary>Client time of the last progress check, seconds.</summary>
    public double PreviousDistanceTime { get; private set; }

    /// <summary>The distance when the move started (or the target was last reported), metres.</summary>
    public float OriginalDistance { get; private set; }

    /// <summary>Client time of <see cref="OriginalDistance"/>, seconds.</summary>
    public double OriginalDistanceTime { get; private set; }

    /// <summary>Steps in a row without progress while neither interpolating nor playing pending motions (retail counts; it
    /// gives up on nothing by it).</summary>
    public uint FailProgressCount { get; private set; }

    /// <summary>The target object's id (move-to-object, turn-to-object).</summary>
    public uint SoughtObjectId { get; private set; }

    /// <summary>The target's top-level object id (the one tracked), or 0 for a position or heading.</summary>
    public uint TopLevelObjectId { get; private set; }

    /// <summary>The target's radius, metres.</summary>
    public float SoughtObjectRadius { get; private set; }

    /// <summary>The target's height, metres.</summary>
    public float SoughtObjectHeight { get; private set; }

    /// <summary>The move or turn being played (walk forward, walk backwards, turn right or left), or 0.</summary>
    public MotionCommand CurrentCommand { get; private set; }

    /// <summary>The correcting turn played while moving, or 0.</summary>
    public MotionCommand AuxCommand { get; private set; }

    /// <summary>The move goes away from the target.</summary>
    public bool MovingAway { get; private set; }

    /// <summary>A move-to or turn-to an object has its target's first report.</summary>
    public bool Initialized { get; private set; }

    /// <summary>Pending steps (the head is running).</summary>
    public int PendingActionCount => _pendingActions.Count;

    /// <summary>The error the last move-to ended with: <see cref="MotionError.None"/> when it arrived (or was replaced by
    /// a stop), else the reason it was cancelled (<see cref="MotionError.ActionCancelled"/> 0x36 by a new movement or an
    /// unstick, <see cref="MotionError.ObjectGone"/> 0x37, <see cref="MotionError.NoObject"/> 0x38,
    /// <see cref="MotionError.YouChargedTooFar"/> 0x3D past the fail distance, <see cref="MotionError.ITeleported"/> 0x3C, or
    /// the error of a motion it could not play).</summary>
    /// <remarks>Non-retail: retail passes this code to a weenie callback that the 11.4186 client has compiled out
    /// (<c>CancelMoveTo</c> and <c>CleanUpAndCallWeenie</c> take it and drop it); kept here so a client can read it.</remarks>
    public MotionError LastResult { get; private set; }

    /// <summary>True while a move-to runs.</summary>
    // retail: MoveToManager::is_moving_to (acclient.c:344894)
    public bool IsMovingTo() => MovementType != MovementType.Invalid;

    internal MoveToNodeList PendingActions => _pendingActions;

    private double CurTime => PhysicsObj is not null ? PhysicsObj.World.CurrentTime : 0.0;

    /// <summary>Sets the character.</summary>
    // retail: MoveToManager::SetWeenieObject (acclient.c:344900)
    internal void SetWeenieObject(IMotionWeenie? weenieObj) => WeenieObj = weenieObj;

    /// <summary>Sets the object.</summary>
    // retail: MoveToManager::SetPhysicsObject (acclient.c:344906)
    internal void SetPhysicsObject(PhysicsObj? physicsObj) => PhysicsObj = physicsObj;

    /// <summary>Resets the move-to state (not the pending list, not the starting position).</summary>
    // retail: MoveToManager::InitializeLocalVariables (acclient.c:344912)
    private void InitializeLocalVariables()
    {
        MovementType = MovementType.Invalid;
        _movementParams.Flags = MovementParameterFlags.None;
        _movementParams.ContextId = 0;
        PreviousDistance = float.MaxValue;
        double now = CurTime;
        PreviousDistanceTime = now;
        OriginalDistance = float.MaxValue;
        OriginalDistanceTime = now;
        PreviousHeading = 0f;
        FailProgressCount = 0;
        CurrentCommand = 0;
        AuxCommand = 0;
        MovingAway = false;
        Initialized = false;
        SoughtPosition = new Position(0, Frame.Identity);
        CurrentTargetPosition = new Position(0, Frame.Identity);
        SoughtObjectId = 0;
        TopLevelObjectId = 0;
        SoughtObjectRadius = 0f;
        SoughtObjectHeight = 0f;
    }

    /// <summary>Drops the head step.</summary>
    // retail: MoveToManager::RemovePendingActionsHead (acclient.c:344961)
    private void RemovePendingActionsHead() => _pendingActions.RemoveHead();

    /// <summary>Drops every step and resets (retail's destructor body).</summary>
    // retail: MoveToManager::Destroy (acclient.c:345046)
    internal void Destroy()
    {
        _pendingActions.Clear();
        InitializeLocalVariables();
    }

    /// <summary>Appends a turn to <paramref name="globalHeading"/>.</summary>
    // retail: MoveToManager::AddTurnToHeadingNode (acclient.c:345095)
    private void AddTurnToHeadingNode(float globalHeading) => _pendingActions.Append(MovementType.TurnToHeading, globalHeading);

    /// <summary>Appends a move to the position.</summary>
    // retail: MoveToManager::AddMoveToPositionNode (acclient.c:345119)
    private void AddMoveToPositionNode() => _pendingActions.Append(MovementType.MoveToPosition, 0f);

    /// <summary>Stops the played commands, stops tracking the target, resets.</summary>
    // retail: MoveToManager::CleanUp (acclient.c:345142)
    private void CleanUp()
    {
        MovementParameters p = StopParams();
        if (PhysicsObj is not null)
        {
            if (CurrentCommand != 0)
            {
                _StopMotion(CurrentCommand, ref p);
            }

            if (AuxCommand != 0)
            {
                _StopMotion(AuxCommand, ref p);
            }

            if (TopLevelObjectId != 0 && MovementType != MovementType.Invalid)
            {
                PhysicsObj.ClearTarget();
            }
        }

        InitializeLocalVariables();
    }

    /// <summary>Cleans up and stops the object completely (the move-to ended with <paramref name="status"/>).</summary>
    // retail: MoveToManager::CleanUpAndCallWeenie (acclient.c:345170)
    private void CleanUpAndCallWeenie(MotionError status)
    {
        CleanUp();
        LastResult = status;
        PhysicsObj?.StopCompletelyUnchecked();
    }

    /// <summary>Cancels a running move-to with <paramref name="error"/>: drops every step, cleans up, stops the object
    /// completely. Nothing happens when no move-to runs.</summary>
    // retail: MoveToManager::CancelMoveTo (acclient.c:345296)
    internal void CancelMoveTo(MotionError error)
    {
        if (MovementType == MovementType.Invalid)
        {
            return;
        }

        _pendingActions.Clear();
        CleanUp();
        LastResult = error;
        PhysicsObj?.StopCompletelyUnchecked();
    }

    /// <summary>The parameters every stop and correcting command is played with: retail's defaults with the move-to's hold
    /// key, without <see cref="MovementParameterFlags.CancelMoveTo"/>.</summary>
    private MovementParameters StopParams()
    {
        var p = new MovementParameters { HoldKeyToApply = _movementParams.HoldKeyToApply };
        p.Flags &= ~MovementParameterFlags.CancelMoveTo;
        return p;
    }

    /// <summary>Plays <paramref name="motion"/> as an interpreted motion after the interpreter's adjustment (which rewrites
    /// the speed of <paramref name="p"/> in place, as retail).</summary>
    // retail: MoveToManager::_DoMotion (acclient.c:344752)
    private MotionError _DoMotion(MotionCommand motion, ref MovementParameters p)
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            return MotionError.NoPhysicsObject;
        }

        if (obj.GetOrCreateMotionInterpreter() is not MotionInterp minterp)
        {
            return MotionError.NoMotionInterpreter;
        }

        minterp.AdjustMotion(ref motion, ref p.Speed, p.HoldKeyToApply);
        return minterp.DoInterpretedMotionUnchecked(motion, p);
    }

    /// <summary>Stops <paramref name="motion"/> as an interpreted motion after the interpreter's adjustment.</summary>
    // retail: MoveToManager::_StopMotion (acclient.c:344792)
    private MotionError _StopMotion(MotionCommand motion, ref MovementParameters p)
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            return MotionError.NoPhysicsObject;
        }

        if (obj.GetOrCreateMotionInterpreter() is not MotionInterp minterp)
        {
            return MotionError.NoMotionInterpreter;
        }

        minterp.AdjustMotion(ref motion, ref p.Speed, p.HoldKeyToApply);
        return minterp.StopInterpretedMotionUnchecked(motion, p);
    }

    /// <summary>Distance to the target: between the two cylinders with <see cref="MovementParameterFlags.UseSpheres"/>,
    /// else between the origins; float.MaxValue with no object.</summary>
    // retail: MoveToManager::GetCurrentDistance (acclient.c:344855)
    internal double GetCurrentDistance()
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            return float.MaxValue;
        }

        if ((_movementParams.Flags & MovementParameterFlags.UseSpheres) != 0)
        {
            float h2 = SoughtObjectHeight;
            float r2 = SoughtObjectRadius;
            float h1 = obj.Height;
            float r1 = obj.Radius;
            return Position.CylinderDistance(r1, h1, obj.Position, r2, h2, CurrentTargetPosition);
        }

        return obj.Position.DistanceInDouble(CurrentTargetPosition);
    }

    /// <summary>
    /// False when, more than a second after the last check, the distance closed (or, moving away, opened) by less than
    /// 0.25 m/s since that check, or since the start; else true (a passing check becomes the new last check).
    /// </summary>
    // retail: MoveToManager::CheckProgressMade (acclient.c:344832)
    internal bool CheckProgressMade(float currDistance)
    {
        double now = CurTime;
        double dt = now - PreviousDistanceTime;
        if (dt > ProgressCheckInterval)
        {
            bool away = MovingAway;
            double closed = away ? (double)currDistance - PreviousDistance : (double)PreviousDistance - currDistance;
            if (closed / dt < MinProgressRate)
            {
                return false;
            }

            PreviousDistance = currDistance;
            PreviousDistanceTime = now;
            double sinceStart = !away ? (double)OriginalDistance - currDistance : (double)currDistance - OriginalDistance;
            if (sinceStart / (now - OriginalDistanceTime) < MinProgressRate)
            {
                return false;
            }
        }

        return true;
    }
}
