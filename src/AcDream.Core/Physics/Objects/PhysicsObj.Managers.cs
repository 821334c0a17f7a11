// PhysicsObj — the managers: MakePositionManager, InterpolateTo, ConstrainTo, GetRadius, GetStepUpHeight, …; the setup check.
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
    /// <summary>Creates the position manager if absent and activates a non-static object (retail <c>MakePositionManager</c>).</summary>
    /// <returns>The position manager.</returns>
    /// <exception cref="System.InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::MakePositionManager (acclient.c:317430)
    public PositionManager MakePositionManager()
    {
        ThrowIfRemoved();
        Touch();
        PositionManager ??= new PositionManager(this);
        ActivateIfNotStatic();
        return PositionManager;
    }

    /// <summary>The motion interpreter of the object's movement manager, or null while it has none (no movement manager,
    /// or one that has not created its interpreter yet). Never creates anything: <see cref="GetOrCreateMotionInterpreter"/>
    /// does.</summary>
    public IMotionInterpreter? MotionInterpreter => Movement?.MotionInterpreter;

    /// <summary>
    /// The motion interpreter, creating the movement manager (in its default state) and its interpreter first when absent
    /// (retail <c>CPhysicsObj::get_minterp</c>: <c>MovementManager::Create</c> + <c>EnterDefaultState</c>, then
    /// activation). The world's <see cref="PhysicsWorld.MovementManagerFactory"/> creates the movement manager, or the
    /// retail <see cref="Motion.MovementManager"/> when unset. Give every walking creature one (the world's player gets one
    /// when it is set).
    /// </summary>
    /// <returns>The interpreter: a <see cref="Motion.MotionInterp"/> for the retail movement manager; whatever a client's own
    /// movement manager answers (<see cref="IMovementManager.GetOrCreateMotionInterpreter"/>, possibly null).</returns>
    /// <exception cref="System.InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::get_minterp (acclient.c:319279)
    public IMotionInterpreter? GetOrCreateMotionInterpreter()
    {
        ThrowIfRemoved();
        if (Movement is null)
        {
            MakeMovementManager(true);
        }

        return Movement!.GetOrCreateMotionInterpreter();
    }

    /// <summary>True while the movement manager runs a move-to.</summary>
    // retail: CPhysicsObj::IsMovingTo (acclient.c:315821)
    public bool IsMovingTo() => Movement is not null && Movement.IsMovingTo();

    /// <summary>Queues an interpolation towards <paramref name="p"/> (creating the position manager).</summary>
    /// <param name="p">The target: the position domain of <see cref="StorePosition"/> (unit quaternion; origin within
    /// ±65,536 m, outdoor x, y in [−192, 384]).</param>
    /// <param name="keepHeading">True to keep the object's heading.</param>
    /// <exception cref="System.ArgumentException">The position is outside that domain; checked before the position manager
    /// is created (state unchanged).</exception>
    /// <exception cref="System.InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::InterpolateTo (acclient.c:317580)
    public void InterpolateTo(in Position p, bool keepHeading)
    {
        ThrowIfRemoved();
        InputLimits.ThrowIfOutside(p, nameof(p));
        Touch();

        MakePositionManager().InterpolateTo(p, keepHeading);
    }

    /// <summary>Stops interpolating.</summary>
    /// <exception cref="System.InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::StopInterpolating (acclient.c:315836)
    public void StopInterpolating()
    {
        ThrowIfRemoved();
        Touch();
        PositionManager?.StopInterpolating();
    }

    /// <summary>True while interpolation nodes are queued (retail <c>CPhysicsObj::IsInterpolating</c>).</summary>
    // retail: CPhysicsObj::IsInterpolating (acclient.c:315846)
    public bool IsInterpolating => PositionManager is not null && PositionManager.IsInterpolating;

    /// <summary>Constrains the object near <paramref name="p"/> (creating the position manager).</summary>
    /// <param name="p">The anchor: the position domain of <see cref="StorePosition"/>.</param>
    /// <param name="startDistance">Distance at which the constraint starts to act, metres: finite.</param>
    /// <param name="maxDistance">Distance at which it holds fully, metres: finite.</param>
    /// <exception cref="System.ArgumentException">The position is outside that domain or a distance is not finite; checked
    /// before the position manager is created (state unchanged).</exception>
    /// <exception cref="System.InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::ConstrainTo (acclient.c:317590)
    public void ConstrainTo(in Position p, float startDistance, float maxDistance)
    {
        ThrowIfRemoved();
        InputLimits.ThrowIfOutside(p, nameof(p));
        if (!float.IsFinite(startDistance) || !float.IsFinite(maxDistance))
        {
            throw new System.ArgumentException("Constraint distances must be finite.", nameof(maxDistance));
        }

        Touch();

        MakePositionManager().ConstrainTo(p, startDistance, maxDistance);
    }

    /// <summary>True when the constraint manager holds the object fully
    /// (retail <c>CPhysicsObj::IsFullyConstrained</c>).</summary>
    // retail: CPhysicsObj::IsFullyConstrained (acclient.c:315932)
    public bool IsFullyConstrained => PositionManager is not null && PositionManager.IsFullyConstrained;

    /// <summary>Id of the object this one sticks to, or 0 (retail <c>CPhysicsObj::get_sticky_object_id</c>).</summary>
    // retail: CPhysicsObj::get_sticky_object_id (acclient.c:315807)
    public uint StickyObjectId => PositionManager?.StickyObjectId ?? 0u;

    /// <summary>Stops sticking to an object (retail <c>CPhysicsObj::unstick_from_object</c>).</summary>
    /// <exception cref="System.InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::unstick_from_object (acclient.c:315797)
    public void StopSticking()
    {
        ThrowIfRemoved();
        Touch();
        PositionManager?.StopSticking();
    }

    /// <summary>True when the object is the world's player.</summary>
    public bool IsPlayer => World.Player == this;

    /// <summary>Distance beyond which an interpolating object blips, metres: player 25 indoors / 100 outdoors, others 20 / 100
    /// (retail <c>CPhysicsObj::GetAutonomyBlipDistance</c>).</summary>
    // retail: CPhysicsObj::GetAutonomyBlipDistance (acclient.c:315860)
    public double AutonomyBlipDistance
    {
        get
        {
            bool indoor = (_position.ObjCellId & 0xFFFFu) >= 0x100u;
            if (IsPlayer)
            {
                return indoor ? 25.0 : 100.0;
            }

            return indoor ? 20.0 : 100.0;
        }
    }

    /// <summary>Distance at which a constraint starts to act, metres: 5 indoors / 10 outdoors
    /// (retail <c>CPhysicsObj::GetStartConstraintDistance</c>).</summary>
    // retail: CPhysicsObj::GetStartConstraintDistance (acclient.c:315884)
    public double StartConstraintDistance => (_position.ObjCellId & 0xFFFFu) >= 0x100u ? 5.0 : 10.0;

    /// <summary>Distance at which a constraint holds fully, metres: 20 indoors / 50 outdoors
    /// (retail <c>CPhysicsObj::GetMaxConstraintDistance</c>).</summary>
    // retail: CPhysicsObj::GetMaxConstraintDistance (acclient.c:315908)
    public double MaxConstraintDistance => (_position.ObjCellId & 0xFFFFu) >= 0x100u ? 20.0 : 50.0;

    /// <summary>Bounding radius, metres: the part array's (<see cref="Parts.IPartArray.Radius"/>), 0 without one. Retail
    /// <c>CPhysicsObj::GetRadius</c>, which hands back the setup's radius times the scale in x87's st0; the callers that
    /// store it as a float get this value.</summary>
    // retail: CPhysicsObj::GetRadius (acclient.c:315672)
    public float Radius => PartArray is not null ? PartArray.Radius : 0f;

    // retail: CPhysicsObj::GetRadius (acclient.c:315672) as DetectionManager::CheckDetection (acclient.c:327020) uses it: the
    // unrounded product of CPartArray::GetRadius (an AnimatedPartArray's setup radius times scale.z), added in double; a part
    // array whose radius is a plain float (SimplePartArray, a client's own) hands back that float
    internal double RadiusInDouble => PartArray switch
    {
        null => 0.0,
        AnimatedPartArray animated => animated.RadiusInDouble,
        var parts => parts.Radius,
    };

    /// <summary>Height, metres: the part array's (<see cref="Parts.IPartArray.Height"/>), 0 without one. Retail
    /// <c>CPhysicsObj::GetHeight</c> (the part array's float).</summary>
    // retail: CPhysicsObj::GetHeight (acclient.c:315686)
    public float Height => PartArray is not null ? PartArray.Height : 0f;

    /// <summary>Step-up height, metres: the part array's (<see cref="Parts.IPartArray.StepUpHeight"/>), 0 without one. Retail
    /// <c>CPhysicsObj::GetStepUpHeight</c> (the part array's float).</summary>
    // retail: CPhysicsObj::GetStepUpHeight (acclient.c:315700)
    public float StepUpHeight => PartArray is not null ? PartArray.StepUpHeight : 0f;

    /// <summary>Step-down height, metres: the part array's (<see cref="Parts.IPartArray.StepDownHeight"/>), 0 without one. Retail
    /// <c>CPhysicsObj::GetStepDownHeight</c> (the part array's float).</summary>
    // retail: CPhysicsObj::GetStepDownHeight (acclient.c:315714)
    public float StepDownHeight => PartArray is not null ? PartArray.StepDownHeight : 0f;

    private void ActivateIfNotStatic()
    {
        if ((_state & PhysicsState.Static) != 0)
        {
            return;
        }

        if ((_transientState & TransientState.Active) == 0)
        {
            UpdateTime = World.CurrentTime;
        }

        _transientState |= TransientState.Active;
    }

    /// <summary>Cancels the movement manager's move-to with the unstick error (<see cref="StickyManager.UnstickMoveToError"/>).</summary>
    // retail: CPhysicsObj::cancel_moveto (acclient.c:317420)
    internal void CancelMoveTo() => Movement?.CancelMoveTo(StickyManager.UnstickMoveToError);

    // The setup check: what keeps the object from walking (not retail; a client's diagnostic).

    /// <summary>Largest step height that counts as "no Setup" (retail's 0.01 f default, acclient.c:325399).</summary>
    private const float NoSetupStepHeight = 0.0099999998f;

    /// <summary>
    /// What keeps this object from walking, stepping and colliding as a retail creature would: <see cref="ObjectSetupIssues.None"/>
    /// for a creature built from a Setup (<see cref="SimplePartArray(SetupPhysics, int)"/>) with a motion table, with a weenie and a movement manager, entered
    /// into a world over terrain. Cheap; not part of the tick. Read it once the object is in place — after
    /// <see cref="EnterWorld"/> and, for the player, after setting <see cref="World.PhysicsWorld.Player"/> (which gives it its movement
    /// manager); before them it reports <see cref="ObjectSetupIssues.NotInCell"/> and
    /// <see cref="ObjectSetupIssues.NoMovementManager"/> even for a correctly built object. An issue is otherwise silent (the
    /// object does not move, moves at half speed, or takes one step and stops).
    /// </summary>
    public ObjectSetupIssues SetupIssues
    {
        get
        {
            ObjectSetupIssues issues = ObjectSetupIssues.None;
            IPartArray? parts = PartArray;
            if (parts is null)
            {
                issues |= ObjectSetupIssues.NoPartArray;
            }
            else
            {
                if (parts.NumSpheres == 0)
                {
                    issues |= ObjectSetupIssues.NoCollisionSpheres;
                }

                if (parts.MotionPlayer is null && Movement is null or Motion.MovementManager)
                {
                    issues |= ObjectSetupIssues.NoMotionTable;
                }

                if (parts.StepUpHeight <= NoSetupStepHeight || parts.StepDownHeight <= NoSetupStepHeight)
                {
                    issues |= ObjectSetupIssues.NoSetupStepHeights;
                }
            }

            if (Movement is null)
            {
                issues |= ObjectSetupIssues.NoMovementManager;
            }

            if (Weenie is null && Movement is null or Motion.MovementManager)
            {
                issues |= ObjectSetupIssues.NoWeenie;
            }

            if (World.IsFreeSpace)
            {
                issues |= ObjectSetupIssues.FreeSpaceSweep;
            }

            if (CellId == 0)
            {
                issues |= ObjectSetupIssues.NotInCell;
            }

            return issues;
        }
    }
}
