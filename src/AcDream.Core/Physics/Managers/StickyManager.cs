using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Motion.MoveTo;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Keeps an object at arm's length from a target object (retail <c>StickyManager</c>, acclient.h:31518;
/// PORTAL/cpmanager/CStickyManager.c): while stuck and initialised, each substep's offset becomes a step towards a point
/// 0.3 m outside the two cylinders, and the heading turns to face the target.
/// </summary>
/// <remarks>
/// The stick is set by <see cref="StickTo"/> (retail: MoveToManager on arrival) and lasts one second of client time: only
/// <see cref="StickTo"/> sets the timeout and <see cref="UseTime"/> drops the stick after it. Positions of the target come
/// from the world's object table, else from the last <see cref="HandleUpdateTarget"/> report.
/// </remarks>
public sealed class StickyManager
{
    /// <summary>Gap kept between the two cylinders, metres. Retail: 0.3f (acclient.c:388559).</summary>
    public const float StickyRadius = 0.3f;

    /// <summary>Multiplier on the motion's max speed for the approach speed. Retail: 5.0 (acclient.c:388572).</summary>
    public const double SpeedMultiplier = 5.0;

    /// <summary>Approach speed when the max speed is below EPSILON, m/s. Retail: 15.0 (acclient.c:388579).</summary>
    public const double FallbackSpeed = 15.0;

    /// <summary>Lifetime of a stick, seconds of client time. Retail: 1.0 (acclient.c:388684).</summary>
    public const double StickyTime = 1.0;

    /// <summary>Radius passed to set_target. Retail: 0.5 (acclient.c:388687).</summary>
    public const float TargetTrackRadius = 0.5f;

    /// <summary>Update quantum passed to set_target, seconds. Retail: 0.5 (acclient.c:388687).</summary>
    public const double TargetTrackQuantum = 0.5;

    /// <summary>Error of the move-to cancelled by an unstick: <see cref="MotionError.ActionCancelled"/>. Retail: 0x36
    /// (acclient.c:317420).</summary>
    public const MotionError UnstickMoveToError = MotionError.ActionCancelled;

    /// <summary>
    /// Longest step a stick takes in one substep, metres: 100 (non-retail). Retail's step is the gap to the standoff point
    /// or 5 × max speed × quantum, whichever is shorter, with no bound: a target radius of 300 m (its Setup's) and a run
    /// rate of 50 gave a 200 m step, which the sweep refuses (longer than 192 m), and the tick threw. With the physics
    /// step's at most 30 m (<see cref="InputLimits.MaxAcceleration"/>) a substep then moves at most 130 m. A real stick
    /// steps far less: at retail's largest run rates (about 4.5) 5 × 18 m/s × 0.2 s = 18 m, and the gap is under a metre.
    /// A longer step is shortened along its direction.
    /// </summary>
    public const float MaxStep = 100f;

    // retail: StickyManager::Create (acclient.c:388727)
    internal StickyManager(PhysicsObj physicsObj)
    {
        PhysicsObj = physicsObj;
        TargetPosition = new Position(0, Frame.Identity);
    }

    /// <summary>The object that sticks.</summary>
    public PhysicsObj PhysicsObj { get; }

    /// <summary>Id of the target object, or 0 (retail <c>target_id</c>).</summary>
    public uint TargetId { get; private set; }

    /// <summary>Radius of the target's cylinder, metres (retail <c>target_radius</c>).</summary>
    public float TargetRadius { get; private set; }

    /// <summary>Last reported target position (retail <c>target_position</c>).</summary>
    public Position TargetPosition { get; private set; }

    /// <summary>True once a tracking report with status Ok arrived (retail <c>initialized</c>).</summary>
    public bool Initialized { get; private set; }

    /// <summary>Client time after which <see cref="UseTime"/> drops the stick, seconds (retail <c>sticky_timeout_time</c>).</summary>
    public double StickyTimeoutTime { get; private set; }

    /// <summary>
    /// Replaces the offset's origin by a horizontal step (in local axes) towards the standoff point, at most
    /// 5 × max speed × quantum (15 m/s when the speed is unknown) and at most <see cref="MaxStep"/>, and its heading by the
    /// turn that faces the target.
    /// </summary>
    /// <param name="offset">The substep's offset frame.</param>
    /// <param name="quantum">Substep duration, seconds.</param>
    // retail: StickyManager::adjust_offset (acclient.c:388518)
    internal void AdjustOffset(ref Frame offset, double quantum)
    {
        if (TargetId == 0 || !Initialized)
        {
            return;
        }

        PhysicsObj obj = PhysicsObj;
        Position body = obj.Position;
        PhysicsObj? target = obj.World.GetObjectById(TargetId);
        Position targetPos = target is not null ? target.Position : TargetPosition;

        Vector3 o = body.GetOffset(targetPos);
        o = body.GlobalToLocalVec(o);
        o.Z = 0f;

        // Position::cylinder_distance_no_z (acclient.c:467268) kept in double until the float store of mag.
        float r1 = obj.Radius;
        Vector3 between = body.GetOffset(targetPos);
        double cyl = VectorMath.Magnitude(between)
            - ((double)r1 + TargetRadius);
        float mag = (float)(cyl - StickyRadius);

        if (VectorMath.NormalizeCheckSmall(ref o))
        {
            o = Vector3.Zero;
        }

        double speed = 0.0;
        IMotionInterpreter? minterp = obj.GetOrCreateMotionInterpreter();
        if (minterp is not null)
        {
            speed = minterp.MaxSpeed * SpeedMultiplier;
        }

        if (speed < PhysicsGlobals.Epsilon)
        {
            speed = FallbackSpeed;
        }

        double step = speed * quantum;
        if (step >= Math.Abs(mag))
        {
            o.X = mag * o.X;
            o.Y = mag * o.Y;
            step = mag;
        }
        else
        {
            o.X = (float)(step * o.X);
            o.Y = (float)(step * o.Y);
        }

        o.Z = (float)(step * o.Z);
        // non-retail: the step's length bounded (see MaxStep); retail's is 5 × max speed × quantum or the gap, unbounded
        if (Math.Abs(step) > MaxStep)
        {
            double k = MaxStep / Math.Abs(step);
            o = new Vector3((float)(o.X * k), (float)(o.Y * k), (float)(o.Z * k));
        }

        offset.Origin = o;

        float toTarget = (float)body.HeadingTo(targetPos);
        double turn = toTarget - body.Frame.Heading;
        float sought = (float)turn;
        if (Math.Abs(turn) < PhysicsGlobals.Epsilon)
        {
            sought = 0f;
        }

        if (-PhysicsGlobals.Epsilon > sought)
        {
            sought = (float)(sought + 360.0);
        }

        offset.SetHeading(sought);
    }

    /// <summary>Drops the stick once the client time passes <see cref="StickyTimeoutTime"/>.</summary>
    // retail: StickyManager::UseTime (acclient.c:388604)
    internal void UseTime()
    {
        if (TargetId != 0 && PhysicsObj.World.CurrentTime > StickyTimeoutTime)
        {
            Unstick();
        }
    }

    /// <summary>Starts sticking to <paramref name="objectId"/> for one second (dropping any previous stick).</summary>
    /// <param name="objectId">Target id.</param>
    /// <param name="radius">Target cylinder radius, metres.</param>
    /// <param name="height">Target height (unused, as in retail).</param>
    /// <exception cref="ArgumentException"><paramref name="radius"/> is not finite; nothing changes.</exception>
    // retail: StickyManager::StickTo (acclient.c:388664)
    public void StickTo(uint objectId, float radius, float height)
    {
        PhysicsObj.Touch();
        if (!float.IsFinite(radius))
        {
            throw new ArgumentException("Radius must be finite.", nameof(radius));
        }

        if (TargetId != 0)
        {
            Unstick();
        }

        TargetRadius = radius;
        TargetId = objectId;
        Initialized = false;
        StickyTimeoutTime = PhysicsObj.World.CurrentTime + StickyTime;
        PhysicsObj.SetTarget(0, objectId, TargetTrackRadius, TargetTrackQuantum);
    }

    /// <summary>A tracking report for the target: Ok stores its position and initialises the stick; any other status unsticks.</summary>
    /// <param name="info">The report; reports for other objects are ignored.</param>
    /// <exception cref="ArgumentException">An Ok report with an unusable position; nothing changes.</exception>
    // retail: StickyManager::HandleUpdateTarget (acclient.c:388690)
    public void HandleUpdateTarget(in TargetInfo info)
    {
        if (info.ObjectId != TargetId)
        {
            return;
        }

        if (info.Status == TargetStatus.Ok)
        {
            if (!InputLimits.IsPositionInDomain(info.TargetPosition))
            {
                throw new ArgumentException("Target position must have a finite origin and a valid rotation.", nameof(info));
            }

            Initialized = true;
            TargetPosition = info.TargetPosition;
        }
        else if (TargetId != 0)
        {
            Unstick();
        }
    }

    /// <summary>Stops sticking: drops the stick (target tracking cleared, move-to cancelled). Retail
    /// <c>StickyManager::HandleExitWorld</c>, which <c>PositionManager::UnStick</c> calls.</summary>
    // retail: StickyManager::HandleExitWorld (acclient.c:388501)
    public void StopSticking()
    {
        if (TargetId != 0)
        {
            Unstick();
        }
    }

    private void Unstick()
    {
        TargetId = 0;
        Initialized = false;
        PhysicsObj.ClearTarget();
        PhysicsObj.CancelMoveTo();
    }
}
