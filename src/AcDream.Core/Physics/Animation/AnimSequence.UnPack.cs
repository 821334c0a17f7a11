using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Animation;

public sealed partial class AnimSequence
{
    /// <summary>
    /// Replaces the sequence with the packed one in <paramref name="data"/> (retail <c>CSequence::UnPack</c>): the animation
    /// count and each animation (id, low, high, framerate); with animations the frame number (a double) and the indices of
    /// the first cyclic and the playing animation, without any the placement frame id; then a bit field (1: velocity
    /// follows, 2: omega follows) and those vectors. The placement frame itself is cleared, as retail clears it.
    /// </summary>
    /// <exception cref="RetailDataFormatException">Truncated; an index past the animations; a framerate outside the domain; a
    /// frame number outside the playing animation's range; a velocity or omega not finite, or a velocity above 50 m/s. The sequence is unchanged.</exception>
    // retail: CSequence::UnPack (acclient.c:340782)
    internal void UnPack(ReadOnlySpan<byte> data)
    {
        var reader = new RetailDataReader(data, "CSequence");
        int numAnims = reader.ReadCount("CSequence num_anims", 16);
        var anims = new AnimData[numAnims];
        for (int i = 0; i < numAnims; i++)
        {
            anims[i] = AnimData.UnPack(ref reader);
        }

        uint placementId = 0;
        double frameNumber = 0.0;
        uint firstCyclicIndex = 0, currIndex = 0;
        int frameAt = 0;
        if (numAnims == 0)
        {
            placementId = reader.ReadUInt32("CSequence placement_frame_id");
        }
        else
        {
            frameAt = reader.Offset;
            frameNumber = BitConverter.Int64BitsToDouble(((long)reader.ReadInt32("CSequence frame_number") & 0xFFFFFFFFL)
                                                         | ((long)reader.ReadInt32("CSequence frame_number") << 32));
            int at = reader.Offset;
            firstCyclicIndex = reader.ReadUInt32("CSequence first_cyclic");
            // non-retail: retail walks GetNext that many times and reads a null node past the end
            if (firstCyclicIndex >= (uint)numAnims)
            {
                throw reader.ErrorAt(at, $"CSequence first_cyclic index {firstCyclicIndex} is past the {numAnims} animations");
            }

            at = reader.Offset;
            currIndex = reader.ReadUInt32("CSequence curr_anim");
            if (currIndex >= (uint)numAnims)
            {
                throw reader.ErrorAt(at, $"CSequence curr_anim index {currIndex} is past the {numAnims} animations");
            }
        }

        uint bits = reader.ReadUInt32("CSequence bitfield");
        Vector3 velocity = Vector3.Zero, omega = Vector3.Zero;
        if ((bits & 1) != 0)
        {
            int at = reader.Offset;
            velocity = ReadFiniteVector(ref reader, "CSequence velocity");
            // non-retail: the sequence velocity's domain, as SimplePartArray.SequenceVelocity's (50 m/s)
            if ((double)velocity.X * velocity.X + (double)velocity.Y * velocity.Y + (double)velocity.Z * velocity.Z
                > (double)InputLimits.MaxSequenceSpeed * InputLimits.MaxSequenceSpeed)
            {
                throw reader.ErrorAt(at, "CSequence velocity exceeds 50 m/s");
            }
        }

        if ((bits & 2) != 0)
        {
            omega = ReadFiniteVector(ref reader, "CSequence omega");
        }

        if (numAnims != 0)
        {
            // non-retail: a frame number outside the playing animation's range made the first update cross every frame
            // in between (or, NaN, none); the bytes are refused
            var probe = new AnimSequenceNode();
            probe.Init(anims[currIndex], _animations);
            if (!(frameNumber >= Math.Min(probe.LowFrame, probe.HighFrame))
                || !(frameNumber <= Math.Max(probe.LowFrame, probe.HighFrame) + 1.0))
            {
                throw reader.ErrorAt(frameAt, $"CSequence frame_number {frameNumber} is outside the playing animation's frames");
            }
        }

        // Everything is read: build the list (retail appends every node, with or without an animation).
        ClearAnimations();
        ClearPhysics();
        _placementFrame = null;
        _placementFrameId = 0;
        AnimSequenceNode? first = null, curr = null;
        for (int i = 0; i < numAnims; i++)
        {
            AnimSequenceNode node = RentNode();
            node.Init(anims[i], _animations);
            InsertAfter(node, _tail);
            PrepareRootMotionMemo(node); // non-retail (#38): the memo is made here, not in the update
            if (i == (int)firstCyclicIndex)
            {
                first = node;
            }

            if (i == (int)currIndex)
            {
                curr = node;
            }
        }

        if (numAnims == 0)
        {
            _placementFrameId = placementId;
        }
        else
        {
            _frameNumber = frameNumber;
            _firstCyclic = first;
            _currAnim = curr;
        }

        _velocity = velocity;
        _omega = omega;
    }

    private static Vector3 ReadFiniteVector(ref RetailDataReader reader, string what)
    {
        float x = reader.ReadFiniteSingle(what), y = reader.ReadFiniteSingle(what), z = reader.ReadFiniteSingle(what);
        return new Vector3(x, y, z);
    }
}
