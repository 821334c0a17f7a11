// PhysicsObj — the object tick: update_object, UpdateObjectInternal and its steps, UpdatePositionInternal.
using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
    /// <summary>
    /// The per-frame update: the bail-outs, the 96 m player gate, then the object's elapsed time cut into steps by the world's
    /// <see cref="PhysicsProfile"/>. Normally run by <see cref="PhysicsWorld.UseTime"/>; callable directly after
    /// <see cref="PhysicsWorld.SetCurrentTime"/>.
    /// </summary>
    // retail: CPhysicsObj::update_object (acclient.c:323080)
    internal void UpdateObject()
    {
        // non-retail: a direct call on a dormant object wakes it first, so that it reads and keeps retail's bookkeeping (the
        // scene visits only awake objects, for which this does nothing)
        Touch();
        if (Parent is not null || CellId == 0 || (_state & PhysicsState.Frozen) != 0)
        {
            _transientState &= ~TransientState.Active;
            return;
        }

        PhysicsWorld world = World;
        PhysicsObj? player = world.Player;
        if (player is not null)
        {
            Vector3 pv = player._position.GetOffset(_position);
            PlayerVector = pv;
            double d = VectorMath.Magnitude(pv);
            PlayerDistance = (float)d;
            if (d > PhysicsGlobals.PlayerActivityDistance && world.ObjectMaintenanceActive)
            {
                _transientState &= ~TransientState.Active;
            }
            else
            {
                SetActiveInternal(true);
            }
        }

        // The profile's slicing (retail: EPSILON gate, MaxQuantum slices, remainder above MinQuantum; ACE: 1/30 s gate that
        // keeps accumulating time, 0.1 s slices). See QuantumSlicer.
        double start = UpdateTime;
        // non-retail: the pose this update starts from, for render interpolation (PhysicsObj.RenderPose.cs)
        Position startPose = _position;
        bool placedBefore = BeginPoseRecord();
        world.PhysicsTime = start;
        var slicer = new QuantumSlicer(world.Profile, start, world.CurrentTime);
        // non-retail: a callback that removed the object from its world ends its update
        while (!RemovedFromWorld && slicer.Next(out double quantum))
        {
            world.PhysicsTime = slicer.Time;
            UpdateObjectInternal((float)quantum);
        }

        UpdateTime = slicer.EndTime(start);
        EndPoseRecord(startPose, start, placedBefore);
    }

    /// <summary>One simulation step of <paramref name="quantum"/> seconds. Active: the next position
    /// (<see cref="BeginStep"/>), the move there (<see cref="MoveToNextPosition"/>: a sweep and its commit, or the frame
    /// alone), the managers (<see cref="UseManagers"/>); then, active or not, particles and scripts.</summary>
    // retail: CPhysicsObj::UpdateObjectInternal (acclient.c:322718)
    internal void UpdateObjectInternal(float quantum)
    {
        // non-retail: the optional step observer (tests, diagnostics)
        World.StepObserver?.OnStep(this, quantum, World.PhysicsTime);
        // non-retail: the observer removed the object from its world: the step ends here
        if (RemovedFromWorld)
        {
            return;
        }

        if ((_transientState & TransientState.Active) != 0)
        {
            if (CellId == 0)
            {
                return;
            }

            BeginStep(quantum, out Position newPos);
            // non-retail: a hook removed the object from its world: no sweep, no commit, no shadows
            if (RemovedFromWorld)
            {
                return;
            }

            MoveToNextPosition(ref newPos, quantum);
            // non-retail: a collision listener removed the object from its world: its step ends here (its managers would act
            // on an object that refuses every mutator). The commit's shadow update tests only CellId for it.
            if (RemovedFromWorld)
            {
                return;
            }

            UseManagers();
        }

        UpdateParticlesAndScripts();
    }

    /// <summary>The step's start: the ethereal check, the jump flag cleared, and the next position built in the object's cell
    /// (<see cref="UpdatePositionInternal"/>: root motion, position manager, integration, hooks).</summary>
    // retail part: the first lines of the active branch of CPhysicsObj::UpdateObjectInternal (acclient.c line 322718)
    private void BeginStep(float quantum, out Position newPos)
    {
        if ((_transientState & TransientState.CheckEthereal) != 0)
        {
            SetEtherealInternal(false);
        }

        JumpedThisFrame = false;
        newPos = new(_position.ObjCellId, Frame.Identity);
        UpdatePositionInternal(quantum, ref newPos.Frame);
    }

    /// <summary>The move to <paramref name="newPos"/>: an object with collision spheres that moved turns along its path (AlignPath,
    /// Sledding) and is swept there (<see cref="SweepAndCommit"/>); one that did not move, or has no spheres, keeps its origin
    /// and takes the new orientation (<see cref="StayInPlace"/>).</summary>
    // retail part: the sphere branch of CPhysicsObj::UpdateObjectInternal (acclient.c line 322718)
    private void MoveToNextPosition(ref Position newPos, float quantum)
    {
        IPartArray? parts = _partArray;
        if (parts is null || (parts is SimplePartArray simple ? simple.NumSpheres : parts.NumSpheres) == 0)
        {
            // No collision spheres: retail keeps the origin and takes only the new orientation.
            if (Movement is null && (_transientState & TransientState.OnWalkable) != 0)
            {
                _transientState &= ~TransientState.Active;
            }

            StayInPlace(ref newPos.Frame);
            return;
        }

        if (VectorMath.AreEqual(newPos.Frame.Origin, _position.Frame.Origin, PhysicsGlobals.Epsilon))
        {
            StayInPlace(ref newPos.Frame);
            return;
        }

        if ((_state & PhysicsState.AlignPath) != 0)
        {
            Vector3 o = newPos.Frame.Origin;
            Vector3 p = _position.Frame.Origin;
            Vector3 diff = VectorMath.Normalize(new Vector3(o.X - p.X, o.Y - p.Y, o.Z - p.Z));
            newPos.Frame.SetVectorHeading(diff);
        }
        else if ((_state & PhysicsState.Sledding) != 0 && !VectorMath.IsZero(_velocity))
        {
            newPos.Frame.SetHeading((float)VelocityHeading(_velocity));
        }

        SweepAndCommit(ref newPos, quantum);
    }

    /// <summary>The sweep to <paramref name="newPos"/> and its commit, by the world's sweep (<see cref="CollisionSweep.SweepStep"/>
    /// answers whether it moved the object); a failed sweep keeps the origin.</summary>
    // retail part: transit = transition(...); SetPositionInternal(transit) of CPhysicsObj::UpdateObjectInternal (acclient.c line 322718)
    private void SweepAndCommit(ref Position newPos, float quantum)
    {
        // non-retail: a scene without SceneEffects.Collision moves freely (retail: the transition)
        CollisionSweep sweep = (World.Effects & SceneEffects.Collision) != 0 ? World.Sweep : FreeSpaceSweep.Instance;
        // retail: transit = transition(...); SetPositionInternal(transit). The retail sweep hands its
        // transition to the commit itself; any other sweep hands over its result.
        if (!sweep.SweepStep(this, newPos, quantum))
        {
            StayInPlace(ref newPos.Frame);
        }
    }

    /// <summary>The step's sweep ended at <paramref name="transit"/> (held in <paramref name="sweep"/>'s pool): the velocity it
    /// caused is cached and the transition committed, collisions and shadows with it.</summary>
    // retail part: the velocity and SetPositionInternal(transit) of CPhysicsObj::UpdateObjectInternal (acclient.c line 322718)
    internal void CommitStep(RetailSweep sweep, Transition transit, float quantum)
    {
        CachedVelocity = DivideByQuantum(_position.GetOffset(transit.SpherePath.CurrPos), quantum);
        CommitTransitionInternal(sweep, transit);
    }

    /// <summary>The step's sweep ended at <paramref name="result"/> (a sweep without a transition): the velocity it caused is
    /// cached and the result committed.</summary>
    // retail part: the velocity and SetPositionInternal(transit) of CPhysicsObj::UpdateObjectInternal (acclient.c line 322718)
    internal void CommitStep(in TransitionResult result, float quantum)
    {
        CachedVelocity = DivideByQuantum(_position.GetOffset(result.CurrentPosition), quantum);
        CommitTransitionInternal(result);
    }

    /// <summary>The object keeps its origin and takes the new frame's orientation, with no velocity.</summary>
    // retail part: the set_frame branches of CPhysicsObj::UpdateObjectInternal (acclient.c line 322718)
    private void StayInPlace(ref Frame newFrame)
    {
        newFrame.Origin = _position.Frame.Origin;
        StoreStepFrame(ref newFrame);
        CachedVelocity = Vector3.Zero;
    }

    /// <summary>The managers after the move: detection, targeting, movement and the part array's movement, then the position
    /// manager.</summary>
    // retail part: the managers' lines of CPhysicsObj::UpdateObjectInternal (acclient.c line 322718)
    private void UseManagers()
    {
        SceneEffects fx = World.Effects;
        // non-retail: the scene's declared effects (retail runs all four managers)
        if ((fx & SceneEffects.RootMotion) != 0)
        {
            DetectionManager?.CheckDetection();
            TargetManager?.HandleTargetting();
            Movement?.UseTime();
            HandlePartArrayMovement();
        }

        // non-retail: the scene's declared effects (retail runs the position manager)
        if ((fx & SceneEffects.Interpolation) != 0)
        {
            PositionManager?.UseTime();
        }
    }

    /// <summary>Particles and scripts, every step, active or not.</summary>
    // retail part: the last lines of CPhysicsObj::UpdateObjectInternal (acclient.c line 322718)
    private void UpdateParticlesAndScripts()
    {
        // non-retail: the scene's declared effects (retail runs the particle and script managers)
        if ((World.Effects & SceneEffects.ParticlesAndScripts) != 0)
        {
            ParticleManager?.UpdateParticles();
            ScriptManager?.UpdateScripts();
        }
    }

    /// <summary>Builds the step's new frame: root motion, contact scaling, position-manager adjustment, combine, physics,
    /// then the hooks.</summary>
    // retail: CPhysicsObj::UpdatePositionInternal (acclient.c:319988)
    internal void UpdatePositionInternal(float quantum, ref Frame newFrame)
    {
        Frame offset = Frame.Identity;
        SceneEffects fx = World.Effects;
        if ((_state & PhysicsState.Hidden) == 0)
        {
            // non-retail: the scene's declared effects (retail runs the part array's root motion)
            if ((fx & SceneEffects.RootMotion) != 0)
            {
                UpdatePartArray(quantum, ref offset);
            }

            Vector3 o = offset.Origin;
            if ((_transientState & TransientState.OnWalkable) != 0)
            {
                double s = Scale;
                offset.Origin = new Vector3((float)(o.X * s), (float)(o.Y * s), (float)(o.Z * s));
            }
            else
            {
                offset.Origin = new Vector3((float)(o.X * 0.0), (float)(o.Y * 0.0), (float)(o.Z * 0.0));
            }

            // non-retail: root motion bounded (see BoundRootMotion), so no part array or animation data makes a Tick throw
            offset.Origin = BoundRootMotion(offset.Origin);
        }

        // non-retail: the scene's declared effects (retail runs the position manager's adjust_offset)
        if ((fx & SceneEffects.Interpolation) != 0)
        {
            PositionManager?.AdjustOffset(ref offset, quantum);
        }

        // non-retail: fidelity switch (remote extrapolation); does nothing under the retail profile
        ApplyExtrapolation(ref offset, quantum);
        // non-retail: fidelity switches (arithmetic, renormalisation); the retail profile runs newFrame.Combine(_position.Frame, offset)
        CombineForProfile(ref newFrame, offset);
        if ((_state & PhysicsState.Hidden) == 0)
        {
            UpdatePhysicsInternal(quantum, ref newFrame);
        }

        // non-retail: the scene's declared effects (retail processes the hooks)
        if ((fx & SceneEffects.Hooks) != 0)
        {
            ProcessHooks();
        }
    }

    /// <summary>The longest root motion one step takes: <see cref="PhysicsGlobals.MaxVelocity"/> ×
    /// <see cref="PhysicsGlobals.MaxQuantum"/> = 10 m (0x41200000).</summary>
    internal const float MaxRootMotionPerStep = (float)(PhysicsGlobals.MaxVelocity * PhysicsGlobals.MaxQuantum);

    // non-retail: retail applies whatever offset the sequence produced. A non-finite offset (NaN survives the airborne × 0)
    // is dropped and one longer than MaxRootMotionPerStep is shortened along its direction: beyond that the sweep refuses
    // the step (192 m, the position domain) and Tick would throw. Real root motion (a run: 11.33 m/s × 0.2 s = 2.3 m) is
    // far inside the bound and passes unchanged.
    internal static Vector3 BoundRootMotion(Vector3 o)
    {
        double lengthSq = (double)o.X * o.X + (double)o.Y * o.Y + (double)o.Z * o.Z;
        if (lengthSq <= (double)MaxRootMotionPerStep * MaxRootMotionPerStep)
        {
            return o;
        }

        if (!double.IsFinite(lengthSq))
        {
            return Vector3.Zero;
        }

        double k = MaxRootMotionPerStep / Math.Sqrt(lengthSq);
        return new Vector3((float)(o.X * k), (float)(o.Y * k), (float)(o.Z * k));
    }

    // retail: Vector3::operator/ (acclient.c:146865): x uses the double reciprocal, y and z its float rounding.
    private static Vector3 DivideByQuantum(Vector3 v, float quantum)
    {
        double inv = 1.0 / quantum;
        float invF = (float)inv;
        return new Vector3((float)(inv * v.X), (float)((double)invF * v.Y), (float)((double)invF * v.Z));
    }

    // retail: AC1Legacy::Vector3::get_heading (acclient.c:148166): heading of (x, y, 0), 0 when too small.
    private static double VelocityHeading(Vector3 v)
    {
        Vector3 n = new(v.X, v.Y, 0f);
        if (VectorMath.NormalizeCheckSmall(ref n))
        {
            return 0.0;
        }

        return HeadingMath.CompassFromAtan2(Math.Atan2(n.Y, n.X));
    }

    // The step's shortcuts that keep retail's bits: the rotation of a repeated omega·dt, the store of the step's frame, and the
    // direct calls into the built-in part array.

    // The rotation (Frame::grotate's axis-angle quaternion) of the last omega·dt this object turned by, keyed by its bits:
    // with constant omega and step the displacement repeats, and the square root, division, sine and cosine are skipped.
    // The rotation is a function of the displacement's bits alone, so a hit gives what recomputing would.
    private int _rotationKeyX, _rotationKeyY, _rotationKeyZ;
    private bool _rotationKnown;
    private AxisAngle _rotation;

    /// <summary>The rotation of <paramref name="w"/> (|w|² at least EPSILON²), from the one-entry cache when w repeats.</summary>
    internal ref readonly AxisAngle StepRotation(Vector3 w)
    {
        int x = BitConverter.SingleToInt32Bits(w.X);
        int y = BitConverter.SingleToInt32Bits(w.Y);
        int z = BitConverter.SingleToInt32Bits(w.Z);
        if (!_rotationKnown || x != _rotationKeyX || y != _rotationKeyY || z != _rotationKeyZ)
        {
            _rotationKnown = AxisAngle.TryCreate(w, out _rotation);
            _rotationKeyX = x;
            _rotationKeyY = y;
            _rotationKeyZ = z;
        }

        return ref _rotation;
    }

    /// <summary>
    /// <see cref="SetFrame"/> for the frame a step has just built (the object is awake: <see cref="UpdateObject"/> touched
    /// it): the same checks, repair and stores, without the wake test and the extra copies, and with the built-in part
    /// array's store called directly.
    /// </summary>
    /// <exception cref="ArgumentException">The origin is NaN or infinite (state unchanged), as <see cref="SetFrame"/>.</exception>
    // retail: CPhysicsObj::set_frame (acclient.c:321327), from UpdateObjectInternal (acclient.c:322718)
    internal void StoreStepFrame(ref Frame frame)
    {
        ThrowIfNotFinite(frame.Origin, nameof(frame));
        if (!frame.IsValid() && frame.IsValidExceptForHeading())
        {
            frame.SetQuaternionRaw(0f, 0f, 0f, 0f);
        }

        _position.Frame = frame;
        SyncObstacleSummary();
        if ((_state & PhysicsState.ParticleEmitter) == 0)
        {
            IPartArray? parts = _partArray;
            if (parts is SimplePartArray simple)
            {
                simple.StoreCheckedFrame(frame);
            }
            else
            {
                parts?.SetFrame(frame);
            }
        }

        UpdateChildrenInternal();
    }

    /// <summary>The part array's root motion for a step (the built-in part array called directly).</summary>
    private void UpdatePartArray(float quantum, ref Frame offset)
    {
        IPartArray? parts = _partArray;
        if (parts is SimplePartArray simple)
        {
            simple.Update(quantum, ref offset);
        }
        else
        {
            parts?.Update(quantum, ref offset);
        }
    }

    /// <summary>The part array's movement notification for a step (the built-in part array called directly).</summary>
    private void HandlePartArrayMovement()
    {
        IPartArray? parts = _partArray;
        if (parts is SimplePartArray simple)
        {
            simple.HandleMovement();
        }
        else
        {
            parts?.HandleMovement();
        }
    }
}
