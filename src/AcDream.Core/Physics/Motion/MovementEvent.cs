using System;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// Applies a server MovementEvent (message 0xF74C) carrying an interpreted motion state to a remote object, as retail's
/// handler does: <c>CPhysicsObj::unpack_movement</c> -> <c>MovementManager::unpack_movement</c>, movement type 0
/// (acclient.c:339491) -> <c>MovementManager::move_to_interpreted_state</c> -> <c>CMotionInterp::move_to_interpreted_state</c>.
/// The object then walks, runs, side-steps and turns between its position updates while the interpolation manager
/// corrects the drift.
/// </summary>
public static class MovementEvent
{
    /// <summary>
    /// Applies <paramref name="state"/> to <paramref name="obj"/>: cancels its move-to and unsticks it, switches to the
    /// state's style if it differs, moves the interpreter to the state (the motion table plays it), sticks to
    /// <paramref name="stickToObject"/> when nonzero, and records the standing-long-jump flag.
    /// </summary>
    /// <returns>True when applied; false when the object's movement manager is a client's own.</returns>
    /// <exception cref="ArgumentNullException">An argument is null (nothing changes).</exception>
    /// <remarks>Retail ignores the event while the object has no interpreter yet; here one is created (in its default
    /// state) first, which is what retail's object creation has always done by the time a MovementEvent arrives.</remarks>
    // retail: MovementManager::unpack_movement (acclient.c:339491), movement type 0, after InterpretedMotionState::UnPack
    public static bool ApplyInterpretedMotion(PhysicsObj obj, InterpretedMotionState state, uint stickToObject = 0,
                                              bool standingLongJump = false)
    {
        ArgumentNullException.ThrowIfNull(obj);
        ArgumentNullException.ThrowIfNull(state);
        // non-retail: the interpreter is created when absent (retail returns without it)
        if (obj.MakeMovementManager(true) is not MovementManager mm)
        {
            return false;
        }

        MotionInterp m = mm.GetOrCreateMotionInterpreter();
        obj.CancelMoveTo();
        obj.StopSticking();
        if (m.InqStyle() != state.CurrentStyle)
        {
            m.DoMotion(state.CurrentStyle, new MovementParameters());
        }

        mm.MoveToInterpretedState(state);
        if (stickToObject != 0)
        {
            obj.StickToObject(stickToObject);
        }

        m.StandingLongJump = standingLongJump;
        return true;
    }
}
