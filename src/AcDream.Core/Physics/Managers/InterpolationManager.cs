using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Moves a remotely-controlled object smoothly towards the positions the server reports (retail <c>InterpolationManager</c>,
/// acclient.h:31505; PORTAL/cpmanager/CInterpolationManager.c), and snaps ("blips") it when it cannot keep up.
/// </summary>
/// <remarks>
/// <para>Each server position becomes a node (<see cref="InterpolateTo"/>). Every physics substep,
/// <see cref="AdjustOffset"/> replaces the animation's offset with a step towards the head node, at most
/// 2 × the motion's max speed × dt; every 5 substeps it audits progress and fails a node that closes at less than 30 % of that
/// rate. After the substep's sweep, <see cref="UseTime"/> blips to the newest node once more than 3 nodes have failed
/// (or a far update pre-armed the counter to 4).</para>
/// <para>The queue is a fixed ring of <see cref="MaxQueueLength"/> nodes stored by value: queuing and ticking allocate
/// nothing. Retail keeps a heap-allocated linked list; the order and every test on it are the same.</para>
/// <para>Distances are <c>Position::distance</c> evaluated in double as retail's x87 code does; stored state is float as in
/// the retail struct.</para>
/// </remarks>
public sealed partial class InterpolationManager
{
    /// <summary>Largest number of queued nodes; the near branch evicts the head to stay within it. Retail: 20 (acclient.c:389084).</summary>
    public const int MaxQueueLength = 20;

    /// <summary>Distance within which a node counts as reached, metres. Retail: 0.05f (acclient.c:389217, 389258; also the
    /// InterpolateTo stop and prune tests, 389057, 389062).</summary>
    public const float DesiredDistance = 0.05f;

    /// <summary>Distance under which a failed progress audit still completes the node successfully, metres. Retail: 0.2
    /// (acclient.c:389270).</summary>
    public const float NearEnoughDistance = 0.2f;

    /// <summary>Substeps between progress audits. Retail: 5 (acclient.c:389244).</summary>
    public const uint ProgressCheckFrames = 5;

    /// <summary>Fraction of the theoretical closing rate below which an audit fails (retail
    /// <c>CREATURE_FAILED_INTERPOLATION_PERCENTAGE</c>). Retail: 0.3f (acclient.c:389248).</summary>
    public const float MinProgressFraction = 0.3f;

    /// <summary>Catch-up speed used when the motion's max speed is unknown (below EPSILON), m/s. Retail
    /// <c>MAX_INTERPOLATED_VELOCITY</c> 7.5f (acclient_data.h:2589; used acclient.c:389240).</summary>
    public const float MaxInterpolatedVelocity = 7.5f;

    /// <summary>Multiplier applied to the motion's max speed to get the catch-up speed. Retail: 2.0 (acclient.c:389237).</summary>
    public const double SpeedMultiplier = 2.0;

    /// <summary>Sentinel of <see cref="OriginalDistance"/> while no node is being audited, metres. Retail <c>BIG_DISTANCE</c>
    /// 999999.0f (acclient_data.h:2590).</summary>
    public const float BigDistance = 999999.0f;

    /// <summary>Fail count the far branch of <see cref="InterpolateTo"/> pre-arms so the next <see cref="UseTime"/> blips.
    /// Retail: 4 (acclient.c:389164).</summary>
    public const int FarBranchFailCount = 4;

    /// <summary><see cref="UseTime"/> blips when the fail counter exceeds this. Retail: 3 (acclient.c:389302).</summary>
    public const int BlipFailThreshold = 3;

    /// <summary>Retail <c>InterpolationManager::fUseAdjustedSpeed_</c> = 1 (acclient_data.h:6710): the audit and the speed cap
    /// use <c>get_adjusted_max_speed</c> rather than <c>get_max_speed</c>.</summary>
    public const bool UseAdjustedSpeed = true;

    private readonly InterpolationNode[] _nodes = new InterpolationNode[MaxQueueLength];
    private int _head;
    private int _count;

    // retail: InterpolationManager::InterpolationManager (acclient.c:388814)
    internal InterpolationManager(PhysicsObj physicsObj)
    {
        PhysicsObj = physicsObj;
        OriginalDistance = BigDistance;
        BliptoPosition = new Position(0, Frame.Identity);
    }

    /// <summary>The object being interpolated (retail <c>physics_obj</c>).</summary>
    public PhysicsObj PhysicsObj { get; }

    /// <summary>Number of queued nodes (0 to <see cref="MaxQueueLength"/>).</summary>
    public int Count => _count;

    /// <summary>True when the newest near-branch update asked to keep the object's own heading (retail <c>keep_heading</c>).</summary>
    public bool KeepHeading { get; private set; }

    /// <summary>Substeps since the last audit or node change (retail <c>frame_counter</c>).</summary>
    public uint FrameCounter { get; private set; }

    /// <summary>Distance to the head node at the last passed audit, metres; <see cref="BigDistance"/> when none
    /// (retail <c>original_distance</c>, float).</summary>
    public float OriginalDistance { get; private set; }

    /// <summary>Sum of the substep durations since the last audit, seconds (retail <c>progress_quantum</c>, float).</summary>
    public float ProgressQuantum { get; private set; }

    /// <summary>Failed audits since the queue was last stopped (retail <c>node_fail_counter</c>); only
    /// <see cref="StopInterpolating"/> resets it.</summary>
    public int NodeFailCounter { get; private set; }

    /// <summary>Where a blip goes when the queue holds no usable node: the last node that failed (retail
    /// <c>blipto_position</c>; cell 0 until a node fails).</summary>
    public Position BliptoPosition { get; private set; }

    /// <summary>True while nodes are queued (retail <c>position_queue.head_ != 0</c>, read by
    /// <c>PositionManager::IsInterpolating</c>).</summary>
    // retail: PositionManager::IsInterpolating (acclient.c:388475)
    public bool IsInterpolating => _count > 0;

    /// <summary>The queued node at <paramref name="index"/> (0 = head, the node being approached).</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="index"/> is outside [0, <see cref="Count"/>).</exception>
    internal InterpolationNode GetNode(int index)
    {
        if ((uint)index >= (uint)_count)
        {
            throw new ArgumentOutOfRangeException(nameof(index));
        }

        return At(index);
    }

    /// <summary>
    /// Queues the server position <paramref name="p"/>. Near (within <see cref="PhysicsObj.AutonomyBlipDistance"/> of the
    /// newest queued position, or of the object when none): if the object is already within 0.05 m it stops interpolating
    /// (turning to <paramref name="p"/>'s heading unless <paramref name="keepHeading"/>); otherwise trailing nodes within 0.05 m
    /// of <paramref name="p"/> are dropped, the head is evicted while the queue is full, and <paramref name="p"/> is appended.
    /// Far: <paramref name="p"/> is appended and the fail counter set to 4, so the next <see cref="UseTime"/> blips to it.
    /// </summary>
    /// <param name="p">The reported position.</param>
    /// <param name="keepHeading">Keep the object's current heading (retail passes <c>IsMovingTo()</c>).</param>
    /// <exception cref="ArgumentException"><paramref name="p"/> has a non-finite origin or an invalid quaternion; nothing changes.</exception>
    // retail: InterpolationManager::InterpolateTo (acclient.c:389016)
    public void InterpolateTo(in Position p, bool keepHeading)
    {
        PhysicsObj.Touch();
        ThrowIfUnusable(p, nameof(p));
        Position body = PhysicsObj.Position;
        InterpolateToInternal(p, keepHeading, body);
    }

    /// <summary>
    /// Client-facing form of <see cref="InterpolateTo"/>. <paramref name="currentBodyPosition"/>, when given, stands in for
    /// the object's stored position in the near/far and 0.05 m tests and the kept heading (for a caller whose body has moved
    /// outside the physics tick since the last update). Null gives retail's behaviour exactly.
    /// </summary>
    /// <param name="p">The reported position.</param>
    /// <param name="keepHeading">Keep the object's current heading.</param>
    /// <param name="currentBodyPosition">The body's position to measure from, or null for the object's own.</param>
    /// <exception cref="ArgumentException">A position has a non-finite origin or an invalid quaternion; nothing changes.</exception>
    internal void Enqueue(in Position p, bool keepHeading = false, Position? currentBodyPosition = null)
    {
        PhysicsObj.Touch();
        ThrowIfUnusable(p, nameof(p));
        if (currentBodyPosition is Position given)
        {
            ThrowIfUnusable(given, nameof(currentBodyPosition));
            InterpolateToInternal(p, keepHeading, given);
            return;
        }

        InterpolateToInternal(p, keepHeading, PhysicsObj.Position);
    }

    /// <summary>
    /// Appends a node of any type at the tail without the near/far logic (evicting the head when the ring is full).
    /// </summary>
    /// <remarks>Not retail: 11.4186 has no producer of Jump or Velocity nodes (only InterpolateTo creates nodes, always
    /// Position). This entry point lets a client or a test drive the Jump/Velocity branches that retail's
    /// <see cref="AdjustOffset"/> and <see cref="UseTime"/> still contain.</remarks>
    /// <param name="type">Node type (not <see cref="InterpolationNodeType.None"/>).</param>
    /// <param name="p">Node position.</param>
    /// <param name="velocity">Node velocity, m/s.</param>
    /// <param name="extent">Jump extent (carried only).</param>
    /// <exception cref="ArgumentException">Unknown type, unusable position or non-finite velocity/extent; nothing changes.</exception>
    internal void EnqueueNode(InterpolationNodeType type, in Position p, Vector3 velocity, float extent = 0f)
    {
        PhysicsObj.Touch();
        if (type is not (InterpolationNodeType.Position or InterpolationNodeType.Jump or InterpolationNodeType.Velocity))
        {
            throw new ArgumentException("Node type must be Position, Jump or Velocity.", nameof(type));
        }

        ThrowIfUnusable(p, nameof(p));
        if (!VectorMath.IsFinite(velocity) || !float.IsFinite(extent))
        {
            throw new ArgumentException("Velocity and extent must be finite.", nameof(velocity));
        }

        if (_count == MaxQueueLength)
        {
            RemoveHead();
        }

        ref InterpolationNode n = ref _nodes[Slot(_count)];
        n.Type = type;
        n.Position = p;
        n.Velocity = velocity;
        n.Extent = extent;
        _count++;
    }

    /// <summary>Drops every node and resets the audit state and the fail counter (keep-heading and the blip target stay).</summary>
    // retail: InterpolationManager::StopInterpolating (acclient.c:388852)
    public void StopInterpolating()
    {
        _head = 0;
        _count = 0;
        FrameCounter = 0;
        ProgressQuantum = 0f;
        NodeFailCounter = 0;
        OriginalDistance = BigDistance;
    }

    private void InterpolateToInternal(in Position p, bool keepHeading, in Position body)
    {
        // The newest queued Position is the reference; a Jump/Velocity tail or an empty queue measures from the body.
        double refDistance = _count > 0 && Tail.Type == InterpolationNodeType.Position
            ? Tail.Position.DistanceInDouble(p)
            : body.DistanceInDouble(p);
        float pa = (float)refDistance;
        if (PhysicsObj.AutonomyBlipDistance >= pa)
        {
            if (body.DistanceInDouble(p) > DesiredDistance)
            {
                // Collapse trailing Position nodes that the new target supersedes (acclient.c:389062).
                while (_count > 0)
                {
                    ref InterpolationNode tail = ref Tail;
                    if (tail.Type != InterpolationNodeType.Position || tail.Position.DistanceInDouble(p) >= DesiredDistance)
                    {
                        break;
                    }

                    _count--;
                }

                while (_count >= MaxQueueLength)
                {
                    RemoveHead();
                }

                KeepHeading = keepHeading;
                AppendPosition(p, body);
            }
            else
            {
                // Already there: face the reported heading (unless kept) and stop.
                if (!keepHeading)
                {
                    float degrees = (float)p.Frame.Heading;
                    PhysicsObj.SetHeading(degrees);
                }

                StopInterpolating();
            }

            return;
        }

        // Far branch: no prune and no cap in retail, and the heading rule uses the stored keep_heading. The ring cannot
        // grow, so a 21st node evicts the head (unobservable: the pre-armed blip goes to this new tail).
        if (_count == MaxQueueLength)
        {
            RemoveHead();
        }

        AppendPosition(p, body);
        NodeFailCounter = FarBranchFailCount;
    }

    private void AppendPosition(in Position p, in Position body)
    {
        ref InterpolationNode n = ref _nodes[Slot(_count)];
        n.Type = InterpolationNodeType.Position;
        n.Position = p;
        n.Velocity = Vector3.Zero;
        n.Extent = 0f;
        if (KeepHeading)
        {
            float heading = (float)body.Frame.Heading;
            n.Position.Frame.SetHeading(heading);
        }

        _count++;
    }

    private static void ThrowIfUnusable(in Position p, string name)
    {
        if (!InputLimits.IsPositionInDomain(p))
        {
            throw new ArgumentException("Position must have a finite origin and a valid rotation.", name);
        }
    }

    private int Slot(int index)
    {
        int s = _head + index;
        return s >= MaxQueueLength ? s - MaxQueueLength : s;
    }

    private ref InterpolationNode At(int index) => ref _nodes[Slot(index)];

    private ref InterpolationNode Head => ref _nodes[_head];

    private ref InterpolationNode Tail => ref _nodes[Slot(_count - 1)];

    private void RemoveHead()
    {
        _head = Slot(1);
        _count--;
        if (_count == 0)
        {
            _head = 0;
        }
    }
}
