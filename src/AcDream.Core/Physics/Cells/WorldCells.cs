using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Math;
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
    /// <exception cref="ArgumentNullException"><paramref name="cell"/> is null.</exception>
    public void AddEnvCell(EnvCell cell)
    {
        ArgumentNullException.ThrowIfNull(cell);
        _envCells[cell.CellId] = cell;
    }

    /// <summary>Removes an indoor cell; false when it was not loaded.</summary>
    public bool RemoveEnvCell(uint cellId) => _envCells.Remove(cellId);

    /// <summary>The loaded indoor cell <paramref name="cellId"/>, or null.</summary>
    // retail: CEnvCell::GetVisible (acclient.c:349673)
    public EnvCell? GetEnvCell(uint cellId) => _envCells.TryGetValue(cellId, out EnvCell? c) ? c : null;

    /// <inheritdoc />
    // retail: CObjCell::GetVisible (acclient.c:346416): indoor ids -> CEnvCell::GetVisible, outdoor -> CLandCell::Get
    public ObjCell? GetVisible(uint cellId) =>
        LandDefs.IsEnvCell(cellId) ? GetEnvCell(cellId) : Terrain.GetLandCell(cellId);
}
