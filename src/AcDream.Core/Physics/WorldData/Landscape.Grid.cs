using System;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.WorldData;

// The grid's arithmetic: the shift between two load points, each slot's level of detail, the block id of a slot, and the
// plan of update_block (which blocks stay, move, leave or are read), computed before anything changes.
public sealed partial class Landscape
{
    /// <summary>The shift in blocks from <paramref name="cellId1"/>'s block to <paramref name="cellId2"/>'s (a cell id of 0 is
    /// block (0, 0)); false, with no shift, when <paramref name="cellId1"/> is 0.</summary>
    // retail: LScape::get_block_shift (acclient.c:306318)
    internal static bool GetBlockShift(uint cellId1, uint cellId2, out int xShift, out int yShift)
    {
        xShift = 0;
        yShift = 0;
        if (cellId1 == 0)
        {
            return false;
        }

        int x2 = cellId2 != 0 ? (int)((cellId2 >> 21) & 0x7F8u) : 0;
        int y2 = cellId2 != 0 ? 8 * (int)((cellId2 >> 16) & 0xFFu) : 0;
        xShift = (x2 - (int)((cellId1 >> 21) & 0x7F8u)) / 8;
        yShift = (y2 - 8 * (int)((cellId1 >> 16) & 0xFFu)) / 8;
        return true;
    }

    /// <summary>A slot's level of detail and direction from the centre of a grid of radius <paramref name="midRadius"/>.</summary>
    // retail: LScape::get_block_orient (acclient.c:306680)
    internal static void GetBlockOrient(int midRadius, int ix, int iy, out int size, out LandscapeDirection dir)
    {
        int dy = iy - midRadius;
        int dx = ix - midRadius;
        int ring = Math.Max(Math.Abs(dx), Math.Abs(dy));
        int v;
        if (ring <= 1)
        {
            v = size = 1;
        }
        else if (ring <= 2)
        {
            v = size = 2;
        }
        else if (ring <= 4)
        {
            v = size = 4;
        }
        else
        {
            size = 8;
            dir = LandscapeDirection.InViewerBlock;
            return;
        }

        if (dx == v)
        {
            dir = dy == v ? LandscapeDirection.Northeast : dy != -v ? LandscapeDirection.East : LandscapeDirection.Southeast;
        }
        else if (dx == -v)
        {
            dir = dy == v ? LandscapeDirection.Northwest : dy == -v ? LandscapeDirection.Southwest : LandscapeDirection.West;
        }
        else if (dy == v)
        {
            dir = LandscapeDirection.North;
        }
        else
        {
            dir = dy != -v ? LandscapeDirection.InViewerBlock : LandscapeDirection.South;
        }
    }

    /// <summary>The landblock id at landscape coordinates (<paramref name="x"/>, <paramref name="y"/>) in cell units; 0
    /// outside the world.</summary>
    // retail: LandDefs::get_block_did (acclient.c:306907)
    internal static uint GetBlockDid(int x, int y) =>
        x < 0 || y < 0 || x >= LandDefs.LCoordLimit || y >= LandDefs.LCoordLimit
            ? 0u
            : ((uint)((y >> 3) | (32 * (x & ~7))) << 16) | 0xFFFFu;

    // One slot of update_block's new grid: the block it holds (kept, moved or read), and the world part it will need.
    private struct SlotPlan
    {
        public LandscapeBlock? Block;      // the slot's block after the update (null: empty)
        public bool Fetched;               // read by this update (entered the grid)
        public int Size;
        public LandscapeDirection Dir;
        public WorldLoader.PendingBlock? Promote; // read for full detail (the block reaches it)
        public bool Demote;                 // leaves full detail
    }

    /// <summary>
    /// The plan of <c>update_block</c> for load point <paramref name="cellId"/>: each new slot's block (kept from the old grid,
    /// moved by the shift, or read from the data source), the old blocks that leave, and each slot's level of detail with the
    /// world part to build or release. Reads every entry it needs; changes nothing.
    /// </summary>
    // retail: LScape::update_block (acclient.c:307785), its choice of blocks; the changes are made by ApplyGrid
    private SlotPlan[] PlanUpdateBlock(LandscapeBlock?[]? old, uint cellId, int xShift, int yShift, bool refresh,
        out LandscapeBlock[] leaving)
    {
        int r = MidRadius;
        int w = MidWidth;
        LandDefs.GidToLCoord(cellId, out int cx, out int cy);
        int baseX = cx - 8 * r;
        int baseY = cy - 8 * r;
        var plan = new SlotPlan[w * w];
        bool reload = old is null || refresh || xShift >= w || yShift >= w || xShift <= -w || yShift <= -w;
        var kept = new bool[w * w];
        for (int ix = 0; ix < w; ix++)
        {
            for (int iy = 0; iy < w; iy++)
            {
                int i = ix * w + iy;
                int ox = ix + xShift, oy = iy + yShift;
                if (!reload && (uint)ox < (uint)w && (uint)oy < (uint)w && (old![ox * w + oy] is not null || xShift != 0 || yShift != 0))
                {
                    // moved (or kept) from the old grid, empty slots included when the grid shifted
                    plan[i].Block = old![ox * w + oy];
                    if (plan[i].Block is not null)
                    {
                        kept[ox * w + oy] = true;
                    }
                }
                else
                {
                    plan[i].Block = Fetch(baseX + 8 * ix, baseY + 8 * iy);
                    plan[i].Fetched = plan[i].Block is not null;
                }
            }
        }

        // The old blocks no slot keeps, in retail's traversal order (the shift's direction).
        var left = new System.Collections.Generic.List<LandscapeBlock>();
        if (old is not null)
        {
            for (int a = 0; a < w; a++)
            {
                int ix = reload || xShift >= 0 ? a : w - 1 - a;
                for (int c = 0; c < w; c++)
                {
                    int iy = reload || yShift >= 0 ? c : w - 1 - c;
                    LandscapeBlock? b = old[ix * w + iy];
                    if (b is not null && !kept[ix * w + iy])
                    {
                        left.Add(b);
                    }
                }
            }
        }

        leaving = left.ToArray();

        // Levels of detail, and the world parts to read for blocks reaching full detail.
        for (int ix = 0; ix < w; ix++)
        {
            for (int iy = 0; iy < w; iy++)
            {
                ref SlotPlan s = ref plan[ix * w + iy];
                if (s.Block is null)
                {
                    continue;
                }

                GetBlockOrient(r, ix, iy, out s.Size, out s.Dir);
                bool wasFull = !s.Fetched && s.Block.Loaded is not null;
                if (s.Size == 1 && !wasFull)
                {
                    s.Promote = _loader.Read(s.Block.BlockId, withEnvCells: false);
                }
                else if (s.Size != 1 && wasFull)
                {
                    s.Demote = true;
                }
            }
        }

        return plan;
    }

    // The block at landscape coordinates (x, y): null outside the world or when the source has no landblock entry there
    // (retail's DBObj::Get failing). Bad bytes throw (nothing has changed yet).
    // retail: LScape::get_all (acclient.c:307435), with LandDefs::in_bounds (acclient.c:122253)
    private LandscapeBlock? Fetch(int x, int y)
    {
        if (!LandDefs.InBounds(x, y))
        {
            return null;
        }

        uint id = GetBlockDid(x, y);
        if (!_source.TryGetEntry(id, out ReadOnlyMemory<byte> bytes))
        {
            return null;
        }

        LandBlockEntry entry = LandBlockEntry.UnPack(bytes.Span);
        WorldLoader.Expect("CLandBlock", entry.Id, id);

        return new LandscapeBlock(id, entry);
    }
}
