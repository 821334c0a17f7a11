using System;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Animation;

// non-retail (#38): a memo of the first frame an update crosses. Every update starts from an identity offset frame
// (CPhysicsObj::UpdatePositionInternal hands the part array a fresh one), so the first frame crossed forwards turns the
// identity into apply_physics(combine(Identity, pos_frame[k]), ±|1/framerate|): a pure function of the animation and frame
// k (its root motion, immutable), the node's framerate, the direction (the sign of the quantum, in this loop the framerate's) and the sequence's velocity
// and omega. The sequence keeps the results it worked out, keyed by the bits of all of these, and copies one when the key
// repeats (a cycle playing at a constant velocity): the combine, apply_physics' products, grotate's quaternion product, its
// square root and division and set_rotate's matrix are skipped. The copy is the bits the same code gave before, so the
// result is bit-identical by construction; a result that is not finite is not kept (a NaN's payload is not promised to come
// out of the arithmetic the same way twice). The memo is the sequence's own (a clip is shared by every object that plays
// it, possibly across threads): it is made outside the tick, when an animation with root motion is queued (appended or
// unpacked), so updates allocate nothing. Skipping apply_physics also skips the update of grotate's axis-angle cache
// (_rotation); that cache is keyed by the bits of the displacement and refills on a miss, so the calls that do run give the
// same bits whether or not it was updated.
public sealed partial class AnimSequence
{
    // The memo, or null: none queued with root motion yet, or switched off.
    private RootMotionMemo? _rootMotionMemo;
    private bool _rootMotionMemoOff;

    /// <summary>Whether the update uses the root-motion memo (default true). Tests switch it off to compare the two paths
    /// bit for bit; switching it on again makes the memo for the animations already queued.</summary>
    internal bool UsesRootMotionMemo
    {
        get => !_rootMotionMemoOff;
        set
        {
            _rootMotionMemoOff = !value;
            _rootMotionMemo = null;
            for (AnimSequenceNode? node = _head; value && node is not null; node = node.Next)
            {
                PrepareRootMotionMemo(node);
            }
        }
    }

    /// <summary>The memo's entry count (0: no memo), for the tests.</summary>
    internal int RootMotionMemoSize => _rootMotionMemo?.Entries.Length ?? 0;

    /// <summary>For the tests: the number of entries kept in the current generation (the velocity and omega the last update
    /// from identity saw); with <paramref name="poison"/>, each of them is overwritten with a NaN origin, so that an update
    /// that reads one shows it.</summary>
    internal int RootMotionMemoEntries(bool poison = false)
    {
        int n = 0;
        RootMotionMemo? memo = _rootMotionMemo;
        for (int i = 0; memo is not null && i < memo.Entries.Length; i++)
        {
            ref RootMotionMemo.Entry e = ref memo.Entries[i];
            if (e.Generation == memo.Generation)
            {
                n++;
                if (poison)
                {
                    e.Result.Origin = new System.Numerics.Vector3(float.NaN);
                }
            }
        }

        return n;
    }

    // Makes (or widens) the memo for a node just queued whose animation has root motion (outside the update).
    private void PrepareRootMotionMemo(AnimSequenceNode node)
    {
        AnimClip? clip = node.Anim;
        if (_rootMotionMemoOff || clip?.PosFromIdentityArray is null)
        {
            return;
        }

        int size = RootMotionMemo.SizeFor(clip.NumFrames);
        if (_rootMotionMemo is null || _rootMotionMemo.Entries.Length < size)
        {
            _rootMotionMemo = new RootMotionMemo(size);
        }
    }

    /// <summary>
    /// The first forward frame of an update from the memo: when <paramref name="retval"/> is the identity (every bit),
    /// the animation has root motion without a non-finite frame, frame <paramref name="fn"/> is in it and the framerate moves,
    /// sets <paramref name="retval"/> to what <see cref="AnimSequenceNode.CombinePosFrame"/> then
    /// <see cref="ApplyPhysics"/>(1/framerate, <paramref name="quantum"/>) give (from the memo, or worked out and kept) and
    /// returns true; otherwise false and <paramref name="retval"/> untouched.
    /// </summary>
    // non-retail (#38): the memo of CSequence::update_internal's first crossed frame (combine, then apply_physics)
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private bool TryRootMotionFromMemo(RootMotionMemo memo, AnimSequenceNode curr, int fn, double quantum, ref Frame retval)
    {
        AnimClip? clip = curr.Anim;
        Frame[]? fromIdentity = clip?.PosFromIdentityArray;
        float framerate = curr.Framerate;
        if (fromIdentity is null || (uint)fn >= (uint)fromIdentity.Length || fn >= clip!.NumFrames
            || !(Math.Abs((double)framerate) > Epsilon) || !retval.HasIdentityBits())
        {
            return false;
        }

        if (((BitConverter.SingleToInt32Bits(_velocity.X) ^ memo.VelocityX) | (BitConverter.SingleToInt32Bits(_velocity.Y) ^ memo.VelocityY)
             | (BitConverter.SingleToInt32Bits(_velocity.Z) ^ memo.VelocityZ) | (BitConverter.SingleToInt32Bits(_omega.X) ^ memo.OmegaX)
             | (BitConverter.SingleToInt32Bits(_omega.Y) ^ memo.OmegaY) | (BitConverter.SingleToInt32Bits(_omega.Z) ^ memo.OmegaZ)) != 0)
        {
            memo.Rekey(_velocity, _omega);
        }

        // The direction (the quantum's sign) is the framerate's: the forward loop runs only when framerate × quantum > 0, so
        // the framerate's bits key it too.
        ref RootMotionMemo.Entry e = ref memo.Entries[fn & (memo.Entries.Length - 1)];
        if (e.Generation == memo.Generation && e.Clip == clip && e.FrameIndex == fn
            && e.FramerateBits == BitConverter.SingleToInt32Bits(framerate))
        {
            retval = e.Result;
            return true;
        }

        RootMotionMiss(ref e, memo.Generation, curr, fn, framerate, quantum, ref retval);
        return true;
    }

    // The memo's miss, out of line: what CombinePosFrame and ApplyPhysics do from an identity frame, kept when finite.
    [MethodImpl(MethodImplOptions.NoInlining)]
    private void RootMotionMiss(ref RootMotionMemo.Entry e, uint generation, AnimSequenceNode curr, int fn, float framerate,
        double quantum, ref Frame retval)
    {
        curr.CombinePosFrame(fn, ref retval);
        ApplyPhysics(ref retval, 1.0 / (double)framerate, quantum);
        if (VectorMath.IsFinite(retval.Origin) && VectorMath.IsFinite(retval.Rotation))
        {
            e.Result = retval;
            e.Clip = curr.Anim;
            e.FrameIndex = fn;
            e.FramerateBits = BitConverter.SingleToInt32Bits(framerate);
            e.Generation = generation;
        }
        else
        {
            e.Generation = 0;
        }
    }

    /// <summary>The kept first frames of one sequence: a direct-mapped table indexed by the frame number's low bits, all of
    /// one velocity and omega (a new one empties the table by moving on to the next generation).</summary>
    private sealed class RootMotionMemo
    {
        // At most 32 entries of 88 B (2,816 B plus the array's and this object's headers and fields, about 2.9 KB).
        internal const int MaxSize = 32;

        internal readonly Entry[] Entries;

        // The bits of the velocity and omega the entries of this generation were worked out with.
        internal int VelocityX, VelocityY, VelocityZ, OmegaX, OmegaY, OmegaZ;

        // The entries of other generations are empty; 0 is never current (an entry not yet filled has generation 0).
        internal uint Generation = 1;

        internal RootMotionMemo(int size)
        {
            Entries = new Entry[size];
        }

        // The least power of two at or above the animation's frame count, at most MaxSize.
        internal static int SizeFor(int numFrames)
        {
            int size = 1;
            while (size < numFrames && size < MaxSize)
            {
                size <<= 1;
            }

            return size;
        }

        // A new velocity or omega: every entry is of an older generation. On the wrap-around (after 2^32 - 1 changes) the
        // entries are cleared, so that none comes back.
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal void Rekey(System.Numerics.Vector3 velocity, System.Numerics.Vector3 omega)
        {
            VelocityX = BitConverter.SingleToInt32Bits(velocity.X);
            VelocityY = BitConverter.SingleToInt32Bits(velocity.Y);
            VelocityZ = BitConverter.SingleToInt32Bits(velocity.Z);
            OmegaX = BitConverter.SingleToInt32Bits(omega.X);
            OmegaY = BitConverter.SingleToInt32Bits(omega.Y);
            OmegaZ = BitConverter.SingleToInt32Bits(omega.Z);
            if (++Generation == 0)
            {
                Array.Clear(Entries);
                Generation = 1;
            }
        }

        /// <summary>One kept result and its key (the velocity and omega are the table's).</summary>
        internal struct Entry
        {
            internal Frame Result;
            internal AnimClip? Clip;
            internal int FrameIndex;
            internal int FramerateBits;
            internal uint Generation;
        }
    }
}
