using System;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>
/// Applies server MovementEvents (message 0xF74C) to an object's movement manager as retail's handler does
/// (<c>MovementManager::unpack_movement</c>, acclient.c:339491). The whole retail entry point, with the stale-event checks
/// and every movement type, is <see cref="PhysicsObj.HandleMovementEvent"/>; <see cref="ApplyInterpretedMotion"/> applies a
/// type-0 state built or decoded by hand. The object then walks, runs, side-steps and turns between its position updates
/// while the interpolation manager corrects the drift.
/// </summary>
public static class MovementEvent
{
    /// <summary>
    /// Applies <paramref name="state"/> to <paramref name="obj"/> as a type-0 event whose header style is the state's own
    /// <see cref="InterpretedMotionState.CurrentStyle"/>: cancels its move-to and unsticks it, switches to that style if the
    /// interpreter is in another, moves the interpreter to the state (the motion table plays it), sticks to
    /// <paramref name="stickToObject"/> when nonzero, and records the standing-long-jump flag. No stamps are checked: for
    /// a server's event use <see cref="PhysicsObj.HandleMovementEvent"/>, which also switches to the header's style when
    /// the state carries none.
    /// </summary>
    /// <returns>True when applied; false when the object's movement manager is a client's own.</returns>
    /// <exception cref="ArgumentNullException">An argument is null (nothing changes).</exception>
    /// <exception cref="ArgumentException">The state runs forward (<see cref="MotionCommand.RunForward"/>) at a speed outside
    /// the run rate's domain (0, <see cref="Spatial.InputLimits.MaxRunRate"/>] (nothing changes; the interpreter would take
    /// it as its run rate).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    /// <remarks>Retail ignores the event while the object has no interpreter yet; here one is created (in its default
    /// state) first, which is what retail's object creation has always done by the time a MovementEvent arrives.</remarks>
    // retail: MovementManager::unpack_movement (acclient.c:339491), movement type 0, after InterpretedMotionState::UnPack
    public static bool ApplyInterpretedMotion(PhysicsObj obj, InterpretedMotionState state, uint stickToObject = 0,
                                              bool standingLongJump = false)
    {
        ArgumentNullException.ThrowIfNull(obj);
        ArgumentNullException.ThrowIfNull(state);
        MotionChecks.CheckState(state, nameof(state));
        // non-retail: the interpreter is created when absent (retail returns without it)
        if (obj.MakeMovementManager(true) is not MovementManager mm)
        {
            return false;
        }

        BeginUnPack(mm, obj, state.CurrentStyle);
        MoveToState(mm, obj, state, stickToObject, standingLongJump);
        return true;
    }

    /// <summary>Unpacks a decoded event into <paramref name="mm"/> (its object is the event's): false, as retail, when the
    /// manager has no interpreter or no object.</summary>
    // retail: MovementManager::unpack_movement (acclient.c:339491)
    internal static bool UnPack(MovementManager mm, MovementEventMessage m)
    {
        PhysicsObj? obj = mm.PhysicsObj;
        if (mm.MotionInterpreter is null || obj is null)
        {
            return false;
        }

        // acclient.c:339540-339542: the style is the header's (command_ids[style index]), switched to before the type's
        // data is read; a type-0 state without the style flag keeps the default non-combat style in its own field.
        BeginUnPack(mm, obj, m.Style);
        switch (m.MovementType)
        {
            case MovementEventType.InterpretedMotion:
                MoveToState(mm, obj, m.State, m.StickToObject, m.StandingLongJump);
                return true;
            case MovementEventType.MoveToObject:
                // acclient.c:339564-339578: an object this client does not know is moved to at its origin instead.
                mm.MakeMoveToManager();
                mm.GetOrCreateMotionInterpreter().MyRunRate = m.RunRate;
                if (obj.World.GetObjectById(m.TargetId) is not null)
                {
                    obj.MoveToObject(m.TargetId, m.Parameters);
                }
                else
                {
                    mm.MakeMoveToManager().MoveToPosition(m.Origin, m.Parameters);
                }

                return true;
            case MovementEventType.MoveToPosition:
                mm.MakeMoveToManager();
                mm.GetOrCreateMotionInterpreter().MyRunRate = m.RunRate;
                mm.MakeMoveToManager().MoveToPosition(m.Origin, m.Parameters);
                return true;
            case MovementEventType.TurnToObject:
                // acclient.c:339592-339606: an unknown object is turned to at the event's heading instead.
                mm.MakeMoveToManager();
                if (obj.World.GetObjectById(m.TargetId) is not null)
                {
                    obj.TurnToObject(m.TargetId, m.Parameters);
                }
                else
                {
                    MovementParameters p = m.Parameters;
                    p.DesiredHeading = m.TurnToObjectHeading;
                    mm.MakeMoveToManager().TurnToHeading(p);
                }

                return true;
            case MovementEventType.TurnToHeading:
                mm.MakeMoveToManager().TurnToHeading(m.Parameters);
                return true;
            default:
                return false;
        }
    }

    // acclient.c:339518-339519: cancel the move-to, unstick; 339540-339542: switch to the style when the interpreter is in
    // another.
    private static void BeginUnPack(MovementManager mm, PhysicsObj obj, MotionCommand style)
    {
        MotionInterp m = mm.GetOrCreateMotionInterpreter();
        obj.CancelMoveTo();
        obj.StopSticking();
        if (m.InqStyle() != style)
        {
            m.DoMotion(style, new MovementParameters());
        }
    }

    // acclient.c:339547-339562: case 0.
    private static void MoveToState(MovementManager mm, PhysicsObj obj, InterpretedMotionState state, uint stickToObject,
                                    bool standingLongJump)
    {
        mm.MoveToInterpretedState(state);
        if (stickToObject != 0)
        {
            obj.StickToObject(stickToObject);
        }

        mm.GetOrCreateMotionInterpreter().StandingLongJump = standingLongJump;
    }
}
