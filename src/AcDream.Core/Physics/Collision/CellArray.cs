using System;
using AcDream.Core.Physics.Cells;

namespace AcDream.Core.Physics.Collision;

/// <summary>One entry of a <see cref="CellArray"/>: a cell id and the cell, which is null when it is not loaded. Retail: <c>CELLINFO</c> (acclient.h:31925).</summary>
internal struct CellInfo
{
    /// <summary>The cell id.</summary>
    public uint CellId;

    /// <summary>The cell, or null when the landblock holding it is not loaded.</summary>
    public ObjCell? Cell;
}

/// <summary>
/// The cells a sphere path overlaps, in the order they were found, without duplicates. Retail: <c>CELLARRAY</c>
/// (acclient.h:31574, PORTAL/cphysics/CCellArray.c). Owned by a pooled <see cref="Transition"/>; it grows only past its capacity.
/// </summary>
internal sealed class CellArray
{
    private CellInfo[] _cells = new CellInfo[InitialCapacity];

    /// <summary>Initial capacity. Retail: 8 (<c>CELLARRAY::CELLARRAY</c>, acclient.c:312113; grows by 8).</summary>
    public const int InitialCapacity = 8;

    /// <summary>The outdoor cells have been added for this search. Retail: <c>added_outside</c>.</summary>
    public bool AddedOutside;

    /// <summary>Restrict an interior search to cells already loaded. Retail: <c>do_not_load_cells</c>.</summary>
    public bool DoNotLoadCells;

    /// <summary>Build the list the plain retail way, without the port's shortcut for spheres inside one landblock's
    /// cells (<see cref="Cells.CellList.TryInteriorCells"/>); set with <see cref="Transition.ReferencePaths"/>.</summary>
    public bool ReferencePaths;

    /// <summary>Number of cells. Retail: <c>num_cells</c>.</summary>
    public int NumCells;

    /// <summary>The cells, <see cref="NumCells"/> long.</summary>
    public ReadOnlySpan<CellInfo> Cells => _cells.AsSpan(0, NumCells);

    /// <summary>The cell at <paramref name="index"/> (null when not loaded).</summary>
    public ObjCell? CellAt(int index) => _cells[index].Cell;

    /// <summary>Empties the array.</summary>
    public void Clear()
    {
        NumCells = 0;
        AddedOutside = false;
        DoNotLoadCells = false;
    }

    /// <summary>Appends a cell unless its id is already present.</summary>
    // retail: CELLARRAY::add_cell (acclient.c:718895)
    public void AddCell(uint cellId, ObjCell? cell)
    {
        for (int i = 0; i < NumCells; i++)
        {
            if (_cells[i].CellId == cellId)
            {
                return;
            }
        }

        if (NumCells >= _cells.Length)
        {
            Array.Resize(ref _cells, _cells.Length + InitialCapacity);
        }

        _cells[NumCells].CellId = cellId;
        _cells[NumCells].Cell = cell;
        NumCells++;
    }

    /// <summary>Removes the entry at <paramref name="index"/> by moving the last entry into its place.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="index"/> is not below <see cref="NumCells"/> (retail does
    /// not check; nothing is changed).</exception>
    // retail: CELLARRAY::remove_cell (acclient.c:718761)
    public void RemoveCell(int index)
    {
        if ((uint)index >= (uint)NumCells)
        {
            throw new ArgumentOutOfRangeException(nameof(index));
        }

        NumCells--;
        _cells[index] = _cells[NumCells];
    }
}
