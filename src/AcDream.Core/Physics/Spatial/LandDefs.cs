using System;
using System.Numerics;

namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// Retail land geometry: landblocks, outdoor cells and cell ids, ported from <c>LandDefs</c>
/// (PORTAL/geometry/LandDefs.c and helpers elsewhere in acclient.exe 11.4186).
/// </summary>
/// <remarks>
/// <para>A cell id is <c>0xXXYYCCCC</c>: XX the landblock column (west to east), YY the landblock row (south to north),
/// CCCC the cell within it. Outdoor cells are 1..64 (0x01..0x40), numbered column-major: cell = x * 8 + y + 1
/// for the 24 m cell at column x, row y inside the block. Indoor (environment) cells are 0x100..0xFFFD; 0xFFFE is the
/// landblock info and 0xFFFF the landblock itself.</para>
/// <para>"lcoord" is a global outdoor cell coordinate: lcoord x = block x * 8 + cell column, 0..2039 on each axis.</para>
/// <para>Positions are local to their landblock: x and y run 0..192 m inside it; +Y is north, +Z is up.</para>
/// </remarks>
public static class LandDefs
{
    /// <summary>Side of an outdoor cell, in metres. Retail: <c>cell_size = 24.0</c> (LandDefs::get_vars, acclient.c:467308).</summary>
    public const float CellLength = 24.0f;

    /// <summary>Cells along one side of a landblock. Retail: <c>cells_per_block = 8</c>.</summary>
    public const int BlockSide = 8;

    /// <summary>Side of a landblock, in metres: 24 * 8 = 192 (retail <c>flt_8EDE44 = 24.0 * 8.0</c>, acclient.c:800515).</summary>
    public const float BlockLength = CellLength * BlockSide;

    /// <summary>Half a cell, in metres (retail <c>24.0 * 0.5</c>, acclient.c:800521).</summary>
    public const float HalfCellLength = CellLength * 0.5f;

    /// <summary>Landblocks along one side of the world. Retail: <c>height = width = 255</c>.</summary>
    public const int LandblocksPerSide = 255;

    /// <summary>Outdoor cells along one side of the world: 255 * 8 = 2040 (the bound in <c>LandDefs::in_bounds</c>).</summary>
    public const int LCoordLimit = LandblocksPerSide * BlockSide;

    /// <summary>Outdoor cells in one landblock (8 x 8).</summary>
    public const int CellsPerBlock = BlockSide * BlockSide;

    /// <summary>Vertices along one side of a landblock's height grid (9).</summary>
    public const int VertexSide = BlockSide + 1;

    /// <summary>Largest object height, in metres. Retail: <c>max_obj_height = 200.0</c>.</summary>
    public const float MaxObjHeight = 200.0f;

    /// <summary>Sky height, in metres. Retail: <c>sky_height = 1000.0</c>.</summary>
    public const float SkyHeight = 1000.0f;

    /// <summary>Road width, in metres. Retail: <c>road_width = 5.0</c>.</summary>
    public const float RoadWidth = 5.0f;

    /// <summary>The lowest outdoor cell number (1).</summary>
    public const ushort FirstOutdoorCell = 0x0001;

    /// <summary>The highest outdoor cell number (64).</summary>
    public const ushort LastOutdoorCell = 0x0040;

    /// <summary>The lowest indoor (environment) cell number.</summary>
    public const ushort FirstEnvCell = 0x0100;

    /// <summary>The highest indoor (environment) cell number.</summary>
    public const ushort LastEnvCell = 0xFFFD;

    /// <summary>True when <paramref name="cellId"/>'s low word is an outdoor cell (1..64).</summary>
    public static bool IsOutdoorCell(uint cellId)
    {
        uint c = cellId & 0xFFFF;
        return c >= FirstOutdoorCell && c <= LastOutdoorCell;
    }

    /// <summary>True when <paramref name="cellId"/>'s low word is an indoor cell (0x100..0xFFFD).</summary>
    public static bool IsEnvCell(uint cellId)
    {
        uint c = cellId & 0xFFFF;
        return c >= FirstEnvCell && c <= LastEnvCell;
    }

    /// <summary>The landblock id of a cell: its high word with the low word set to 0xFFFF.</summary>
    public static uint BlockIdOf(uint cellId) => (cellId & 0xFFFF0000u) | 0xFFFFu;

    /// <summary>
    /// The id of the outdoor cell that contains the point (<paramref name="x"/>, <paramref name="y"/>) of a landblock:
    /// <c>0xXXYY0000 | (cx · 8 + cy + 1)</c>, with cx = ⌊x / 24⌋ and cy = ⌊y / 24⌋ the point's 24 m cell column and row
    /// (docs/terrain.md). Library helper (no retail symbol; the numbering is retail's <c>LandDefs::lcoord_to_gid</c>).
    /// </summary>
    /// <param name="landblockId">The landblock, 0xXXYYFFFF (the low word is ignored, so any cell id of the landblock serves);
    /// XX and YY in 0x00..0xFE.</param>
    /// <param name="x">East coordinate local to the landblock, metres: finite, in [0, 192).</param>
    /// <param name="y">North coordinate local to the landblock, metres: finite, in [0, 192).</param>
    /// <returns>The outdoor cell id, e.g. 0xA9B40025 for (100, 100) in landblock 0xA9B4FFFF (cell column 4, row 4:
    /// 4 · 8 + 4 + 1 = 37 = 0x25).</returns>
    /// <exception cref="ArgumentOutOfRangeException">The landblock lies outside the world (XX or YY is 0xFF), or x or y is
    /// NaN, infinite or outside [0, 192) (a point beyond the edge belongs to another landblock: re-home it with
    /// <see cref="Position.TryAdjustToOutside"/>).</exception>
    public static uint OutdoorCellId(uint landblockId, float x, float y)
    {
        if ((landblockId >> 24) >= LandblocksPerSide || ((landblockId >> 16) & 0xFFu) >= LandblocksPerSide)
        {
            throw new ArgumentOutOfRangeException(nameof(landblockId), landblockId,
                "The landblock's column and row (0xXXYY....) must be 0x00..0xFE: 0xFF lies outside the world.");
        }

        ThrowIfOutsideBlock(x, nameof(x));
        ThrowIfOutsideBlock(y, nameof(y));
        uint cx = (uint)(x / CellLength);
        uint cy = (uint)(y / CellLength);
        return (landblockId & 0xFFFF0000u) | (cx * BlockSide + cy + 1u);
    }

    private static void ThrowIfOutsideBlock(float v, string paramName)
    {
        if (!(v >= 0f && v < BlockLength))
        {
            throw new ArgumentOutOfRangeException(paramName, v,
                "A landblock-local coordinate must be finite and in [0, 192) metres; beyond the edge it belongs to another landblock.");
        }
    }

    /// <summary>
    /// True when global outdoor cell coordinates lie inside the world.
    /// </summary>
    // retail: LandDefs::in_bounds (acclient.c:122253)
    public static bool InBounds(int x, int y) => x >= 0 && y >= 0 && x < LCoordLimit && y < LCoordLimit;

    /// <summary>
    /// The lcoord of the south-west cell of the landblock of <paramref name="blockId"/>; false for id 0 or out of bounds.
    /// </summary>
    // retail: LandDefs::blockid_to_lcoord (acclient.c:122259)
    public static bool BlockIdToLCoord(uint blockId, out int x, out int y)
    {
        x = 0;
        y = 0;
        if (blockId == 0)
        {
            return false;
        }

        x = (int)((blockId >> 21) & 0x7F8);
        y = 8 * (int)((blockId >> 16) & 0xFF);
        return x >= 0 && x < LCoordLimit && y < LCoordLimit;
    }

    /// <summary>
    /// True when the cell number is outdoor (1..64), indoor (0x100..0xFFFD) or the block itself (0xFFFF), and its landblock
    /// lies inside the world.
    /// </summary>
    // retail: LandDefs::inbound_valid_cellid (acclient.c:209467)
    public static bool InboundValidCellId(uint cellId)
    {
        uint c = cellId & 0xFFFF;
        if (!((c >= 1 && c <= 0x40) || (c >= 0x100 && c <= 0xFFFD) || c == 0xFFFF))
        {
            return false;
        }

        int x = (int)((cellId >> 21) & 0x7F8);
        int y = (int)((cellId >> 13) & 0x7F8);
        return x < LCoordLimit && y < LCoordLimit;
    }

    /// <summary>
    /// The global lcoord of an outdoor cell id; false for an indoor or invalid id.
    /// </summary>
    // retail: LandDefs::gid_to_lcoord (acclient.c:209520)
    public static bool GidToLCoord(uint cellId, out int x, out int y)
    {
        x = 0;
        y = 0;
        if (!InboundValidCellId(cellId) || (cellId & 0xFFFF) >= 0x100)
        {
            return false;
        }

        uint c = cellId & 0xFFFF;
        x = (int)((cellId >> 21) & 0x7F8) + (int)((c - 1) >> 3);
        y = 8 * (int)((cellId >> 16) & 0xFF) + (int)((c - 1) & 7);
        return x >= 0 && y >= 0 && x < LCoordLimit && y < LCoordLimit;
    }

    /// <summary>
    /// The outdoor cell id at global lcoord (x, y), or 0 when it lies outside the world.
    /// </summary>
    // retail: LandDefs::lcoord_to_gid (acclient.c:218181)
    public static uint LCoordToGid(int x, int y)
    {
        if (x < 0 || y < 0 || x >= LCoordLimit || y >= LCoordLimit)
        {
            return 0;
        }

        uint block = ((uint)(y >> 3)) | (32u * (uint)(x & ~7));
        return (block << 16) | (uint)((y & 7) + 8 * (x & 7) + 1);
    }

    /// <summary>
    /// The offset, in metres, from the landblock of <paramref name="cellFrom"/> to that of <paramref name="cellTo"/>
    /// (zero within one landblock; z is always 0). Adding it to a position local to <paramref name="cellTo"/>'s block
    /// expresses that position in <paramref name="cellFrom"/>'s block.
    /// </summary>
    /// <remarks>Retail quirk kept: a <paramref name="cellTo"/> of 0 uses the raw <paramref name="cellFrom"/> id as both
    /// coordinates. Retail never passes 0 there in practice.</remarks>
    // retail: LandDefs::get_block_offset (acclient.c:123109)
    public static Vector3 GetBlockOffset(uint cellFrom, uint cellTo)
    {
        if ((cellFrom >> 16) == (cellTo >> 16))
        {
            return Vector3.Zero;
        }

        int fromX = 0, fromY = 0;
        if (cellFrom != 0)
        {
            fromX = (int)((cellFrom >> 21) & 0x7F8);
            fromY = 8 * (int)((cellFrom >> 16) & 0xFF);
        }

        int toX, toY;
        if (cellTo != 0)
        {
            toX = (int)((cellTo >> 21) & 0x7F8);
            toY = 8 * (int)((cellTo >> 16) & 0xFF);
        }
        else
        {
            toX = (int)cellFrom;
            toY = (int)cellFrom;
        }

        return new Vector3((float)((double)(toX - fromX) * 24.0), (float)((double)(toY - fromY) * 24.0), 0f);
    }

    /// <summary>
    /// The global lcoord of the outdoor cell that contains <paramref name="loc"/> (local to <paramref name="cellId"/>'s
    /// landblock, possibly outside it); false when the id is not a cell id or the result leaves the world.
    /// </summary>
    // retail: LandDefs::get_outside_lcoord (acclient.c:467410)
    public static bool GetOutsideLCoord(uint cellId, Vector3 loc, out int x, out int y)
    {
        x = 0;
        y = 0;
        uint c = cellId & 0xFFFF;
        if (!((c >= 1 && c <= 0x40) || (c >= 0x100 && c <= 0xFFFD) || c == 0xFFFF))
        {
            return false;
        }

        BlockIdToLCoord(cellId, out x, out y);
        x += FloorToInt((double)loc.X / 24.0);
        y += FloorToInt((double)loc.Y / 24.0);
        return x >= 0 && y >= 0 && x < LCoordLimit && y < LCoordLimit;
    }

    /// <summary>
    /// Re-homes a position that has crossed a cell or landblock edge: finds the outdoor cell that contains
    /// <paramref name="loc"/>, sets <paramref name="cellId"/> to it and wraps <paramref name="loc"/> x and y into 0..192
    /// of the new landblock. Returns false and sets <paramref name="cellId"/> to 0 past the world edge (retail behaviour;
    /// <see cref="Position.TryAdjustToOutside"/> is the non-destructive form).
    /// </summary>
    /// <remarks>As retail, an x or y within <see cref="PhysicsGlobals.Epsilon"/> of zero is first snapped to exactly 0,
    /// so that -0.0001 stays in the current block rather than falling into the western or southern neighbour.</remarks>
    // retail: LandDefs::adjust_to_outside (acclient.c:467433)
    public static bool AdjustToOutside(ref uint cellId, ref Vector3 loc)
    {
        uint c = cellId & 0xFFFF;
        if (!((c >= 1 && c <= 0x40) || (c >= 0x100 && c <= 0xFFFD) || c == 0xFFFF))
        {
            cellId = 0;
            return false;
        }

        if (Math.Abs(loc.X) < PhysicsGlobals.Epsilon)
        {
            loc.X = 0f;
        }

        if (Math.Abs(loc.Y) < PhysicsGlobals.Epsilon)
        {
            loc.Y = 0f;
        }

        if (!GetOutsideLCoord(cellId, loc, out int x, out int y))
        {
            cellId = 0;
            return false;
        }

        cellId = LCoordToGid(x, y);
        loc.X = (float)(loc.X - Math.Floor(loc.X / (double)BlockLength) * BlockLength);
        loc.Y = (float)(loc.Y - Math.Floor(loc.Y / (double)BlockLength) * BlockLength);
        return true;
    }

    /// <summary>
    /// True when a sphere of <paramref name="radius"/> centred at <paramref name="vc"/> (block-local) lies wholly inside
    /// the landblock in x and y.
    /// </summary>
    // retail: LandDefs::within_block (acclient.c:315582)
    public static bool WithinBlock(Vector3 vc, float radius)
    {
        if (vc.X >= (double)radius && vc.Y >= (double)radius)
        {
            float far = BlockLength - radius;
            return far > vc.X && far > vc.Y;
        }

        return false;
    }

    // Retail converts floor() through __ftol2 to a 64-bit integer and keeps the low 32 bits.
    private static int FloorToInt(double v) => unchecked((int)(long)Math.Floor(v));
}
