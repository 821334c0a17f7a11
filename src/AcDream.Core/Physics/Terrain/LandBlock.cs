using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Terrain;

/// <summary>
/// The terrain of one landblock: 9 × 9 height and terrain vertices built into 8 × 8 land cells of two triangles each.
/// Ported from retail's <c>CLandBlockStruct</c> (acclient.h:31310, PORTAL/ccell/CLandBlockStruct.c) and the terrain
/// parts of <c>CLandBlock</c> (acclient.h:31337, PORTAL/ccell/CLandBlock.c), at full detail (retail
/// <c>generate(block_id, 1, dir)</c>: side_cell_count 8, side_vertex_count 9).
/// </summary>
/// <remarks>
/// <para><b>Layout.</b> Vertex (vx, vy) — vx west→east, vy south→north, 0..8 — has index <c>vx * 9 + vy</c> in
/// <see cref="Height"/>, <see cref="Terrain"/> and <see cref="Vertices"/>, and sits at <c>(vx * 24, vy * 24,
/// table[height])</c> in landblock-local metres. Cell (x, y), 0..7, has index <c>x * 8 + y</c> and cell id low word
/// <c>x * 8 + y + 1</c>; its polygons are <c>2 * (x * 8 + y)</c> and the next one.</para>
/// <para><b>Split.</b> Each cell is cut along one diagonal chosen by retail's pseudo-random rule on the global cell
/// coordinate (<see cref="IsSWtoNECut(int, int)"/>). Every triangle is counter-clockwise seen from above, so every
/// normal points up.</para>
/// <para>Immutable after construction; queries allocate nothing.</para>
/// </remarks>
public sealed partial class LandBlock
{
    /// <summary>Cells along one side (8). Retail: <c>side_cell_count</c> at full detail.</summary>
    public const int SideCellCount = LandDefs.BlockSide;

    /// <summary>Polygon rows along one side (8). Retail: <c>side_polygon_count</c>.</summary>
    public const int SidePolygonCount = LandDefs.BlockSide;

    /// <summary>Vertices along one side (9). Retail: <c>side_vertex_count</c>.</summary>
    public const int SideVertexCount = LandDefs.VertexSide;

    /// <summary>Vertices in a landblock (81).</summary>
    public const int VertexCount = SideVertexCount * SideVertexCount;

    /// <summary>Land cells in a landblock (64).</summary>
    public const int CellCount = SideCellCount * SideCellCount;

    /// <summary>Terrain triangles in a landblock (128).</summary>
    public const int PolygonCount = 2 * SidePolygonCount * SidePolygonCount;

    private readonly byte[] _height;
    private readonly ushort[] _terrain;
    private readonly Vector3[] _vertices = new Vector3[VertexCount];
    private readonly Polygon[] _polygons = new Polygon[PolygonCount];
    private readonly LandCell[] _cells = new LandCell[CellCount];
    private readonly bool[] _swToNeCut = new bool[CellCount];

    /// <summary>
    /// Builds a landblock's terrain from its retail data: vertices, split triangles and their planes, cells, water.
    /// </summary>
    /// <param name="blockId">The landblock id, <c>0xXXYYFFFF</c> (XX column west→east, YY row south→north, both below 0xFF).</param>
    /// <param name="height">81 height indices, index <c>vx * 9 + vy</c> (the dat's <c>Height</c> array).</param>
    /// <param name="terrain">81 terrain words, same indexing (road bits 0-1, type bits 2-6, scene bits 11-15).</param>
    /// <param name="heightTable">The land height table that maps height indices to metres.</param>
    /// <exception cref="ArgumentException">The id is not a landblock id inside the world, or an array is not 81 long.</exception>
    /// <exception cref="ArgumentNullException"><paramref name="heightTable"/> is null.</exception>
    // retail: CLandBlockStruct::generate (acclient.c:354761)
    public LandBlock(uint blockId, ReadOnlySpan<byte> height, ReadOnlySpan<ushort> terrain, LandHeightTable heightTable)
    {
        ArgumentNullException.ThrowIfNull(heightTable);
        if ((blockId & 0xFFFF) != 0xFFFF)
        {
            throw new ArgumentException($"A landblock id has the form 0xXXYYFFFF; got 0x{blockId:X8}.", nameof(blockId));
        }

        if (!LandDefs.BlockIdToLCoord(blockId, out int bx, out int by))
        {
            throw new ArgumentException($"Landblock 0x{blockId:X8} lies outside the world.", nameof(blockId));
        }

        if (height.Length != VertexCount)
        {
            throw new ArgumentException($"A landblock has {VertexCount} height indices; got {height.Length}.", nameof(height));
        }

        if (terrain.Length != VertexCount)
        {
            throw new ArgumentException($"A landblock has {VertexCount} terrain words; got {terrain.Length}.", nameof(terrain));
        }

        Id = blockId;
        BlockX = bx >> 3;
        BlockY = by >> 3;
        HeightTable = heightTable;
        _height = height.ToArray();
        _terrain = terrain.ToArray();
        ConstructVertices();
        ConstructPolygons();
        CalcWater();
        GetLandLimits();
    }

    /// <summary>The landblock id, <c>0xXXYYFFFF</c>.</summary>
    public uint Id { get; }

    /// <summary>The landblock column, 0..254 west→east (the id's high byte).</summary>
    public int BlockX { get; }

    /// <summary>The landblock row, 0..254 south→north.</summary>
    public int BlockY { get; }

    /// <summary>The height table the vertices were built with.</summary>
    public LandHeightTable HeightTable { get; }

    /// <summary>The landblock's water type: none, some cells, or every cell entirely water. Retail: <c>water_type</c>.</summary>
    public WaterType WaterType { get; private set; }

    /// <summary>Highest terrain height plus 200 m (retail <c>max_zval</c>, <c>get_land_limits</c>).</summary>
    public float MaxZval { get; private set; }

    /// <summary>Lowest terrain height minus 1 m (retail <c>min_zval</c>).</summary>
    public float MinZval { get; private set; }

    /// <summary>The 81 height indices, index <c>vx * 9 + vy</c>.</summary>
    public ReadOnlySpan<byte> Height => _height;

    /// <summary>The 81 terrain words, index <c>vx * 9 + vy</c>.</summary>
    public ReadOnlySpan<ushort> Terrain => _terrain;

    /// <summary>The 81 vertices in landblock-local metres, index <c>vx * 9 + vy</c>.</summary>
    public ReadOnlySpan<Vector3> Vertices => _vertices;

    /// <summary>The 128 terrain triangles; cell (x, y) owns <c>2 * (x * 8 + y)</c> and the next.</summary>
    public ReadOnlySpan<Polygon> Polygons => _polygons;

    /// <summary>The 64 land cells, index <c>x * 8 + y</c>.</summary>
    public ReadOnlySpan<LandCell> Cells => _cells;

    /// <summary>The land cell at column <paramref name="cellX"/>, row <paramref name="cellY"/> (0..7).</summary>
    /// <exception cref="ArgumentOutOfRangeException">A coordinate is outside 0..7.</exception>
    public LandCell GetCell(int cellX, int cellY)
    {
        if ((uint)cellX >= SideCellCount || (uint)cellY >= SideCellCount)
        {
            throw new ArgumentOutOfRangeException(nameof(cellX), "Cell coordinates are 0..7.");
        }

        return _cells[cellX * SideCellCount + cellY];
    }

    /// <summary>
    /// The land cell with id <paramref name="cellId"/>, or null when the id is not an outdoor cell of this landblock.
    /// </summary>
    // retail: CLandBlock::get_landcell (acclient.c:352097)
    public LandCell? GetLandCell(uint cellId)
    {
        if ((cellId | 0xFFFF) != Id || !LandDefs.IsOutdoorCell(cellId))
        {
            return null;
        }

        LandCell c = _cells[(int)(cellId & 0xFFFF) - 1];
        return c.Id == cellId ? c : null;
    }

    /// <summary>True when cell (x, y) of this landblock is cut from its south-west to its north-east corner.</summary>
    /// <exception cref="ArgumentOutOfRangeException">A coordinate is outside 0..7.</exception>
    public bool IsCellSWtoNECut(int cellX, int cellY)
    {
        if ((uint)cellX >= SideCellCount || (uint)cellY >= SideCellCount)
        {
            throw new ArgumentOutOfRangeException(nameof(cellX), "Cell coordinates are 0..7.");
        }

        return _swToNeCut[cellX * SideCellCount + cellY];
    }

    /// <summary>The landblock id <c>0xXXYYFFFF</c> of column <paramref name="blockX"/>, row <paramref name="blockY"/>.</summary>
    /// <exception cref="ArgumentOutOfRangeException">A coordinate is outside 0..254.</exception>
    public static uint MakeId(int blockX, int blockY)
    {
        if ((uint)blockX >= LandDefs.LandblocksPerSide || (uint)blockY >= LandDefs.LandblocksPerSide)
        {
            throw new ArgumentOutOfRangeException(nameof(blockX), "Landblock coordinates are 0..254.");
        }

        return ((uint)blockX << 24) | ((uint)blockY << 16) | 0xFFFFu;
    }
}
