// PhysicsObj — move-to: MoveToObject, TurnToObject, TurnToHeading, StopCompletely, motions_pending, get_heading.
using System;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Objects;

// The object's side of the move-to manager: the wrappers that look a target up in the world and hand the movement manager
// a request.
public sealed partial class PhysicsObj
{
    /// <summary>
    /// Walks or runs to object <paramref name="objectId"/> of this world and follows it (see
    /// <see cref="Motion.MovementManager.MoveToObject"/>): its radius and height, and the object tracked (the one it is
    /// attached to, else itself), come from the world's object table. The movement manager is created first (in its default
    /// state) when absent; an id the world does not hold does nothing more. Retail <c>CPhysicsObj::MoveToObject</c>.
    /// </summary>
    /// <param name="objectId">The target's id: any value (one the world does not hold moves nothing).</param>
    /// <param name="p">The parameters: every float finite, not <c>default(MovementParameters)</c>.</param>
    /// <remarks>An object whose movement manager is a client's own (<see cref="Seams.IMovementManager"/>) has no move-to
    /// manager: nothing moves.</remarks>
    /// <exception cref="ArgumentException">The parameters are refused; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::MoveToObject (acclient.c:319766)
    public void MoveToObject(uint objectId, in MovementParameters p)
    {
        ThrowIfRemoved();
        p.CheckFiniteForMoveTo(nameof(p));
        Touch();
        MakeMovementManager(true);
        PhysicsObj? found = World.GetObjectById(objectId);
        if (found is null)
        {
            return;
        }

        float height = found.PartArray is not null ? found.PartArray.Height : 0f;
        float radius = found.PartArray is not null ? found.PartArray.Radius : 0f;
        PhysicsObj top = found.Parent ?? found;
        MoveToObjectInternal(objectId, top.Id, radius, height, p);
    }

    /// <summary>Hands the movement manager a move-to-object request (type 6), creating it first when absent.</summary>
    // retail: CPhysicsObj::MoveToObject_Internal (acclient.c:317482)
    internal void MoveToObjectInternal(uint objectId, uint topLevelId, float radius, float height, in MovementParameters p)
    {
        if (MakeMovementManager(true) is not Motion.MovementManager mm)
        {
            return;
        }

        MovementStruct mvs = MovementStruct.Of(MovementType.MoveToObject, p);
        mvs.TopLevelId = topLevelId;
        mvs.Radius = radius;
        mvs.ObjectId = objectId;
        mvs.Height = height;
        mm.PerformMovement(mvs);
    }

    /// <summary>
    /// Turns to face object <paramref name="objectId"/> of this world (see <see cref="Motion.MovementManager.TurnToObject"/>);
    /// the object tracked is the one it is attached to, else itself. An id the world does not hold does nothing. Retail
    /// <c>CPhysicsObj::TurnToObject</c>.
    /// </summary>
    /// <param name="objectId">The target's id: any value.</param>
    /// <param name="p">The parameters: every float finite, not <c>default(MovementParameters)</c>.</param>
    /// <exception cref="ArgumentException">The parameters are refused; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::TurnToObject (acclient.c:319827)
    public void TurnToObject(uint objectId, in MovementParameters p)
    {
        ThrowIfRemoved();
        p.CheckFiniteForMoveTo(nameof(p));
        Touch();
        PhysicsObj? found = World.GetObjectById(objectId);
        if (found is null)
        {
            return;
        }

        PhysicsObj top = found.Parent ?? found;
        TurnToObjectInternal(objectId, top.Id, p);
    }

    /// <summary>Hands the movement manager a turn-to-object request (type 8), creating it first when absent.</summary>
    // retail: CPhysicsObj::TurnToObject_Internal (acclient.c:317532)
    internal void TurnToObjectInternal(uint objectId, uint topLevelId, in MovementParameters p)
    {
        if (MakeMovementManager(true) is not Motion.MovementManager mm)
        {
            return;
        }

        MovementStruct mvs = MovementStruct.Of(MovementType.TurnToObject, p);
        mvs.ObjectId = objectId;
        mvs.TopLevelId = topLevelId;
        mm.PerformMovement(mvs);
    }

    /// <summary>Turns to <see cref="MovementParameters.DesiredHeading"/> (see
    /// <see cref="Motion.MovementManager.TurnToHeading"/>), creating the movement manager first when absent. Retail
    /// <c>CPhysicsObj::TurnToHeading</c>.</summary>
    /// <param name="p">The parameters: every float finite, not <c>default(MovementParameters)</c>.</param>
    /// <exception cref="ArgumentException">The parameters are refused; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::TurnToHeading (acclient.c:319850)
    public void TurnToHeading(in MovementParameters p)
    {
        ThrowIfRemoved();
        p.CheckFiniteForMoveTo(nameof(p));
        Touch();
        if (MakeMovementManager(true) is not Motion.MovementManager mm)
        {
            return;
        }

        mm.PerformMovement(MovementStruct.Of(MovementType.TurnToHeading, p));
    }

    /// <summary>Stops everything: the movement manager's stop-completely request (type 5; its interpreter cancels a running
    /// move-to and stops every motion), when the object has a retail movement manager. Retail
    /// <c>CPhysicsObj::StopCompletely</c>.</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public void StopCompletely()
    {
        ThrowIfRemoved();
        Touch();
        StopCompletelyUnchecked();
    }

    /// <summary>The engine's stop-completely (the move-to manager's), without the removed-object check.</summary>
    // retail: CPhysicsObj::StopCompletely (acclient.c:317392)
    internal void StopCompletelyUnchecked()
    {
        if (Movement is Motion.MovementManager mm)
        {
            mm.PerformMovement(MovementStruct.Of(MovementType.StopCompletely, new MovementParameters()));
        }
    }

    /// <summary>True while the motion interpreter has unfinished motions.</summary>
    // retail: CPhysicsObj::motions_pending (acclient.c:315778)
    internal bool MotionsPending() => Movement is Motion.MovementManager mm && mm.MotionsPending();

    /// <summary>True when the last move was this client's own (<see cref="LastMoveWasAutonomous"/>).</summary>
    // retail: CPhysicsObj::movement_is_autonomous (acclient.c:315830)
    internal bool MovementIsAutonomous() => _lastMoveWasAutonomous;

    /// <summary>The compass heading the object faces, degrees (the x87 double of <c>Frame::get_heading</c>).</summary>
    // retail: CPhysicsObj::get_heading (acclient.c:318634)
    internal double GetHeading() => _position.Frame.Heading;

    /// <summary>The position manager, created when absent.</summary>
    // retail: CPhysicsObj::get_position_manager (acclient.c:319308)
    internal PositionManager GetPositionManager() => MakePositionManager();

    /// <summary>Unsticks (the engine's <c>unstick_from_object</c>; <see cref="StopSticking"/> is the public one).</summary>
    internal void UnstickFromObject() => PositionManager?.StopSticking();

    /// <summary>Turns the object to <paramref name="degrees"/> (the engine's <c>set_heading</c>; the heading is finite).</summary>
    internal void SetHeadingUnchecked(float degrees)
    {
        Touch();
        Spatial.Frame f = _position.Frame;
        f.SetHeading(degrees);
        SetFrameInternal(f);
    }
}
