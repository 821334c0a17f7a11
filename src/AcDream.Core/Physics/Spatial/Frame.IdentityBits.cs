using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace AcDream.Core.Physics.Spatial;

public partial struct Frame
{
    // Frame.Identity's 64 bytes (quaternion, matrix, origin: 16 floats), as two 32-byte halves.
    private static readonly Vector256<uint> s_identityLow = Vector256.LoadUnsafe(ref Unsafe.As<Frame, uint>(ref Unsafe.AsRef(in s_identity)));
    private static readonly Vector256<uint> s_identityHigh = Vector256.LoadUnsafe(ref Unsafe.As<Frame, uint>(ref Unsafe.AsRef(in s_identity)), 8);

    /// <summary>True when every bit of this frame is <see cref="Identity"/>'s (so -0 is not 0 and no NaN matches): an
    /// operation on this frame then gives what it gives on <see cref="Identity"/>, bit for bit.</summary>
    // non-retail (#38): the test of the root-motion shortcut (AnimClip's combine from identity)
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal readonly bool HasIdentityBits()
    {
        ref uint first = ref Unsafe.As<Frame, uint>(ref Unsafe.AsRef(in this));
        return Vector256.LoadUnsafe(ref first) == s_identityLow && Vector256.LoadUnsafe(ref first, 8) == s_identityHigh;
    }
}
