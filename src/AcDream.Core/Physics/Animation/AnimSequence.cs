using System.Numerics;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// The animations an object is playing and the velocity and omega they carry (retail <c>CSequence</c>, CSequence.c): a
/// list of queued animations, the link animations first and the cyclic ones last (from <see cref="FirstCyclic"/>), the
/// one playing and its fractional frame number. Each update advances the frame number by framerate × time, applies each
/// crossed frame's root motion (<see cref="AnimClip.PosFrames"/>) and the sequence's velocity and omega to the object's
/// offset frame, queues the crossed frames' hooks on the object, and moves on to the next animation (looping the cyclic
/// ones) when one ends.
/// </summary>
/// <remarks>
/// The motion table fills the sequence (<c>append_animation</c> and friends, engine-internal); a client reads it through its
/// part array, for example <see cref="CurrentAnimFrame"/> to draw the parts. The list's nodes are pooled: after the first
/// animations have been queued, playing and re-queueing allocates nothing.
/// </remarks>
public sealed partial class AnimSequence
{
    private readonly IAnimationSource? _animations;
    private readonly AnimDoneHook _animDoneHook = new();

    // anim_list: head and tail of the doubly linked list.
    private AnimSequenceNode? _head;
    private AnimSequenceNode? _tail;

    // The pool of unused nodes, linked through Next.
    private AnimSequenceNode? _free;

    private AnimSequenceNode? _firstCyclic;
    private AnimSequenceNode? _currAnim;
    private Vector3 _velocity;
    private Vector3 _omega;
    private PhysicsObj? _hookObj;
    private double _frameNumber;
    private AnimFrame? _placementFrame;
    private uint _placementFrameId;

    /// <summary>Creates an empty sequence that resolves animation ids through <paramref name="animations"/> (null: none
    /// resolve, so nothing is ever queued).</summary>
    // retail: CSequence::CSequence (acclient.c:339779)
    internal AnimSequence(IAnimationSource? animations)
    {
        _animations = animations;
        for (int i = 0; i < InitialPoolSize; i++)
        {
            ReturnNode(new AnimSequenceNode());
        }
    }

    // Nodes made with the sequence: a link and a cycle or two need no allocation later.
    private const int InitialPoolSize = 4;

    /// <summary>The sequence's velocity in the object's local axes, m/s (retail <c>velocity</c>; the motion data's).</summary>
    public Vector3 Velocity => _velocity;

    /// <summary>The sequence's angular velocity in the object's local axes, rad/s (retail <c>omega</c>).</summary>
    public Vector3 Omega => _omega;

    /// <summary>The playing animation's fractional frame number (retail <c>frame_number</c>).</summary>
    public double FrameNumber => _frameNumber;

    /// <summary>The playing animation (retail <c>curr_anim->anim</c>), or null when nothing plays.</summary>
    public AnimClip? CurrentAnimation => _currAnim?.Anim;

    /// <summary>True when animations are queued (retail <c>CSequence::has_anims</c>).</summary>
    // retail: CSequence::has_anims (acclient.c:339947)
    public bool HasAnims => _head is not null;

    /// <summary>The placement frame id set with the placement frame (retail <c>placement_frame_id</c>).</summary>
    public uint PlacementFrameId => _placementFrameId;

    /// <summary>The number of queued animations (links and cycles).</summary>
    public int AnimationCount
    {
        get
        {
            int n = 0;
            for (AnimSequenceNode? node = _head; node is not null; node = node.Next)
            {
                n++;
            }

            return n;
        }
    }

    /// <summary>The number of queued link animations (those before the first cyclic one).</summary>
    public int LinkAnimationCount
    {
        get
        {
            int n = 0;
            for (AnimSequenceNode? node = _head; node is not null && node != _firstCyclic; node = node.Next)
            {
                n++;
            }

            return n;
        }
    }

    /// <summary>
    /// The frame to draw the parts with: the playing animation's frame at the floor of <see cref="FrameNumber"/>, or the
    /// placement frame when nothing plays (retail <c>CSequence::get_curr_animframe</c>). Null when neither exists.
    /// </summary>
    // retail: CSequence::get_curr_animframe (acclient.c:339744)
    public AnimFrame? CurrentAnimFrame
    {
        get
        {
            AnimSequenceNode? curr = _currAnim;
            return curr is not null ? curr.GetPartFrame(AnimSequenceNode.FloorToFrame(_frameNumber)) : _placementFrame;
        }
    }

    /// <summary>The floor of <see cref="FrameNumber"/> (retail <c>CSequence::get_curr_frame_number</c>).</summary>
    // retail: CSequence::get_curr_frame_number (acclient.c:339773)
    public long CurrentFrameNumber => (long)System.Math.Floor(_frameNumber);

    // The engine's reads of the list (the motion table's and the tests').
    internal AnimSequenceNode? Head => _head;

    internal AnimSequenceNode? Tail => _tail;

    internal AnimSequenceNode? FirstCyclic => _firstCyclic;

    internal AnimSequenceNode? CurrAnim => _currAnim;

    internal PhysicsObj? HookObject => _hookObj;

    internal AnimFrame? PlacementFrame => _placementFrame;

    /// <summary>The object the crossed frames' hooks are queued on (null: hooks are not fired).</summary>
    // retail: CSequence::set_object (acclient.c:339676)
    internal void SetObject(PhysicsObj? physObj) => _hookObj = physObj;

    // retail: CSequence::set_velocity (acclient.c:339701)
    internal void SetVelocity(Vector3 v) => _velocity = v;

    // retail: CSequence::set_omega (acclient.c:339707)
    internal void SetOmega(Vector3 o) => _omega = o;

    /// <summary>Adds a motion's velocity and omega (component by component, in float).</summary>
    // retail: CSequence::combine_physics (acclient.c:339713)
    internal void CombinePhysics(Vector3 v, Vector3 o)
    {
        _velocity = new Vector3(_velocity.X + v.X, v.Y + _velocity.Y, v.Z + _velocity.Z);
        _omega = new Vector3(_omega.X + o.X, o.Y + _omega.Y, o.Z + _omega.Z);
    }

    /// <summary>Subtracts a motion's velocity and omega.</summary>
    // retail: CSequence::subtract_physics (acclient.c:339724)
    internal void SubtractPhysics(Vector3 v, Vector3 o)
    {
        _velocity = new Vector3(_velocity.X - v.X, _velocity.Y - v.Y, _velocity.Z - v.Z);
        _omega = new Vector3(_omega.X - o.X, _omega.Y - o.Y, _omega.Z - o.Z);
    }

    /// <summary>Multiplies the framerate of every cyclic animation (a negative multiplier also swaps their frame ranges).</summary>
    // retail: CSequence::multiply_cyclic_animation_fr (acclient.c:339735)
    internal void MultiplyCyclicAnimationFramerate(float multiplier)
    {
        for (AnimSequenceNode? i = _firstCyclic; i is not null; i = i.GetNext())
        {
            i.MultiplyFramerate(multiplier);
        }
    }

    /// <summary>Sets the frame drawn when nothing plays, and its id.</summary>
    // retail: CSequence::set_placement_frame (acclient.c:339766)
    internal void SetPlacementFrame(AnimFrame? placementFrame, uint id)
    {
        _placementFrame = placementFrame;
        _placementFrameId = id;
    }

    /// <summary>Zeroes the velocity and omega.</summary>
    // retail: CSequence::clear_physics (acclient.c:340085)
    internal void ClearPhysics()
    {
        _velocity = Vector3.Zero;
        _omega = Vector3.Zero;
    }

    /// <summary>Removes every animation; nothing plays, frame number 0.</summary>
    // retail: CSequence::clear_animations (acclient.c:340101)
    internal void ClearAnimations()
    {
        while (_head is not null)
        {
            AnimSequenceNode node = _head;
            Unlink(node);
            ReturnNode(node);
        }

        _firstCyclic = null;
        _frameNumber = 0.0;
        _currAnim = null;
    }

    /// <summary>Removes the animations, the velocity and omega and the placement frame.</summary>
    // retail: CSequence::clear (acclient.c:340646)
    internal void Clear()
    {
        ClearAnimations();
        ClearPhysics();
        _placementFrame = null;
        _placementFrameId = 0;
    }

    /// <summary>
    /// Queues an animation at the end of the list; it becomes the first cyclic animation (the ones before it are links). When
    /// nothing played, the list's first animation starts. An animation the source does not resolve is dropped.
    /// </summary>
    // retail: CSequence::append_animation (acclient.c:340589)
    internal void AppendAnimation(in AnimData newData)
    {
        AnimSequenceNode node = RentNode();
        node.Init(newData, _animations);
        if (node.HasAnim())
        {
            InsertAfter(node, _tail);
            PrepareRootMotionMemo(node); // non-retail (#38): the memo is made here, not in the update
            _firstCyclic = _tail;
            if (_currAnim is null)
            {
                AnimSequenceNode? head = _head;
                _currAnim = head;
                // retail calls get_starting_frame on a null head too (never reached: the node was just inserted)
                _frameNumber = head!.GetStartingFrame();
            }
        }
        else
        {
            ReturnNode(node);
        }
    }

    /// <summary>Removes every cyclic animation; when one was playing, the last link plays on from its end.</summary>
    // retail: CSequence::remove_cyclic_anims (acclient.c:340153)
    internal void RemoveCyclicAnims()
    {
        AnimSequenceNode? node = _firstCyclic;
        while (node is not null)
        {
            if (_currAnim == node)
            {
                AnimSequenceNode? prev = node.GetPrev();
                _currAnim = prev;
                _frameNumber = prev is not null ? prev.GetEndingFrame() : 0.0;
            }

            AnimSequenceNode? temp = node.GetNext();
            Unlink(node);
            ReturnNode(node);
            node = temp;
        }

        _firstCyclic = _tail;
    }

    /// <summary>Removes up to <paramref name="n"/> link animations, the last ones first (those just before the first cyclic
    /// one); when the playing one goes, the first cyclic animation starts.</summary>
    // retail: CSequence::remove_link_animations (acclient.c:339953)
    internal void RemoveLinkAnimations(uint n)
    {
        for (uint i = 0; i < n; i++)
        {
            // non-retail: with no cyclic animation (an empty list) retail dereferences a null node; nothing to remove
            AnimSequenceNode? link = _firstCyclic?.GetPrev();
            if (link is null)
            {
                break;
            }

            RemoveLink(link);
        }
    }

    /// <summary>Removes every link animation.</summary>
    // retail: CSequence::remove_all_link_animations (acclient.c:340019)
    internal void RemoveAllLinkAnimations()
    {
        AnimSequenceNode? link;
        while ((link = _firstCyclic?.GetPrev()) is not null)
        {
            RemoveLink(link);
        }
    }

    // The shared body of remove_link_animations and remove_all_link_animations.
    private void RemoveLink(AnimSequenceNode link)
    {
        if (link == _currAnim)
        {
            AnimSequenceNode? first = _firstCyclic;
            _currAnim = first;
            if (first is not null)
            {
                _frameNumber = first.GetStartingFrame();
            }
        }

        Unlink(link);
        ReturnNode(link);
    }

    /// <summary>Drops the animations before the playing one that have played out (up to the first cyclic one).</summary>
    // retail: CSequence::apricot (acclient.c:339892)
    internal void Apricot()
    {
        AnimSequenceNode? node = _head;
        while (node != _currAnim && node != _firstCyclic)
        {
            // node is not null here: curr_anim or first_cyclic is in the list when it is not empty
            Unlink(node!);
            ReturnNode(node!);
            node = _head;
        }
    }

    // DLListBase::InsertAfter: links node after `after`, or at the head when `after` is null.
    private void InsertAfter(AnimSequenceNode node, AnimSequenceNode? after)
    {
        if (after is null)
        {
            node.Prev = null;
            node.Next = _head;
            if (_head is not null)
            {
                _head.Prev = node;
            }
            else
            {
                _tail = node;
            }

            _head = node;
            return;
        }

        node.Prev = after;
        node.Next = after.Next;
        if (after.Next is not null)
        {
            after.Next.Prev = node;
        }
        else
        {
            _tail = node;
        }

        after.Next = node;
    }

    // DLListBase's removal of one node (inlined in every retail caller).
    private void Unlink(AnimSequenceNode node)
    {
        if (node.Prev is not null)
        {
            node.Prev.Next = node.Next;
        }
        else
        {
            _head = node.Next;
        }

        if (node.Next is not null)
        {
            node.Next.Prev = node.Prev;
        }
        else
        {
            _tail = node.Prev;
        }

        node.Next = null;
        node.Prev = null;
    }

    private AnimSequenceNode RentNode()
    {
        AnimSequenceNode? node = _free;
        if (node is null)
        {
            return new AnimSequenceNode();
        }

        _free = node.Next;
        node.Next = null;
        return node;
    }

    private void ReturnNode(AnimSequenceNode node)
    {
        node.Reset();
        node.Next = _free;
        _free = node;
    }
}
