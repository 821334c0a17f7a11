// PhysicsObj — the object's state, construction and plain properties: CPhysicsObj (constructor), get_velocity.
using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Scene;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

/// <summary>
/// A simulated object (retail <c>CPhysicsObj</c>, acclient.h:30689; PORTAL/cphysobj/CPhysicsObj.c). It belongs to one
/// <see cref="PhysicsWorld"/>, which owns the clocks and the player the object reads while it updates.
/// </summary>
/// <remarks>
/// <para>The class is split by concern into partial files in this folder; the first line of each <c>PhysicsObj.*.cs</c> names
/// its concern and the retail functions it holds.</para>
/// <para>Optional managers are null when absent and cost nothing. As in retail, an object enters a cell only when it has a
/// part array (<c>CPhysicsObj::enter_cell</c>, acclient.c:318201; <see cref="EnterWorld"/> returns false without one), and
/// update_object does nothing for an object with no cell: give every simulated object an <see cref="IPartArray"/> (e.g.
/// <see cref="SimplePartArray"/>).</para>
/// <para>An object removed from its world (<see cref="PhysicsWorld.RemoveObject"/>) is in no cell, has no transient state
/// and refuses every public mutator (<see cref="InvalidOperationException"/>); its reads stay allowed.</para>
/// </remarks>
public sealed partial class PhysicsObj
{
    internal Position _position;
    internal Vector3 _velocity;
    internal Vector3 _acceleration;
    internal Vector3 _omega;
    internal PhysicsState _state;
    internal TransientState _transientState;
    private float _friction;
    private float _elasticity;
    private float _translucencyOriginal;
    private IPartArray? _partArray;
    private IMovementManager? _movementManager;
    private RareComponents? _rare;

    // retail: CPhysicsObj::CPhysicsObj (acclient.c:319489)
    internal PhysicsObj(PhysicsWorld world, uint id, ulong creationNumber)
    {
        World = world;
        Id = id;
        CreationNumber = creationNumber;
        PlayerVector = new Vector3(0f, 0f, 1f);
        PlayerDistance = float.MaxValue;
        _position = new Position(0, Frame.Identity);
        _elasticity = PhysicsGlobals.DefaultElasticity;
        Translucency = PhysicsGlobals.DefaultTranslucency;
        _translucencyOriginal = PhysicsGlobals.DefaultTranslucency;
        _friction = PhysicsGlobals.DefaultFriction;
        _state = (PhysicsState)PhysicsGlobals.DefaultState;
        MassInv = 1.0f / PhysicsGlobals.DefaultMass;
        Scale = PhysicsGlobals.DefaultScale;
    }

    /// <summary>The world that owns the object.</summary>
    public PhysicsWorld World { get; }

    /// <summary>The object's creation number in its world (0, 1, 2, …): orders objects of equal id (not retail).</summary>
    internal ulong CreationNumber { get; }

    /// <summary>True from creation until the object is removed from its world.</summary>
    internal bool InWorld { get; set; }

    /// <summary>The next object of the lost cell this one waits in (the world's lost-cell table chains them), or null.</summary>
    internal PhysicsObj? LostNext { get; set; }

    /// <summary>True once <see cref="PhysicsWorld.RemoveObject"/> took the object out of its world (for good): a step in
    /// progress stops, and the object never lists itself in a cell again.</summary>
    internal bool RemovedFromWorld { get; set; }

    /// <summary>
    /// True once <see cref="PhysicsWorld.RemoveObject"/> has taken the object out of its world, for good; false from
    /// <see cref="PhysicsWorld.CreateObject"/> until then, whether the object has been placed (<see cref="EnterWorld"/>) or not,
    /// and whether it is in a cell or not (<see cref="CellId"/> 0: not yet placed, or sent to the lost cell).
    /// </summary>
    /// <remarks>A removed object is in no cell, has no transient state, cannot be added back and refuses every public mutator
    /// (<see cref="InvalidOperationException"/>); its reads stay allowed. Read this in a callback that may have removed the
    /// object (a hook, a collision or player listener, the step observer) before acting on it.</remarks>
    public bool IsRemoved => RemovedFromWorld;

    /// <summary>The object's id (retail <c>id</c>).</summary>
    public uint Id { get; }

    /// <summary>Where the object is (retail <c>m_position</c>): cell id and frame.</summary>
    public Position Position => _position;

    /// <summary>Id of the cell the object is in (retail <c>cell</c>, a pointer); 0 when the object is in no cell.</summary>
    public uint CellId { get; private set; }

    /// <summary>Persistent state bits (retail <c>state</c>). Default REPORT_COLLISIONS | GRAVITY | LIGHTING_ON | EDGE_SLIDE.</summary>
    public PhysicsState State => _state;

    /// <summary>Per-frame state bits (retail <c>transient_state</c>).</summary>
    public TransientState TransientState => _scene.Dormancy == Dormancy.Awake ? _transientState : LazyTransientState();

    /// <summary>True when the ACTIVE transient bit is set: the object is simulated.</summary>
    public bool IsActive => (TransientState & TransientState.Active) != 0;

    /// <summary>Velocity in world axes, m/s (retail <c>m_velocityVector</c>). Set with <see cref="SetVelocity"/>.</summary>
    public Vector3 Velocity => _velocity;

    /// <summary>Acceleration in world axes, m/s² (retail <c>m_accelerationVector</c>), normally set by <see cref="CalcAcceleration"/>.</summary>
    public Vector3 Acceleration => _acceleration;

    /// <summary>Angular velocity in world axes, rad/s (retail <c>m_omegaVector</c>). Set with <see cref="SetOmega"/>.</summary>
    public Vector3 Omega => _omega;

    /// <summary>Displacement of the last swept step divided by its duration, m/s (retail <c>cached_velocity</c>);
    /// zero after a step that did not sweep. Retail <c>CPhysicsObj::get_velocity</c> answers it.</summary>
    // retail: CPhysicsObj::get_velocity (acclient.c:318565)
    public Vector3 CachedVelocity { get; private set; }

    /// <summary>Client time of the object's last consumed update, seconds (retail <c>update_time</c>).</summary>
    public double UpdateTime
    {
        get => _scene.Dormancy == Dormancy.Awake ? _scene.UpdateTime : LazyUpdateTime();
        internal set => _scene.UpdateTime = value;
    }

    /// <summary>Offset from the player to this object, metres (retail <c>player_vector</c>; (0, 0, 1) until measured).</summary>
    public Vector3 PlayerVector
    {
        get => _scene.Dormancy == Dormancy.Awake ? _scene.PlayerVector : LazyPlayerVector();
        private set => _scene.PlayerVector = value;
    }

    /// <summary>Distance to the player, metres (retail <c>player_distance</c>; float.MaxValue until measured).</summary>
    public float PlayerDistance
    {
        get => _scene.Dormancy == Dormancy.Awake ? _scene.PlayerDistance : LazyPlayerDistance();
        private set => _scene.PlayerDistance = value;
    }

    /// <summary>Friction coefficient in [0, 1] (retail <c>friction</c>, default 0.95): on walkable ground speed decays as (1 - f)^dt.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is NaN or outside [0, 1] (outside, retail's pow would yield NaN or growth).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public float Friction
    {
        get => _friction;
        set
        {
            ThrowIfRemoved();
            if (!(value >= 0f && value <= 1f))
            {
                throw new ArgumentOutOfRangeException(nameof(value), "Friction must be in [0, 1].");
            }

            _friction = value;
        }
    }

    /// <summary>Elasticity (retail <c>elasticity</c>, default 0.05), used by the collision response.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public float Elasticity
    {
        get => _elasticity;
        set
        {
            ThrowIfRemoved();
            if (!float.IsFinite(value))
            {
                throw new ArgumentOutOfRangeException(nameof(value), "Elasticity must be finite.");
            }

            _elasticity = value;
        }
    }

    /// <summary>Inverse mass, 1/kg (retail <c>massinv</c>, default 1). Retail stores no mass, only its inverse.</summary>
    public float MassInv { get; private set; }

    /// <summary>Uniform scale (retail <c>m_scale</c>, default 1); scales root motion on walkable ground.</summary>
    public float Scale { get; private set; }

    /// <summary>Current translucency (retail <c>translucency</c>); never below <see cref="TranslucencyOriginal"/> once set.</summary>
    public float Translucency { get; private set; }

    /// <summary>Floor of <see cref="Translucency"/> (retail <c>translucencyOriginal</c>).</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public float TranslucencyOriginal
    {
        get => _translucencyOriginal;
        set
        {
            ThrowIfRemoved();
            if (!float.IsFinite(value))
            {
                throw new ArgumentOutOfRangeException(nameof(value), "Translucency must be finite.");
            }

            _translucencyOriginal = value;
        }
    }

    /// <summary>Normal of the contact plane of the last sweep (retail <c>contact_plane.N</c>).</summary>
    public Vector3 ContactPlaneNormal { get; private set; }

    /// <summary>Distance term of the contact plane (retail <c>contact_plane.d</c>).</summary>
    public float ContactPlaneD { get; private set; }

    /// <summary>Cell of the contact plane (retail <c>contact_plane_cell_id</c>).</summary>
    public uint ContactPlaneCellId { get; private set; }

    /// <summary>Sliding normal of the last sweep (retail <c>sliding_normal</c>).</summary>
    public Vector3 SlidingNormal { get; private set; }

    /// <summary>Set when the velocity was changed this frame (retail <c>jumped_this_frame</c>); cleared at each active step.</summary>
    public bool JumpedThisFrame { get; private set; }

    /// <summary>Whether the last move was autonomous (retail <c>last_move_was_autonomous</c>; read by
    /// <c>CPhysicsObj::movement_is_autonomous</c>).</summary>
    /// <exception cref="InvalidOperationException">Set on an object removed from its world.</exception>
    public bool LastMoveWasAutonomous
    {
        get => _lastMoveWasAutonomous;
        set
        {
            ThrowIfRemoved();
            _lastMoveWasAutonomous = value;
        }
    }

    private bool _lastMoveWasAutonomous;

    /// <summary>The part array and animation seam, or null (retail <c>part_array</c>).</summary>
    /// <remarks>A <see cref="SimplePartArray"/> belongs to one object at a time; it is released when its object takes another
    /// part array (or null).</remarks>
    /// <exception cref="ArgumentException">The value is a <see cref="SimplePartArray"/> or an <see cref="AnimatedPartArray"/>
    /// that belongs to another object; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public IPartArray? PartArray
    {
        get => _partArray;
        set
        {
            ThrowIfRemoved();
            // non-retail: retail's part arrays are made per object; a shared one would record two objects' frames and cells
            if (value is SimplePartArray { Owner: not null } taken && taken.Owner != this)
            {
                throw new ArgumentException("This SimplePartArray belongs to another object.", nameof(value));
            }

            if (value is AnimatedPartArray { Owner: not null } animatedTaken && animatedTaken.Owner != this)
            {
                throw new ArgumentException("This AnimatedPartArray belongs to another object.", nameof(value));
            }

            Touch();
            if (_partArray is SimplePartArray previous && !ReferenceEquals(previous, value))
            {
                previous.Owner = null;
            }
            else if (_partArray is AnimatedPartArray previousAnimated && !ReferenceEquals(previousAnimated, value))
            {
                previousAnimated.Owner = null;
            }

            _partArray = value;
            if (value is SimplePartArray simple)
            {
                simple.Owner = this;
            }
            else if (value is AnimatedPartArray animated)
            {
                animated.Owner = this;
            }

            SyncObstacleSummary();
        }
    }

    /// <summary>The object's movement manager, or null (retail <c>movement_manager</c>): the retail
    /// <see cref="Motion.MovementManager"/> (<c>obj.Movement is MovementManager mm</c>, or <see cref="Motion.MovementManager.Of"/>)
    /// or a client's own <see cref="IMovementManager"/>. Null until <see cref="MakeMovementManager"/> or
    /// <see cref="GetOrCreateMotionInterpreter"/> creates it; an object without one deactivates itself when it rests on
    /// walkable ground.</summary>
    /// <exception cref="System.InvalidOperationException">Set on an object removed from its world.</exception>
    public IMovementManager? Movement
    {
        get => _movementManager;
        set
        {
            ThrowIfRemoved();
            Touch();
            _movementManager = value;
        }
    }

    /// <summary>The position manager, or null until <see cref="MakePositionManager"/> (retail <c>position_manager</c>).</summary>
    public PositionManager? PositionManager
    {
        get => _rare?.PositionManager;
        private set
        {
            if (value is not null || _rare is not null)
            {
                Rare(true)!.PositionManager = value;
            }
        }
    }

    /// <summary>The object's detection manager (retail <c>detection_manager</c>), or null: retail's
    /// <see cref="Managers.DetectionManager"/> (created for this object), or a client's own. Checked in the object's step.</summary>
    /// <exception cref="ArgumentException">A <see cref="Managers.DetectionManager"/> of another object.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public IDetectionManager? DetectionManager
    {
        get => _rare?.DetectionManager;
        set
        {
            ThrowIfRemoved();
            if (value is Managers.DetectionManager dm && dm.PhysicsObj != this)
            {
                throw new ArgumentException("The detection manager was created for another object.", nameof(value));
            }

            Touch();
            Rare(value is not null)?.DetectionManager = value;
        }
    }

    /// <summary>The object's target tracking (retail <c>target_manager</c>), or null until the object first tracks a target or
    /// is tracked (a move-to or turn-to an object, a stick).</summary>
    public Managers.TargetManager? TargetManager => _rare?.TargetManager;

    /// <summary>Particle manager seam, or null (runs for inactive objects too).</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public IParticleManager? ParticleManager
    {
        get => _rare?.ParticleManager;
        set
        {
            ThrowIfRemoved();
            Touch();
            Rare(value is not null)?.ParticleManager = value;
        }
    }

    /// <summary>Script manager seam, or null (runs for inactive objects too).</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public IScriptManager? ScriptManager
    {
        get => _rare?.ScriptManager;
        set
        {
            ThrowIfRemoved();
            Touch();
            Rare(value is not null)?.ScriptManager = value;
        }
    }

    /// <summary>Sets the persistent state bits (retail <c>set_state</c>). A change of <see cref="PhysicsState.Hidden"/> hides or
    /// shows the object as retail's <c>set_hidden</c> does: hidden, it ignores collisions and stops reporting them (those in
    /// progress end), its children get <see cref="PhysicsState.NoDraw"/> and its cell's voyeurs are told it left; shown, the
    /// reverse. The lighting and no-draw side effects belong to the renderer.</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_state (acclient.c:322171)
    public void SetState(PhysicsState newState)
    {
        ThrowIfRemoved();
        Touch();
        PhysicsState changed = newState ^ _state;
        _state = newState;
        if ((changed & PhysicsState.HasPhysicsBsp) != 0)
        {
            SyncObstacleSummary();
        }
        if ((changed & PhysicsState.Hidden) != 0)
        {
            SetHidden((newState & PhysicsState.Hidden) != 0);
        }
    }

    /// <summary>Sets the acceleration directly (retail <c>set_description</c> writes it); normally <see cref="CalcAcceleration"/> does.</summary>
    /// <param name="acceleration">m/s² in world axes: finite, magnitude at most <see cref="InputLimits.MaxAcceleration"/>
    /// (1,000 m/s²).</param>
    /// <exception cref="ArgumentException">A component is NaN or infinite, or the magnitude exceeds 1,000 m/s² (state
    /// unchanged).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public void SetAcceleration(Vector3 acceleration)
    {
        ThrowIfRemoved();
        ThrowIfNotFinite(acceleration, nameof(acceleration));
        // non-retail: the acceleration's bound (1e30 m/s² swept an object 1e28 m in one step)
        if ((double)acceleration.X * acceleration.X + (double)acceleration.Y * acceleration.Y
            + (double)acceleration.Z * acceleration.Z > (double)InputLimits.MaxAcceleration * InputLimits.MaxAcceleration)
        {
            throw new ArgumentException("Acceleration must not exceed 1,000 m/s².", nameof(acceleration));
        }

        Touch();
        _acceleration = acceleration;
    }

    /// <inheritdoc />
    public override string ToString() =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture, $"PhysicsObj 0x{Id:X8} {_position}");

    // The side object of what few objects have: the detection, target, particle and script seams (created when one is first
    // set, at setup, by the client) and the LinearExtrapolation state (created at the first report in that mode); null until
    // then, so that an object without them keeps one reference instead of five.
    private RareComponents? Rare(bool create) => create ? _rare ??= new RareComponents() : _rare;

    private sealed class RareComponents
    {
        public IDetectionManager? DetectionManager;
        public Managers.TargetManager? TargetManager;
        public IParticleManager? ParticleManager;
        public IScriptManager? ScriptManager;
        public Extrapolation? Extrapolation;
        public PhysicsObj? Parent;
        public ChildList? Children;
        public PositionManager? PositionManager;
    }

    // non-retail: an object removed from its world refuses every public mutator (retail deletes the object; here the client
    // keeps a reference that could otherwise be changed, placed and reported in a cell while no tick ever visits it)
    private void ThrowIfRemoved()
    {
        if (RemovedFromWorld)
        {
            ThrowRemoved();
        }
    }

    [System.Diagnostics.CodeAnalysis.DoesNotReturn]
    private void ThrowRemoved() =>
        throw new InvalidOperationException(string.Create(System.Globalization.CultureInfo.InvariantCulture,
            $"Object 0x{Id:X8} was removed from its world: it can be read but not changed (create a new object)."));

    /// <summary>Takes an object being removed from its world out of its cell and clears its transient state (contact, walkable,
    /// active...), so that it reports what it is: in no cell, not simulated. Its position stays readable.</summary>
    internal void ClearOnRemove()
    {
        CellId = 0;
        _transientState = 0;
    }

    private static void ThrowIfNotFinite(Vector3 v, string name)
    {
        if (!VectorMath.IsFinite(v))
        {
            throw new ArgumentException("Vector components must be finite.", name);
        }
    }
}
