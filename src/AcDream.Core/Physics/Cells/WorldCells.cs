using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// The cells the sweep can reach: the outdoor terrain of a <see cref="TerrainWorld"/> and the loaded indoor cells
/// (buildings' interiors and dungeons). Retail found indoor cells through the global <c>CEnvCell::GetVisible</c>
/// table; here the table is explicit world state.
/// </summary>
/// <remarks>Lookups allocate nothing. Cells are added and removed between ticks; not thread-safe for writes.</remarks>
public sealed class WorldCells : ICellSource
{
    /// <summary>The world whose objects' shadows these cells hold (set when a world takes a sweep over them).</summary>
    internal PhysicsWorld? OwnerWorld { get; set; }

    private readonly Dictionary<uint, EnvCell> _envCells = new();

    /// <summary>Creates the cell set over <paramref name="terrain"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="terrain"/> is null.</exception>
    public WorldCells(TerrainWorld terrain)
    {
        ArgumentNullException.ThrowIfNull(terrain);
        Terrain = terrain;
    }

    /// <summary>The outdoor world.</summary>
    public TerrainWorld Terrain { get; }

    /// <summary>The number of loaded indoor cells.</summary>
    public int EnvCellCount => _envCells.Count;

    /// <summary>Adds (or replaces) an indoor cell.</summary>
    /// <remarks>Objects of the world these cells serve that stand in the cell, or whose shadows reach into it, are listed in the
    /// new cell (their shadows leave a replaced cell); positions and cells are kept. Objects lost in the cell come back, placed
    /// again where they were (retail <c>CObjectMaint::InitObjCell</c>). Call between ticks (docs/stability.md,
    /// "Landblocks changing under objects").</remarks>
    /// <exception cref="ArgumentNullException"><paramref name="cell"/> is null.</exception>
    /// <exception cref="InvalidOperationException">Called from a callback inside the tick of the world these cells serve;
    /// nothing changes.</exception>
    public void AddEnvCell(EnvCell cell) => AddEnvCell(cell, initObjects: true);

    /// <summary>Adds (or replaces) an indoor cell; with <paramref name="initObjects"/> the objects lost in it come back at
    /// once, else the caller brings them back later (<see cref="PhysicsWorld.InitObjCell"/>).</summary>
    internal void AddEnvCell(EnvCell cell, bool initObjects)
    {
        ArgumentNullException.ThrowIfNull(cell);
        ThrowIfOwnerTicking();
        _envCells[cell.CellId] = cell;
        // non-retail: objects re-homed into the new cell (retail never swaps a cell under an object)
        Owner?.RehomeObjectsIn(cell.CellId, 0xFFFFFFFFu);
        if (initObjects)
        {
            Owner?.InitObjCell(cell.CellId);
        }
    }

    /// <summary>Removes an indoor cell; false when it was not loaded.</summary>
    /// <param name="cellId">The indoor cell's id.</param>
    /// <param name="leftWorld">When given, receives every object that left the world because it stood in the cell.</param>
    /// <remarks>Objects standing in the cell leave the world as retail's lost cell (<see cref="Objects.PhysicsObj.CellId"/> 0,
    /// no shadows, last position kept, not simulated until placed again); objects elsewhere keep only their shadows in cells
    /// still loaded. Call between ticks.</remarks>
    /// <exception cref="InvalidOperationException">Called from a callback inside the tick of the world these cells serve;
    /// nothing changes.</exception>
    public bool RemoveEnvCell(uint cellId, ICollection<Objects.PhysicsObj>? leftWorld = null)
    {
        ThrowIfOwnerTicking();
        if (!_envCells.Remove(cellId))
        {
            return false;
        }

        // non-retail: objects in the cell leave the world (retail unloads cells only away from objects it simulates)
        Owner?.SendObjectsOutOfWorld(cellId, 0xFFFFFFFFu, leftWorld);
        return true;
    }

    // The world whose objects stand in these cells: this set's owner, else its terrain's.
    private PhysicsWorld? Owner => OwnerWorld ?? Terrain.OwnerWorld;

    private void ThrowIfOwnerTicking()
    {
        if (Owner is { IsTicking: true })
        {
            throw new InvalidOperationException("Cells cannot change inside a tick of the world whose objects stand in them.");
        }
    }

    /// <summary>The loaded indoor cells (their enumerator allocates nothing), for the debug view.</summary>
    internal Dictionary<uint, EnvCell>.ValueCollection EnvCells => _envCells.Values;

    /// <summary>The loaded indoor cell <paramref name="cellId"/>, or null.</summary>
    // retail: CEnvCell::GetVisible (acclient.c:349673)
    public EnvCell? GetEnvCell(uint cellId) => _envCells.TryGetValue(cellId, out EnvCell? c) ? c : null;

    /// <inheritdoc />
    // retail: CObjCell::GetVisible (acclient.c:346416): indoor ids -> CEnvCell::GetVisible, outdoor -> CLandCell::Get
    public ObjCell? GetVisible(uint cellId) =>
        LandDefs.IsEnvCell(cellId) ? GetEnvCell(cellId) : Terrain.GetLandCell(cellId);
}
