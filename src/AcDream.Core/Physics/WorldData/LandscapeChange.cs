using System;
using System.Collections.Generic;

namespace AcDream.Core.Physics.WorldData;

/// <summary>What a <see cref="Landscape.ChangePosition"/> call did.</summary>
public enum LandscapeStatus
{
    /// <summary>The position is in the cell of the last call, which was found: nothing to do (retail does nothing either).</summary>
    SameCell,

    /// <summary>The landscape follows the new cell: blocks and objects may have been built and released (the change's lists
    /// say which).</summary>
    Updated,

    /// <summary>The position's cell id was 0: everything was released (retail <c>CellManager::Reset</c>).</summary>
    Released,

    /// <summary>The position's cell cannot be built from the data source (its landblock entry is missing, or the indoor cell
    /// is not one of its block's cells): nothing changed. A later call may succeed.</summary>
    NoCell,
}

/// <summary>
/// The outcome of one <see cref="Landscape.ChangePosition"/>: its status, the blocks that entered and left the grid, the
/// blocks built into the world (full detail reached) and released from it, for a renderer and for sound.
/// </summary>
public sealed class LandscapeChange
{
    private static readonly uint[] NoIds = Array.Empty<uint>();
    private static readonly WorldBlock[] NoBlocks = Array.Empty<WorldBlock>();

    internal static readonly LandscapeChange SameCell = new(LandscapeStatus.SameCell);
    internal static readonly LandscapeChange NoCell = new(LandscapeStatus.NoCell);
    internal static readonly LandscapeChange Moved = new(LandscapeStatus.Updated);
    internal static readonly LandscapeChange ReleasedAll = new(LandscapeStatus.Released);

    private LandscapeChange(LandscapeStatus status)
    {
        Status = status;
        Entered = NoIds;
        Left = NoIds;
        Built = NoBlocks;
        Released = NoIds;
        CellsEntered = NoIds;
        CellsReleased = NoIds;
    }

    internal LandscapeChange(LandscapeStatus status, uint[] entered, uint[] left, WorldBlock[] built, uint[] released,
        uint[] cellsEntered, uint[] cellsReleased)
    {
        Status = status;
        Entered = entered;
        Left = left;
        Built = built;
        Released = released;
        CellsEntered = cellsEntered;
        CellsReleased = cellsReleased;
    }

    /// <summary>What the call did.</summary>
    public LandscapeStatus Status { get; }

    /// <summary>Landblock ids that entered the grid (at any level of detail), in the order they were read.</summary>
    public IReadOnlyList<uint> Entered { get; }

    /// <summary>Landblock ids that left the grid, in the order they were released.</summary>
    public IReadOnlyList<uint> Left { get; }

    /// <summary>The blocks built into the world by this call (each reaching full detail), in the order they were built: each
    /// with the buildings, static objects and scenery made for it.</summary>
    public IReadOnlyList<WorldBlock> Built { get; }

    /// <summary>Landblock ids whose world part was released (the block left full detail or the grid): their objects were
    /// destroyed and the objects standing in them went to their lost cells.</summary>
    public IReadOnlyList<uint> Released { get; }

    /// <summary>Indoor cells that became visible (retail's visible-cell table), in the order they came; their static objects:
    /// <see cref="Landscape.GetCellObjects"/>.</summary>
    public IReadOnlyList<uint> CellsEntered { get; }

    /// <summary>Indoor cells no longer visible: their static objects destroyed, the objects in them sent to their lost cells.</summary>
    public IReadOnlyList<uint> CellsReleased { get; }
}
