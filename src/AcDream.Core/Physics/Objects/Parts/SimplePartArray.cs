using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Math;

namespace AcDream.Core.Physics.Objects.Parts;

/// <summary>
/// Built-in <see cref="IPartArray"/> for an object without animations: retail's <c>CSequence</c> with an empty animation
/// list, which moves the local frame only by the sequence's own velocity and omega (<c>CSequence::apply_physics</c>).
/// It records the visual values that hooks apply so a client (or a test) can read them.
/// </summary>
public sealed partial class SimplePartArray : IPartArray
{
    private readonly float[] _partTranslucency;
    private readonly float[] _partLuminosity;
    private readonly float[] _partDiffusion;
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
        _partTranslucency = new float[numParts];
        _partLuminosity = new float[numParts];
        _partDiffusion = new float[numParts];
    }

    /// <inheritdoc />
    public int NumSpheres => _spheres.Length;

    /// <inheritdoc />
    /// <remarks>Created as <see cref="Sphere.Dummy"/> spheres; replace them with <see cref="SetSpheres"/>.</remarks>
    public ReadOnlySpan<Sphere> Spheres => _spheres;

    /// <summary>Replaces the collision spheres (a setup's sphere list; object-local, unscaled).</summary>
    /// <exception cref="ArgumentException">A centre or radius is NaN or infinite, or a radius is not positive.</exception>
    public void SetSpheres(ReadOnlySpan<Sphere> spheres)
    {
        for (int i = 0; i < spheres.Length; i++)
        {
            Sphere s = spheres[i];
            if (!VectorMath.IsFinite(s.Center) || !float.IsFinite(s.Radius) || !(s.Radius > 0f))
            {
                throw new ArgumentException("Spheres need a finite centre and a positive finite radius.", nameof(spheres));
            }
        }

        Owner?.Touch();
        _spheres = spheres.ToArray();
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

    /// <summary>Step-up height, metres; default 0.01 f, retail's value without a setup (acclient.c:325399).</summary>
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public float StepUpHeight
    {
        get => _stepUpHeight;
        set => _stepUpHeight = Finite(value);
    }

    /// <summary>Step-down height, metres; default 0.01 f, retail's value without a setup (acclient.c:325413).</summary>
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public float StepDownHeight
    {
        get => _stepDownHeight;
        set => _stepDownHeight = Finite(value);
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
    public bool IsIdle => _sequenceVelocity == Vector3.Zero && _sequenceOmega == Vector3.Zero;

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
    public float GetPartTranslucency(uint part) => part < (uint)NumParts ? _partTranslucency[part] : 0f;

    /// <summary>Luminosity last applied to part <paramref name="part"/> (0 when out of range).</summary>
    public float GetPartLuminosity(uint part) => part < (uint)NumParts ? _partLuminosity[part] : 0f;

    /// <summary>Diffusion last applied to part <paramref name="part"/> (0 when out of range).</summary>
    public float GetPartDiffusion(uint part) => part < (uint)NumParts ? _partDiffusion[part] : 0f;

    /// <inheritdoc />
    // retail: CSequence::apply_physics (acclient.c:339859), reached from CSequence::update with an empty anim list
    public void Update(float quantum, ref Frame offsetFrame)
    {
        // sign = quantum: |quantum|, negated only for a negative sign (never, here).
        double s = System.Math.Abs((double)quantum);
        if (quantum < 0f)
        {
            s = -s;
        }

        Vector3 v = SequenceVelocity;
        Vector3 o = offsetFrame.Origin;
        offsetFrame.Origin = new Vector3((float)(s * v.X + o.X), (float)(s * v.Y + o.Y), (float)(s * v.Z + o.Z));
        Vector3 w = SequenceOmega;
        offsetFrame.Rotate(new Vector3((float)(s * w.X), (float)(s * w.Y), (float)(s * w.Z)));
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The origin is NaN or infinite (state unchanged).</exception>
    public void SetFrame(in Frame frame)
    {
        Finite(frame.Origin);
        _frame = frame;
    }

    /// <inheritdoc />
    public void SetCellId(uint cellId) => CellId = cellId;

    /// <inheritdoc />
    public void HandleMovement() => HandleMovementCount++;

    /// <inheritdoc />
    public void HandleEnterWorld()
    {
    }

    /// <inheritdoc />
    public Frame GetPartFrame(int index) => _frame;

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The scale is outside [<see cref="InputLimits.MinScale"/>,
    /// <see cref="InputLimits.MaxScale"/>] = [0.01, 100] (also NaN, ±∞, 0, negative); state unchanged.</exception>
    public void SetScale(float scale)
    {
        InputLimits.ThrowIfScaleOutside(scale, nameof(scale));
        Scale = scale;
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetTranslucency(float translucency)
    {
        Finite(translucency);
        Translucency = translucency;
        Array.Fill(_partTranslucency, translucency);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetPartTranslucency(uint part, float translucency)
    {
        Finite(translucency);
        if (part < (uint)NumParts)
        {
            _partTranslucency[part] = translucency;
        }
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetLuminosity(float luminosity)
    {
        Finite(luminosity);
        Luminosity = luminosity;
        Array.Fill(_partLuminosity, luminosity);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetPartLuminosity(uint part, float luminosity)
    {
        Finite(luminosity);
        if (part < (uint)NumParts)
        {
            _partLuminosity[part] = luminosity;
        }
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetDiffusion(float diffusion)
    {
        Finite(diffusion);
        Diffusion = diffusion;
        Array.Fill(_partDiffusion, diffusion);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    public void SetPartDiffusion(uint part, float diffusion)
    {
        Finite(diffusion);
        if (part < (uint)NumParts)
        {
            _partDiffusion[part] = diffusion;
        }
    }
}
