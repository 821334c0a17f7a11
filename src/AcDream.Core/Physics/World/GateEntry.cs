namespace AcDream.Core.Physics;

/// <summary>
/// A dormant object waiting in a <see cref="GateQueue"/>: what a re-measurement against the 96 m gate needs, so that it reads
/// no object. The position is the object's own (landblock coordinates and local origin).
/// </summary>
internal struct GateEntry
{
    /// <summary>Clock reading (metres) at which the object must be re-measured.</summary>
    public double Key;

    /// <summary>Local origin, as the object's position holds it.</summary>
    public float X, Y, Z;

    /// <summary>The object's slot in its queue.</summary>
    public int Slot;

    /// <summary>The slot's generation when the entry was made (a mismatch marks the entry stale).</summary>
    public int Generation;

    /// <summary>Landblock x and y of the object's cell.</summary>
    public byte BlockX, BlockY;

    /// <summary><see cref="GateFlags"/>.</summary>
    public byte Flags;

    /// <summary>True when the object was beyond 96 m at its last measurement.</summary>
    public bool Far
    {
        readonly get => (Flags & GateFlags.Far) != 0;
        set => Flags = (byte)(value ? Flags | GateFlags.Far : Flags & ~GateFlags.Far);
    }

    /// <summary>The entry's global position: block offsets are whole multiples of 192 m (as <c>LandDefs::get_block_offset</c>),
    /// so differences of these agree with <c>Position::get_offset</c> to float rounding.</summary>
    public readonly void Global(out double x, out double y, out double z)
    {
        x = BlockX * (double)LandDefs.BlockLength + X;
        y = BlockY * (double)LandDefs.BlockLength + Y;
        z = Z;
    }

    /// <summary>A position's global x, y, z, in the same frame as the entries'.</summary>
    public static void Global(in Position p, out double x, out double y, out double z)
    {
        uint cell = p.ObjCellId;
        x = ((cell >> 24) & 0xFF) * (double)LandDefs.BlockLength + p.Frame.Origin.X;
        y = ((cell >> 16) & 0xFF) * (double)LandDefs.BlockLength + p.Frame.Origin.Y;
        z = p.Frame.Origin.Z;
    }
}

/// <summary>Bits of <see cref="GateEntry.Flags"/>.</summary>
internal static class GateFlags
{
    /// <summary>Beyond 96 m at the last measurement.</summary>
    public const byte Far = 1;

    /// <summary>Idle: a visit on either side of the gate changes nothing but bookkeeping, so a crossing needs no visit.</summary>
    public const byte Idle = 2;

    /// <summary>On walkable ground (within 96 m it then re-activates every other tick).</summary>
    public const byte OnWalkable = 4;
}
