using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.World;

// Retail's lost cells (CObjectMaint::lost_cell_table): the objects that left visibility because their cell was not loaded,
// kept by the id of the cell their position names, and put back when that cell is initialised again (the landscape loading
// the block under them). World state: retail's table hangs off the one CObjectMaint.
public sealed partial class PhysicsWorld
{
    // Retail IntrusiveHashTable<unsigned long, CLostCell*>: cell id -> the first and last object lost in it; the objects of a
    // lost cell are chained through PhysicsObj.LostNext in the order they were lost (retail appends to the cell's array).
    // Sized once so that losing and finding objects allocates nothing in a tick.
    private readonly Dictionary<uint, LostCell> _lostCells = new(LostCellCapacity);

    private const int LostCellCapacity = 64;

    private int _lostObjectCount;

    /// <summary>The number of objects waiting in lost cells for their cell to be loaded again.</summary>
    /// <remarks>Retail: <c>CObjectMaint::lost_cell_table</c>. An object is lost when it is placed, moved or left in a cell that
    /// is not loaded (its landblock was released, or it was placed where nothing is loaded): it is in no cell, casts no
    /// shadow and is not simulated, and comes back (placed again at its stored position, sliding) when the cell its position
    /// names is loaded again.</remarks>
    public int LostObjectCount => _lostObjectCount;

    /// <summary>True when <paramref name="obj"/> waits in a lost cell.</summary>
    internal bool IsInLostCell(PhysicsObj obj)
    {
        if (!_lostCells.TryGetValue(obj.Position.ObjCellId, out LostCell cell))
        {
            return false;
        }

        for (PhysicsObj? o = cell.First; o is not null; o = o.LostNext)
        {
            if (o == obj)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Adds an object without a parent to the lost cell of <paramref name="cellId"/> (its position's cell).</summary>
    // retail: CObjectMaint::GotoLostCell (acclient.c:309732), with CObjectMaint::GetLostCell (acclient.c:309690)
    internal void GotoLostCell(PhysicsObj obj, uint cellId)
    {
        if (obj.Parent is not null)
        {
            return;
        }

        obj.LostNext = null;
        if (_lostCells.TryGetValue(cellId, out LostCell cell))
        {
            cell.Last!.LostNext = obj;
            _lostCells[cellId] = new LostCell(cell.First, obj);
        }
        else
        {
            _lostCells.Add(cellId, new LostCell(obj, obj));
        }

        _lostObjectCount++;
    }

    /// <summary>Takes an object in no cell and without a parent out of the lost cell its position names.</summary>
    // retail: CObjectMaint::RemoveFromLostCell (acclient.c:309545)
    internal void RemoveFromLostCell(PhysicsObj obj)
    {
        if (obj.CellId != 0 || obj.Parent is not null || _lostObjectCount == 0)
        {
            return;
        }

        uint cellId = obj.Position.ObjCellId;
        if (!_lostCells.TryGetValue(cellId, out LostCell cell))
        {
            return;
        }

        PhysicsObj? prev = null;
        for (PhysicsObj? o = cell.First; o is not null; prev = o, o = o.LostNext)
        {
            if (o != obj)
            {
                continue;
            }

            PhysicsObj? next = o.LostNext;
            o.LostNext = null;
            _lostObjectCount--;
            if (prev is null && next is null)
            {
                _lostCells.Remove(cellId);
            }
            else
            {
                if (prev is not null)
                {
                    prev.LostNext = next;
                }

                _lostCells[cellId] = new LostCell(prev is null ? next! : cell.First, next is null ? prev! : cell.Last);
            }

            return;
        }
    }

    /// <summary>Cell <paramref name="cellId"/> was loaded: its lost cell is taken out of the table and each of its objects
    /// re-enters visibility (placed again at its stored position), in the order they were lost.</summary>
    // retail: CObjectMaint::InitObjCell (acclient.c:309758)
    internal void InitObjCell(uint cellId)
    {
        if (_lostObjectCount == 0 || !_lostCells.Remove(cellId, out LostCell cell))
        {
            return;
        }

        PhysicsObj? o = cell.First;
        while (o is not null)
        {
            PhysicsObj? next = o.LostNext;
            o.LostNext = null;
            _lostObjectCount--;
            if (o.InWorld && o.CellId == 0)
            {
                o.ReenterVisibility();
            }

            o = next;
        }
    }

    /// <summary>Cell <paramref name="cell"/> is released: its moving objects (not static, no parent), gathered first in the
    /// cell's list order, each leave visibility for the lost cell of their position's cell.</summary>
    // retail: CObjectMaint::ReleaseObjCell (acclient.c:309288)
    internal void ReleaseObjCell(ObjCell cell)
    {
        ReadOnlySpan<PhysicsObj> list = cell.ObjectList;
        List<PhysicsObj> gathered = _releaseScratch;
        gathered.Clear();
        for (int i = 0; i < list.Length; i++)
        {
            PhysicsObj o = list[i];
            if ((o.State & PhysicsState.Static) == 0 && o.Parent is null)
            {
                gathered.Add(o);
            }
        }

        foreach (PhysicsObj o in gathered)
        {
            o.LeaveVisibility();
        }

        gathered.Clear();
    }

    /// <summary>Each moving object of <paramref name="cell"/> not shadowed in every cell it reaches is shadowed again (the
    /// second half of <c>CObjCell::init_objects</c>).</summary>
    // retail: CObjCell::init_objects (acclient.c:346914) -> CPhysicsObj::recalc_cross_cells (acclient.c:322917)
    internal void RecalcCrossCellsOfIncomplete(ObjCell cell)
    {
        if (_sweep is not RetailSweep sweep)
        {
            return;
        }

        ReadOnlySpan<PhysicsObj> list = cell.ObjectList;
        for (int i = 0; i < list.Length; i++)
        {
            PhysicsObj o = list[i];
            if ((o.State & PhysicsState.Static) == 0 && !o.IsCompletelyVisible)
            {
                o.RehomeShadows(sweep);
            }
        }
    }

    // Retail's static DArray of ReleaseObjCell, kept by the world.
    private readonly List<PhysicsObj> _releaseScratch = new();

    /// <summary>Every outdoor cell of <paramref name="block"/> was loaded: each cell's objects are initialised (the objects
    /// lost in it come back, the incomplete ones are shadowed again), in retail's order (x, then y).</summary>
    // retail: CLandBlock::init_dyn_objs (acclient.c:351558) -> CObjCell::init_objects (acclient.c:346914) per land cell
    internal void InitLandBlockObjCells(LandBlock block)
    {
        for (int x = 0; x < LandDefs.BlockSide; x++)
        {
            for (int y = 0; y < LandDefs.BlockSide; y++)
            {
                block.GetCell(x, y).InitObjects(this);
            }
        }
    }

    private readonly record struct LostCell(PhysicsObj First, PhysicsObj Last);
}
