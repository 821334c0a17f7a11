using System;
using System.Numerics;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects.Parts;

/// <summary>
/// A part array that plays a setup's motion table and animations (retail <c>CPartArray</c> with its
/// <c>motion_table_manager</c> and <c>sequence</c>): the motion interpreter's motions go to the retail motion table
/// (<see cref="MotionTablePlayer"/>), each step plays the sequence (<c>CSequence::update</c>: the animations' root motion,
/// the motion data's velocity and omega, the frames' hooks), and each part's frame for drawing is placed at each
/// <see cref="SetFrame"/> from the animation frame playing then (<see cref="GetPartFrame"/>; <see cref="GetPartLocalFrame"/>
/// reads the playing frame itself). <see cref="SimplePartArray"/> stays the part array of an object without animations.
/// </summary>
/// <remarks>The setup's fields are plain constructor inputs (its physics, part count and default placement frame); the
/// motion table comes from its bytes (<see cref="MotionTable.UnPack"/>), the animations from an
/// <see cref="IAnimationSource"/>. Belongs to one object at a time.</remarks>
public sealed class AnimatedPartArray : IPartArray, IPartCollision, IAnimationDoneTarget
{
    private readonly Sphere[] _spheres;
    private readonly CylSphere[] _cylSpheres;
    private readonly MotionTablePlayer? _player;
    private readonly AnimSequence _sequence;
    private Frame _frame = Frame.Identity;
    private Vector3 _scale = Vector3.One;

    // The parts' frames (retail CPhysicsPart::pos.frame), kept lazily: SetFrame records the object's frame, the animation
    // frame and the scale of that call (the snapshot); parts below _snapshotCovered are that snapshot combined on demand,
    // the others hold what an earlier SetFrame that covered them wrote (retail's UpdateParts leaves them), materialised
    // into _partFrames only when a SetFrame covers fewer parts than the snapshot before it. Made once, per part.
    private readonly Frame[] _partFrames;
    private Frame _snapshotFrame = Frame.Identity;
    private AnimFrame? _snapshotAnimFrame;
    private Vector3 _snapshotScale = Vector3.One;
    private int _snapshotCovered;

    /// <summary>Creates the part array of a setup.</summary>
    /// <param name="setup">The setup's physics (spheres, cylinder spheres, sizes, step heights).</param>
    /// <param name="numParts">The setup's part count (retail <c>CSetup::num_parts</c>): at least 1.</param>
    /// <param name="motionTable">The setup's motion table (retail <c>CSetup::mtable_id</c>, read with
    /// <see cref="MotionTable.UnPack"/>), or null for an object that plays no motions (its motions then fail with
    /// <see cref="MotionError.NoMotionTable"/>).</param>
    /// <param name="animations">Resolves the animations the table names, or null (then none plays; only the motion data's
    /// velocity and omega move the body).</param>
    /// <param name="placementFrames">The setup's placement frame, one <see cref="AFrame"/> per part (retail
    /// <c>CSetup::placement_frames</c>): the parts' frames while no animation plays. Retail's <c>CPartArray::CreateSetup</c>
    /// asks for entry 0x65 (Resting) and, when the setup has none, falls back to entry 0 (Default). Empty: identity.</param>
    /// <param name="placementId">The id of the entry <paramref name="placementFrames"/> holds, as the sequence reports it
    /// (<see cref="AnimSequence.PlacementFrameId"/>): 0 (Default, retail's fallback) unless given; 0x65 for a Resting entry.</param>
    /// <exception cref="ArgumentNullException"><paramref name="setup"/> is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="numParts"/> is below 1.</exception>
    /// <exception cref="ArgumentException"><paramref name="placementFrames"/> is neither empty nor one frame per part.</exception>
    public AnimatedPartArray(SetupPhysics setup, int numParts, MotionTable? motionTable, IAnimationSource? animations,
        ReadOnlySpan<AFrame> placementFrames = default, uint placementId = 0)
    {
        ArgumentNullException.ThrowIfNull(setup);
        ArgumentOutOfRangeException.ThrowIfLessThan(numParts, 1);
        if (!placementFrames.IsEmpty && placementFrames.Length != numParts)
        {
            throw new ArgumentException("The placement frame needs one AFrame per part.", nameof(placementFrames));
        }

        NumParts = numParts;
        _partFrames = new Frame[numParts];
        Array.Fill(_partFrames, Frame.Identity);
        _spheres = setup.Spheres.ToArray();
        _cylSpheres = setup.CylSpheres.ToArray();
        _setupRadius = setup.Radius;
        _setupHeight = setup.Height;
        StepUpHeight = setup.StepUpHeight;
        StepDownHeight = setup.StepDownHeight;
        if (motionTable is not null)
        {
            _player = new MotionTablePlayer(motionTable, animations);
            _sequence = _player.Sequence;
        }
        else
        {
            _sequence = new AnimSequence(animations);
        }

        if (!placementFrames.IsEmpty)
        {
            // retail: CPartArray::SetPlacementFrame (acclient.c:326817) -> CSequence::set_placement_frame: the entry found,
            // labelled with its id (0x65 when the setup has a Resting entry, else 0, the Default entry retail falls back to)
            _sequence.SetPlacementFrame(new AnimFrame(placementFrames.ToArray(), null, 0), placementId);
        }
    }

    /// <summary>The motion table's player (the retail manager, table and sequence), or null without a table.</summary>
    public MotionTablePlayer? Player => _player;

    /// <summary>The sequence this part array plays (retail <c>CPartArray::sequence</c>).</summary>
    public AnimSequence Sequence => _sequence;

    /// <inheritdoc />
    public IMotionPlayer? MotionPlayer => _player;

    /// <summary>The object this part array belongs to (set when assigned to <see cref="PhysicsObj.PartArray"/>): the
    /// sequence's hooks are queued on it and finished motions reported to it.</summary>
    internal PhysicsObj? Owner
    {
        get => _owner;
        set
        {
            _owner = value;
            // retail: CPartArray::InitParts / SetSetupID hand the sequence its object (CSequence::set_object)
            _sequence.SetObject(value);
        }
    }

    private PhysicsObj? _owner;

    /// <inheritdoc />
    // retail: CPartArray::GetNumSphere (acclient.c:325357)
    public int NumSpheres => _spheres.Length;

    /// <inheritdoc />
    public ReadOnlySpan<Sphere> Spheres => _spheres;

    /// <inheritdoc />
    public ReadOnlySpan<CylSphere> CylSpheres => _cylSpheres;

    /// <inheritdoc />
    public Sphere SortingSphere => Sphere.Dummy;

    /// <inheritdoc />
    public int NumCollisionParts => 0;

    /// <inheritdoc />
    public int NumParts { get; }

    /// <inheritdoc />
    // retail: CPartArray::GetRadius (acclient.c:325381): the setup's radius times scale.z
    public float Radius => (float)RadiusInDouble;

    // retail: CPartArray::GetRadius (acclient.c:325381): the product as x87 hands it back, before a caller stores it as float
    internal double RadiusInDouble => (double)_setupRadius * _scale.Z;

    /// <inheritdoc />
    // retail: CPartArray::GetHeight (acclient.c:325387): the setup's height times scale.z
    public float Height => (float)((double)_setupHeight * _scale.Z);

    private readonly float _setupRadius;
    private readonly float _setupHeight;

    /// <inheritdoc />
    public float StepUpHeight { get; }

    /// <inheritdoc />
    public float StepDownHeight { get; }

    /// <summary>Last frame the object handed to its parts (retail <c>CPartArray::SetFrame</c>).</summary>
    public Frame Frame => _frame;

    /// <summary>Last uniform scale applied.</summary>
    public float Scale => _scale.X;

    /// <summary>Last cell id the object handed to its parts.</summary>
    public uint CellId { get; private set; }

    /// <inheritdoc />
    /// <exception cref="ArgumentException"><paramref name="quantum"/> is NaN, infinite or longer than
    /// <see cref="PhysicsGlobals.HugeQuantum"/> (2 s, the longest frame the object's update simulates) either way (state
    /// unchanged).</exception>
    // retail: CPartArray::Update (acclient.c:325139)
    public void Update(float quantum, ref Frame offsetFrame)
    {
        // non-retail: the quantum's domain, checked where a client can pass it (retail takes any float: a NaN made the
        // sequence's frame number NaN for good, a huge one played an unbounded number of passes)
        if (!(Math.Abs(quantum) <= PhysicsGlobals.HugeQuantum))
        {
            throw new ArgumentException($"The quantum must be finite and within ±{PhysicsGlobals.HugeQuantum} s.", nameof(quantum));
        }

        _sequence.Update(quantum, ref offsetFrame);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The origin is NaN or infinite (state unchanged).</exception>
    // retail: CPartArray::SetFrame (acclient.c:326765)
    public void SetFrame(in Frame frame)
    {
        if (!VectorMath.IsFinite(frame.Origin))
        {
            throw new ArgumentException("The frame's origin must be finite.", nameof(frame));
        }

        _frame = frame;
        UpdateParts(frame);
    }

    // The parts the animation frame covers take the object's frame combined with their animation frame; the others stay
    // where they were. Lazily: the snapshot is recorded, and only the parts the previous snapshot covered and this one does
    // not are combined now.
    // retail: CPartArray::UpdateParts (acclient.c:326600)
    private void UpdateParts(in Frame frame)
    {
        AnimFrame? f = _sequence.CurrentAnimFrame;
        int covered = f is null ? 0 : Math.Min(NumParts, f.NumParts);
        for (int i = covered; i < _snapshotCovered; i++)
        {
            Frame r = Frame.Identity;
            CombineScaled(ref r, _snapshotFrame, _snapshotAnimFrame!.Frames[i], _snapshotScale);
            _partFrames[i] = r;
        }

        _snapshotFrame = frame;
        _snapshotAnimFrame = f;
        _snapshotScale = _scale;
        _snapshotCovered = covered;
    }

    /// <inheritdoc />
    // retail: CPartArray::SetCellID (acclient.c:325145)
    public void SetCellId(uint cellId) => CellId = cellId;

    /// <inheritdoc />
    // retail: CPartArray::HandleMovement (acclient.c:325105)
    public void HandleMovement()
    {
        if (_player is not null)
        {
            _player.HandleMovement();
            _owner?.ReportCompletedMotions(_player);
        }
    }

    /// <inheritdoc />
    // retail: CPartArray::HandleEnterWorld (acclient.c:325115)
    public void HandleEnterWorld()
    {
        if (_player is not null)
        {
            _player.RemoveLinkAnimations();
            _owner?.ReportCompletedMotions(_player);
        }
    }

    /// <summary>The object left the world: every pending motion is done, unsuccessfully.</summary>
    // retail: CPartArray::HandleExitWorld (acclient.c:325127)
    public void HandleExitWorld()
    {
        if (_player is not null)
        {
            _player.HandleExitWorld();
            _owner?.ReportCompletedMotions(_player);
        }
    }

    /// <summary>One animation of the sequence ended (its AnimDone hook ran): the motions waiting for it are done.</summary>
    // retail: CPartArray::AnimationDone (acclient.c:325079)
    void IAnimationDoneTarget.AnimationDone(bool success)
    {
        if (_player is not null)
        {
            _player.AnimationDone(success);
            _owner?.ReportCompletedMotions(_player);
        }
    }

    /// <summary>True while animations are queued (retail <c>CPartArray::HasAnims</c>).</summary>
    // retail: CPartArray::HasAnims (acclient.c:325089)
    public bool HasAnims => _sequence.HasAnims;

    /// <summary>
    /// Part <paramref name="index"/>'s frame relative to the object: the playing animation frame's (retail
    /// <c>CSequence::get_curr_animframe</c>), else the placement frame's, else the identity.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="index"/> is not a part.</exception>
    public AFrame GetPartLocalFrame(int index)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(index);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(index, NumParts);
        AnimFrame? f = _sequence.CurrentAnimFrame;
        if (f is not null && index < f.NumParts)
        {
            return f.Frames[index];
        }

        return AFrame.Identity;
    }

    /// <summary>
    /// Part <paramref name="index"/>'s frame in the world as the last <see cref="SetFrame"/> placed it (retail
    /// <c>CPhysicsPart::pos.frame</c>, written by <c>CPartArray::UpdateParts</c>, acclient.c:326600): the object's frame
    /// combined with the part's frame in the animation frame playing then, its origin scaled. A part that animation frame did
    /// not cover stays where an earlier one put it (the identity before any), as in retail.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="index"/> is not a part.</exception>
    public Frame GetPartFrame(int index)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(index);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(index, NumParts);
        if (index >= _snapshotCovered)
        {
            return _partFrames[index];
        }

        Frame result = Frame.Identity;
        CombineScaled(ref result, _snapshotFrame, _snapshotAnimFrame!.Frames[index], _snapshotScale);
        return result;
    }

    /// <summary>Every part's world frame (<see cref="GetPartFrame"/>) into <paramref name="destination"/>, for drawing.</summary>
    /// <exception cref="ArgumentException"><paramref name="destination"/> is shorter than <see cref="NumParts"/>.</exception>
    public void CopyPartFrames(Span<Frame> destination)
    {
        if (destination.Length < NumParts)
        {
            throw new ArgumentException("The destination needs one frame per part.", nameof(destination));
        }

        for (int i = 0; i < NumParts; i++)
        {
            if (i < _snapshotCovered)
            {
                Frame r = Frame.Identity;
                CombineScaled(ref r, _snapshotFrame, _snapshotAnimFrame!.Frames[i], _snapshotScale);
                destination[i] = r;
            }
            else
            {
                destination[i] = _partFrames[i];
            }
        }
    }

    // f1 ∘ (f2 with its origin scaled), in retail's sum order; the quaternion through set_rotate.
    // retail: Frame::combine (acclient.c:326562)
    private static void CombineScaled(ref Frame result, in Frame f1, in AFrame f2, Vector3 scale)
    {
        double x = (double)f2.Origin.X * scale.X;
        double y = (double)f2.Origin.Y * scale.Y;
        double z = (double)f2.Origin.Z * scale.Z;
        float ox = (float)(x * f1.M11 + z * f1.M31 + y * f1.M21 + f1.Origin.X);
        float oy = (float)(x * f1.M12 + z * f1.M32 + y * f1.M22 + f1.Origin.Y);
        float oz = (float)(x * f1.M13 + z * f1.M33 + y * f1.M23 + f1.Origin.Z);
        double aw = f1.Qw, ax = f1.Qx, ay = f1.Qy, az = f1.Qz;
        double bw = f2.Qw, bx = f2.Qx, by = f2.Qy, bz = f2.Qz;
        float nz = (float)(aw * bz + ax * by - bx * ay + bw * az);
        float ny = (float)(aw * by - ax * bz + bx * az + bw * ay);
        float nx = (float)(bx * aw + bw * ax + bz * ay - by * az);
        float nw = (float)(bw * aw - bx * ax - by * ay - bz * az);
        result.Origin = new Vector3(ox, oy, oz);
        result.SetRotate(nw, nx, ny, nz);
    }

    /// <inheritdoc />
    /// <exception cref="ArgumentException">The scale is outside [0.01, 100] (state unchanged).</exception>
    // retail: CPartArray::SetScaleInternal (acclient.c:326181)
    public void SetScale(float scale)
    {
        InputLimits.ThrowIfScaleOutside(scale, nameof(scale));
        _scale = new Vector3(scale, scale, scale);
    }

    /// <inheritdoc />
    /// <param name="translucency">Any value: this part array keeps no surface values (a no-op; a client's renderer reads them from its own state).</param>
    public void SetTranslucency(float translucency)
    {
    }

    /// <inheritdoc />
    /// <param name="part">Any part index (a no-op).</param>
    /// <param name="translucency">Any value: this part array keeps no surface values (a no-op; a client's renderer reads them from its own state).</param>
    public void SetPartTranslucency(uint part, float translucency)
    {
    }

    /// <inheritdoc />
    /// <param name="luminosity">Any value: this part array keeps no surface values (a no-op; a client's renderer reads them from its own state).</param>
    public void SetLuminosity(float luminosity)
    {
    }

    /// <inheritdoc />
    /// <param name="part">Any part index (a no-op).</param>
    /// <param name="luminosity">Any value: this part array keeps no surface values (a no-op; a client's renderer reads them from its own state).</param>
    public void SetPartLuminosity(uint part, float luminosity)
    {
    }

    /// <inheritdoc />
    /// <param name="diffusion">Any value: this part array keeps no surface values (a no-op; a client's renderer reads them from its own state).</param>
    public void SetDiffusion(float diffusion)
    {
    }

    /// <inheritdoc />
    /// <param name="part">Any part index (a no-op).</param>
    /// <param name="diffusion">Any value: this part array keeps no surface values (a no-op; a client's renderer reads them from its own state).</param>
    public void SetPartDiffusion(uint part, float diffusion)
    {
    }
}
