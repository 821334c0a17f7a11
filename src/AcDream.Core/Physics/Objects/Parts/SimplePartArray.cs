using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects.Parts;

/// <summary>
/// Built-in <see cref="IPartArray"/> for an object without animations: retail's <c>CSequence</c> with an empty animation
/// list, which moves the local frame only by the sequence's own velocity and omega (<c>CSequence::apply_physics</c>).
/// It records the visual values that hooks apply so a client (or a test) can read them.
/// </summary>
public sealed partial class SimplePartArray : IPartArray
{
    // The visual values last applied to each part, three per part (translucency, luminosity, diffusion) in one array, so
    // that a part array keeps one array for them rather than three.
    private const int Translucency0 = 0, Luminosity0 = 1, Diffusion0 = 2, PartValues = 3;
    private readonly float[] _partValues;
    private Frame _frame = Frame.Identity;
    private Sphere[] _spheres;

    /// <summary>Creates a part array with <paramref name="numParts"/> parts and <paramref name="numSpheres"/> collision spheres.</summary>
    /// <exception cref="ArgumentOutOfRangeException">A count is negative.</exception>
    public SimplePartArray(int numParts = 1, int numSpheres = 0)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(numParts);
        ArgumentOutOfRangeException.ThrowIfNegative(numSpheres);
        NumParts = numParts;
        _spheres = new Sphere[numSpheres];
        Array.Fill(_spheres, Sphere.Dummy);
        UpdateObstacleReach();
        _partValues = new float[numParts * PartValues];
    }

    /// <inheritdoc />
    public int NumSpheres => _spheres.Length;

    /// <inheritdoc />
    /// <remarks>Created as <see cref="Sphere.Dummy"/> spheres; replace them with <see cref="SetSpheres"/>.</remarks>
    public ReadOnlySpan<Sphere> Spheres => _spheres;

    /// <summary>Replaces the collision spheres (a setup's sphere list; object-local, unscaled).</summary>
    /// <param name="spheres">The spheres: each with a finite centre, a positive radius and |centre| + radius at most
    /// <see cref="InputLimits.MaxShapeReach"/> (192 m).</param>
    /// <exception cref="ArgumentException">A sphere is outside that domain (a centre or radius NaN or infinite, a radius not
    /// positive, or a reach beyond 192 m; the message names its index); nothing changes.</exception>
    public void SetSpheres(ReadOnlySpan<Sphere> spheres)
    {
        // non-retail: the shapes' domain (a 1e7 m sphere made every later Tick throw)
        Sphere.ThrowIfAnyOutside(spheres, nameof(spheres));

        Owner?.Touch();
        _spheres = spheres.ToArray();
        UpdateObstacleReach();
    }

    /// <inheritdoc />
    public int NumParts { get; }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public float Radius
    {
        get => _radius;
        set => _radius = Finite(value);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public float Height
    {
        get => _height;
        set => _height = Finite(value);
    }

    /// <summary>Step-up height, metres, in [0, <see cref="InputLimits.MaxStepHeight"/>] = [0, 192]; default 0.01 f,
    /// retail's value without a setup (acclient.c:325399).</summary>
    /// <exception cref="ArgumentException">The value is NaN, negative or above 192 m (state unchanged).</exception>
    public float StepUpHeight
    {
        get => _stepUpHeight;
        set => _stepUpHeight = InputLimits.ThrowIfStepHeightOutside(value, nameof(value));
    }

    /// <summary>Step-down height, metres, in [0, <see cref="InputLimits.MaxStepHeight"/>] = [0, 192]; default 0.01 f,
    /// retail's value without a setup (acclient.c:325413).</summary>
    /// <exception cref="ArgumentException">The value is NaN, negative or above 192 m (state unchanged).</exception>
    public float StepDownHeight
    {
        get => _stepDownHeight;
        set => _stepDownHeight = InputLimits.ThrowIfStepHeightOutside(value, nameof(value));
    }

    private float _radius;
    private float _height;
    private float _stepUpHeight = 0.0099999998f;
    private float _stepDownHeight = 0.0099999998f;

    private static float Finite(float value) =>
        float.IsFinite(value) ? value : throw new ArgumentException("Part array values must be finite.", nameof(value));

    private static Vector3 Finite(Vector3 value) =>
        VectorMath.IsFinite(value) ? value : throw new ArgumentException("Part array vectors must be finite.", nameof(value));

    /// <summary>The sequence's velocity in the object's local axes, m/s (retail <c>CSequence::velocity</c>).</summary>
    /// <remarks>Valid domain: finite, speed |v| at most <see cref="InputLimits.MaxSequenceSpeed"/> (50 m/s, retail's max
    /// velocity), so that one 0.2 s step moves the object at most 10 m (× scale) and its sweep re-homes it.</remarks>
    /// <exception cref="ArgumentException">A component is NaN or infinite, or the speed exceeds 50 m/s (state unchanged;
    /// retail's sequence velocity comes from the motion tables unchecked).</exception>
    public Vector3 SequenceVelocity
    {
        get => _sequenceVelocity;
        set
        {
            Finite(value);
            // non-retail: the animation velocity's bound (an unbounded one moved a walker 8,000 km in one tick)
            if ((double)value.X * value.X + (double)value.Y * value.Y + (double)value.Z * value.Z
                > (double)InputLimits.MaxSequenceSpeed * InputLimits.MaxSequenceSpeed)
            {
                throw new ArgumentException("Sequence velocity must not exceed 50 m/s.", nameof(value));
            }

            Owner?.Touch();
            _sequenceVelocity = value;
        }
    }

    /// <summary>The sequence's angular velocity in the object's local axes, rad/s (retail <c>CSequence::omega</c>).</summary>
    /// <exception cref="ArgumentException">A component is NaN or infinite (state unchanged).</exception>
    public Vector3 SequenceOmega
    {
        get => _sequenceOmega;
        set
        {
            Finite(value);
            Owner?.Touch();
            _sequenceOmega = value;
        }
    }

    /// <summary>True when the sequence has no velocity and no omega: <see cref="Update"/> leaves the offset at the identity.
    /// (<see cref="HandleMovementCount"/> counts the visits the scene actually makes.)</summary>
    public bool IsIdle => _motionPlayer is null
        ? _sequenceVelocity == Vector3.Zero && _sequenceOmega == Vector3.Zero
        : _motionPlayer.Velocity == Vector3.Zero && _motionPlayer.Omega == Vector3.Zero;

    /// <summary>
    /// The motion player (null by default): what plays the object's motions, a player of a motion table
    /// (<see cref="Animation.MotionTablePlayer"/>) or a stand-in. When set, it drives the sequence: <see cref="Update"/>
    /// moves the body by the player's velocity and omega instead of <see cref="SequenceVelocity"/> and
    /// <see cref="SequenceOmega"/>. Set a
    /// <see cref="Motion.SpeedOnlyMotionPlayer"/> for a creature that should walk, run and turn at retail speeds without
    /// the real motion tables.
    /// </summary>
    public Motion.IMotionPlayer? MotionPlayer
    {
        get => _motionPlayer;
        set
        {
            Owner?.Touch();
            _motionPlayer = value;
        }
    }

    private Motion.IMotionPlayer? _motionPlayer;

    /// <summary>The object this part array belongs to (set when assigned to <see cref="PhysicsObj.PartArray"/>), woken when the
    /// sequence changes.</summary>
    internal PhysicsObj? Owner { get; set; }

    private Vector3 _sequenceVelocity;
    private Vector3 _sequenceOmega;

    /// <summary>Last frame the object handed to its parts.</summary>
    public Frame Frame => _frame;

    /// <summary>Last cell id the object handed to its parts.</summary>
    public uint CellId { get; private set; }

    /// <summary>Last uniform scale applied.</summary>
    public float Scale { get; private set; } = 1f;

    /// <summary>Last whole-object translucency applied.</summary>
    public float Translucency { get; private set; }

    /// <summary>Last whole-object luminosity applied.</summary>
    public float Luminosity { get; private set; }

    /// <summary>Last whole-object diffusion applied.</summary>
    public float Diffusion { get; private set; }

    /// <summary>Number of <see cref="HandleMovement"/> calls (one per active step).</summary>
    public int HandleMovementCount { get; private set; }

    /// <summary>Translucency last applied to part <paramref name="part"/> (0 when out of range).</summary>
    public float GetPartTranslucency(uint part) => part < (uint)NumParts ? _partValues[(part * PartValues) + Translucency0] : 0f;

    /// <summary>Luminosity last applied to part <paramref name="part"/> (0 when out of range).</summary>
    public float GetPartLuminosity(uint part) => part < (uint)NumParts ? _partValues[(part * PartValues) + Luminosity0] : 0f;

    /// <summary>Diffusion last applied to part <paramref name="part"/> (0 when out of range).</summary>
    public float GetPartDiffusion(uint part) => part < (uint)NumParts ? _partValues[(part * PartValues) + Diffusion0] : 0f;

    /// <inheritdoc />
    // retail: CSequence::apply_physics (acclient.c:339859), reached from CSequence::update with an empty anim list
    public void Update(float quantum, ref Frame offsetFrame)
    {
        Vector3 v = _motionPlayer is null ? _sequenceVelocity : _motionPlayer.Velocity;
        Vector3 w = _motionPlayer is null ? _sequenceOmega : _motionPlayer.Omega;
        if (IsStill(v, w) && quantum >= 0f && quantum <= float.MaxValue)
        {
            // An idle sequence (the usual case: no animation velocity): s·v is +0 on each axis (s = quantum is finite and not
            // negative, v is +0), so each origin component becomes +0 + o, which is o except that -0 becomes +0; and rotate by
            // a zero vector never changes the frame (|w|² = 0 is below EPSILON², or NaN, which set_rotate refuses). So only
            // the zero sums remain.
            Vector3 o0 = offsetFrame.Origin;
            offsetFrame.Origin = new Vector3(o0.X + 0f, o0.Y + 0f, o0.Z + 0f);
            return;
        }

        // sign = quantum: |quantum|, negated only for a negative sign (never, here).
        double s = Math.Abs((double)quantum);
        if (quantum < 0f)
        {
            s = -s;
        }

        Vector3 o = offsetFrame.Origin;
        offsetFrame.Origin = new Vector3((float)(s * v.X + o.X), (float)(s * v.Y + o.Y), (float)(s * v.Z + o.Z));
        offsetFrame.Rotate(new Vector3((float)(s * w.X), (float)(s * w.Y), (float)(s * w.Z)));
    }

    // The idle test of Update: velocity +0 on every axis (bits, as the sums above depend on the sign) and omega zero.
    private static bool IsStill(Vector3 v, Vector3 w) =>
        (BitConverter.SingleToInt32Bits(v.X) | BitConverter.SingleToInt32Bits(v.Y) | BitConverter.SingleToInt32Bits(v.Z)) == 0
        && w == Vector3.Zero;

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The origin is NaN or infinite (state unchanged).</exception>
    public void SetFrame(in Frame frame)
    {
        Finite(frame.Origin);
        _frame = frame;
    }

    /// <summary><see cref="SetFrame"/> for a frame whose origin the caller has already checked finite (the object's tick).</summary>
    internal void StoreCheckedFrame(in Frame frame) => _frame = frame;

    /// <inheritdoc />
    public void SetCellId(uint cellId) => CellId = cellId;

    /// <inheritdoc />
    /// <remarks>With a motion table, its finished motions are reported to the owner's movement manager (retail
    /// <c>CPartArray::HandleMovement</c> -> <c>MotionTableManager::UseTime</c>).</remarks>
    public void HandleMovement()
    {
        HandleMovementCount++;
        if (_motionPlayer is not null)
        {
            Owner?.CheckForCompletedMotions();
        }
    }

    /// <inheritdoc />
    /// <remarks>The motion table drops its link animations (retail <c>CPartArray::HandleEnterWorld</c>, which
    /// <c>CPhysicsObj::RemoveLinkAnimations</c> calls).</remarks>
    public void HandleEnterWorld() => _motionPlayer?.RemoveLinkAnimations();

    /// <inheritdoc />
    public Frame GetPartFrame(int index) => _frame;

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The scale is outside [<see cref="InputLimits.MinScale"/>,
    /// <see cref="InputLimits.MaxScale"/>] = [0.01, 100] (also NaN, ±∞, 0, negative); state unchanged.</exception>
    public void SetScale(float scale)
    {
        InputLimits.ThrowIfScaleOutside(scale, nameof(scale));
        Scale = scale;
        ScaleBspParts(scale);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetTranslucency(float translucency)
    {
        Finite(translucency);
        Translucency = translucency;
        FillParts(Translucency0, translucency);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetPartTranslucency(uint part, float translucency) => SetPart(Translucency0, part, translucency);

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetLuminosity(float luminosity)
    {
        Finite(luminosity);
        Luminosity = luminosity;
        FillParts(Luminosity0, luminosity);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetPartLuminosity(uint part, float luminosity) => SetPart(Luminosity0, part, luminosity);

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetDiffusion(float diffusion)
    {
        Finite(diffusion);
        Diffusion = diffusion;
        FillParts(Diffusion0, diffusion);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetPartDiffusion(uint part, float diffusion) => SetPart(Diffusion0, part, diffusion);

    // Sets value `channel` of one part (a part that does not exist is ignored, as retail's part loop skips it).
    private void SetPart(int channel, uint part, float value)
    {
        Finite(value);
        if (part < (uint)NumParts)
        {
            _partValues[(part * PartValues) + channel] = value;
        }
    }

    // Sets value `channel` of every part.
    private void FillParts(int channel, float value)
    {
        for (int i = channel; i < _partValues.Length; i += PartValues)
        {
            _partValues[i] = value;
        }
    }
}
