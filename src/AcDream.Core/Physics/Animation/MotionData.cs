using System.Numerics;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// One entry of a motion table: the animations a cycle, link or modifier plays and the velocity and omega it moves the
/// body by (retail <c>MotionData</c>, PORTAL/canim/CMotionPrim.c; 0x34 bytes: the hash id, num_anims, anims, velocity, omega,
/// bitfield).
/// </summary>
internal sealed class MotionData
{
    /// <summary>Bit 0 of <see cref="Bitfield"/>: playing this clears the modifiers (tested as <c>bitfield &amp; 1</c> in
    /// <c>GetObjectSequence</c>).</summary>
    public const byte ClearsModifiers = 1;

    /// <summary>Bit 1 of <see cref="Bitfield"/>: allowed only from the style's default substate (<c>is_allowed</c>).</summary>
    public const byte OnlyFromDefault = 2;

    // AnimData::UnPack reads four dwords.
    private const int AnimDataPackedSize = 16;

    /// <summary>The hash key the entry is stored under (retail <c>LongHashData::id</c>).</summary>
    public uint Id;

    /// <summary>The animations, played in order (retail <c>anims</c>, <c>num_anims</c> long; <c>num_anims</c> is a signed
    /// char in retail, so the unpacker accepts 0..127 only).</summary>
    public AnimData[] Anims = System.Array.Empty<AnimData>();

    /// <summary>Velocity at speed 1, object-local m/s (retail <c>velocity</c>).</summary>
    public Vector3 Velocity;

    /// <summary>Angular velocity at speed 1, object-local rad/s (retail <c>omega</c>).</summary>
    public Vector3 Omega;

    /// <summary>Retail <c>bitfield</c> (<see cref="ClearsModifiers"/>, <see cref="OnlyFromDefault"/>).</summary>
    public byte Bitfield;

    /// <summary>Retail <c>num_anims</c>: the number of animations.</summary>
    public int NumAnims => Anims.Length;

    /// <summary>Reads one entry: id, num_anims (byte), bitfield (byte), the physics flags (byte: 1 velocity, 2 omega), padding
    /// to four bytes, the animations (<c>AnimData::UnPack</c> each), then the velocity and the omega when flagged (zero
    /// otherwise).</summary>
    /// <exception cref="RetailDataFormatException">The bytes end early.</exception>
    // retail: MotionData::UnPack (acclient.c:341813)
    public static MotionData UnPack(ref RetailDataReader r)
    {
        var d = new MotionData();
        d.Id = r.ReadUInt32("MotionData id");
        int numAnimsAt = r.Offset;
        byte numAnims = r.ReadByte("MotionData num_anims");
        // non-retail: num_anims is a signed char; retail sizes the array by the byte (unsigned) but runs its read loop
        // (`v14 < num_anims`, unsigned against the sign-extended count) and GetObjectSequence's sums on the signed value, so a
        // count of 128..255 reads past the array: refused (docs/divergences.md)
        if (numAnims > sbyte.MaxValue)
        {
            throw r.ErrorAt(numAnimsAt, $"MotionData num_anims {numAnims} is above 127 (a signed char in retail)");
        }

        d.Bitfield = r.ReadByte("MotionData bitfield");
        byte physics = r.ReadByte("MotionData physics flags");
        r.Align4();
        // An AnimData is 16 bytes (AnimData::UnPack reads four dwords), so the count is checked before the array is made.
        int n = (int)r.CheckCount(numAnims, "MotionData anims", AnimDataPackedSize, numAnimsAt);
        if (n != 0)
        {
            d.Anims = new AnimData[n];
            for (int i = 0; i < n; i++)
            {
                d.Anims[i] = AnimData.UnPack(ref r);
            }
        }

        // Retail reads each vector only when size >= 12 and otherwise leaves it unset; the reader's bounds check makes a short
        // buffer a format error instead.
        d.Velocity = (physics & 1) != 0 ? ReadFinite(ref r, "MotionData velocity") : Vector3.Zero;
        d.Omega = (physics & 2) != 0 ? ReadFinite(ref r, "MotionData omega") : Vector3.Zero;
        return d;
    }

    // non-retail: a NaN or infinite vector, or one longer than InputLimits.MaxSequenceSpeed (50, retail's max velocity), is
    // refused (retail would move the body to NaN or kilometres a tick); see docs/divergences.md.
    private static Vector3 ReadFinite(ref RetailDataReader r, string what)
    {
        int at = r.Offset;
        Vector3 v = r.ReadVector3(what);
        if (!float.IsFinite(v.X) || !float.IsFinite(v.Y) || !float.IsFinite(v.Z))
        {
            throw r.ErrorAt(at, $"{what} is not finite");
        }

        double len2 = (double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z;
        if (len2 > (double)Spatial.InputLimits.MaxSequenceSpeed * Spatial.InputLimits.MaxSequenceSpeed)
        {
            throw r.ErrorAt(at, $"{what} is longer than {Spatial.InputLimits.MaxSequenceSpeed}");
        }

        return v;
    }
}
