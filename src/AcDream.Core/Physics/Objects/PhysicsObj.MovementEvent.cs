// PhysicsObj — the MovementEvent entry point: CPhysics::SetObjectMovement, unpack_movement; DoMotion, StopMotion.
using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Physics.Objects;

// Retail's MovementEvent entry point (CPhysics::SetObjectMovement -> CPhysicsObj::unpack_movement), and the object's own
// motion commands (CPhysicsObj::DoMotion / StopMotion).
public sealed partial class PhysicsObj
{
    /// <summary>
    /// Applies a server MovementEvent (0xF74C) to this object as retail's client does (retail
    /// <c>CPhysics::SetObjectMovement</c>, then <c>CPhysicsObj::unpack_movement</c> and
    /// <c>MovementManager::unpack_movement</c>): an event whose movement stamp is not newer than the last one (16-bit
    /// wrap-around order) is dropped; the movement stamp is taken; an event whose server-control stamp is older than the
    /// last one is dropped; the server-control stamp is taken; the server's echo of this client's own player's autonomous
    /// motion is ignored. Otherwise <see cref="LastMoveWasAutonomous"/> becomes the event's flag and the movement is
    /// unpacked: any move-to is cancelled and the object unsticks, it switches to the event's style (the header's) when its
    /// interpreter is in another, then type 0 moves the interpreter to the event's state (sticking to
    /// <see cref="MovementEventMessage.StickToObject"/> when set), types 6 and 7 set the run rate and start a move to the
    /// target object (or, when this world has no such object, to the origin) or to the position, and types 8 and 9 turn to
    /// the object (or to the event's heading) or to the heading.
    /// </summary>
    /// <param name="message">The event, decoded by <see cref="MovementEventDecoder.Decode"/> (or filled by hand). Its
    /// <see cref="MovementEventMessage.ObjectId"/> must be this object's id; the instance stamp is the network layer's
    /// concern (retail's SmartBox queues an event for a newer instance and drops one for an older).</param>
    /// <returns>What happened (<see cref="MovementEventResult"/>).</returns>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="ArgumentException">The message is for another object, its type is not 0, 6, 7, 8 or 9, or (types
    /// 6-9) its parameters are <c>default(MovementParameters)</c>, hold a NaN or infinite number or a speed beyond
    /// ±<see cref="MovementParameters.MaxMoveToSpeed"/>, its heading is not finite, (types 6, 7) its run rate is not in
    /// (0, <see cref="InputLimits.MaxRunRate"/>] or its origin is outside the position domain, or (type 0) its state runs
    /// forward at a speed outside (0, <see cref="InputLimits.MaxRunRate"/>]; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysics::SetObjectMovement (acclient.c:311148)
    public MovementEventResult HandleMovementEvent(MovementEventMessage message)
    {
        ThrowIfRemoved();
        ArgumentNullException.ThrowIfNull(message);
        CheckMovementEvent(message);
        bool isThePlayer = Weenie is IMotionWeenie { IsThePlayer: true };
        if (!NewerEvent(PhysicsTimeStamp.Movement, message.MovementTimestamp))
        {
            return MovementEventResult.Stale;
        }

        ushort stored = _updateTimes[(int)PhysicsTimeStamp.ServerControlledMove];
        ushort received = message.ServerControlTimestamp;
        bool older = Math.Abs(stored - received) > 0x7FFF ? stored < received : received < stored;
        if (older)
        {
            return MovementEventResult.StaleServerControl;
        }

        _updateTimes[(int)PhysicsTimeStamp.ServerControlledMove] = received;
        if (message.Autonomous && isThePlayer)
        {
            return MovementEventResult.OwnAutonomousEcho;
        }

        _lastMoveWasAutonomous = message.Autonomous;
        if (!UnPackMovement(message))
        {
            return MovementEventResult.NotApplied;
        }

        // non-retail: "Applied" means the object will move; without a motion table the result names what is missing
        return PartArray?.MotionPlayer is null ? MovementEventResult.NoMotionTable : MovementEventResult.Applied;
    }

    // Every refusal before anything changes: the entry point's ArgumentException contract.
    private void CheckMovementEvent(MovementEventMessage m)
    {
        if (m.ObjectId != Id)
        {
            throw new ArgumentException(
                $"The MovementEvent is for object 0x{m.ObjectId:X8}, not this object (0x{Id:X8}).", nameof(m));
        }

        switch (m.MovementType)
        {
            case MovementEventType.InterpretedMotion:
                // The state's RunForward speed becomes the run rate, and its actions play after its movement.
                MotionChecks.CheckState(m.State, nameof(m));
                return;
            case MovementEventType.MoveToObject:
            case MovementEventType.MoveToPosition:
                // non-retail: the run rate's domain (InputLimits.MaxRunRate); retail stores any float as my_run_rate
                if (!MotionChecks.IsRunRateInDomain(m.RunRate))
                {
                    throw new ArgumentException(
                        $"The MovementEvent's run rate must be in (0, {InputLimits.MaxRunRate}] (got {m.RunRate}).", nameof(m));
                }

                if (!InputLimits.IsPositionInDomain(m.Origin))
                {
                    throw new ArgumentException("The MovementEvent's origin is outside the position domain.", nameof(m));
                }

                break;
            case MovementEventType.TurnToObject:
                if (!float.IsFinite(m.TurnToObjectHeading))
                {
                    throw new ArgumentException("The MovementEvent's heading must be finite.", nameof(m));
                }

                break;
            case MovementEventType.TurnToHeading:
                break;
            default:
                throw new ArgumentException($"Movement type {(byte)m.MovementType} is not 0, 6, 7, 8 or 9.", nameof(m));
        }

        // The move-to API's own check (MoveToObject, TurnToObject, MoveToPosition, TurnToHeading), here before any stamp.
        m.Parameters.CheckFiniteForMoveTo(nameof(m));
    }

    /// <summary>Creates the movement manager when absent (without its default state, as retail) and unpacks the movement
    /// into it.</summary>
    // retail: CPhysicsObj::unpack_movement (acclient.c:319253)
    private bool UnPackMovement(MovementEventMessage message)
    {
        Touch();
        if (Movement is null)
        {
            // non-retail: retail creates the manager without an interpreter here, and MovementManager::unpack_movement then
            // ignores the event; the interpreter is created (in its default state) so the first event moves the object.
            MakeMovementManager(true);
        }

        return Movement is MovementManager mm && MovementEvent.UnPack(mm, message);
    }

    /// <summary>Starts a motion command as this client's own (retail <c>CPhysicsObj::DoMotion</c>):
    /// <see cref="LastMoveWasAutonomous"/> becomes true, then the movement manager runs it
    /// (<see cref="MovementManager.DoMotion"/>).</summary>
    /// <returns>The motion error; <see cref="MotionError.NoMovementManager"/> when the object has no movement manager yet
    /// or a client's own, nothing started (retail answers 7, <see cref="MotionError.NoMotionTable"/>).</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> or its speed is NaN,
    /// infinite or beyond ±<see cref="InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::DoMotion (acclient.c:317314)
    public MotionError DoMotion(MotionCommand motion, in MovementParameters p)
    {
        ThrowIfRemoved();
        MotionChecks.Check(p);
        Touch();
        _lastMoveWasAutonomous = true;
        // non-retail: retail answers 7 (NoMotionTable) without a movement manager; the error names what is missing
        return Movement is MovementManager mm ? mm.DoMotion(motion, p) : MotionError.NoMovementManager;
    }

    /// <summary>Stops a motion command as this client's own (retail <c>CPhysicsObj::StopMotion</c>):
    /// <see cref="LastMoveWasAutonomous"/> becomes true, then the movement manager stops it
    /// (<see cref="MovementManager.StopMotion"/>).</summary>
    /// <returns>The motion error; <see cref="MotionError.NoMovementManager"/> without a movement manager or with a
    /// client's own (retail answers 7, <see cref="MotionError.NoMotionTable"/>).</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> or its speed is NaN,
    /// infinite or beyond ±<see cref="InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::StopMotion (acclient.c:317353)
    public MotionError StopMotion(MotionCommand motion, in MovementParameters p)
    {
        ThrowIfRemoved();
        MotionChecks.Check(p);
        Touch();
        _lastMoveWasAutonomous = true;
        // non-retail: retail answers 7 (NoMotionTable) without a movement manager; the error names what is missing
        return Movement is MovementManager mm ? mm.StopMotion(motion, p) : MotionError.NoMovementManager;
    }
}
