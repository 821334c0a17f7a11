using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// One 24 m outdoor cell: its two terrain triangles and its water. Ported from retail's <c>CLandCell</c>
/// (acclient.h:31886, PORTAL/ccell/CLandCell.c) with the <c>CObjCell</c> members terrain needs (water type, position,
/// landblock).
/// </summary>
/// <remarks>All points given to a land cell are local to its landblock (metres, 0..192 in x and y). Valid domain of the
/// queries: any point or position (a point outside the cell or non-finite gives a miss or false, never an exception); they
/// never change the cell.</remarks>
public sealed partial class LandCell
{
    private readonly Polygon _polygon0;
    private readonly Polygon _polygon1;

    internal LandCell(LandBlock landBlock, int cellX, int cellY, uint id, Polygon polygon0, Polygon polygon1, Vector3 origin)
    {
        LandBlock = landBlock;
        CellX = cellX;
        CellY = cellY;
        Id = id;
        _polygon0 = polygon0;
        _polygon1 = polygon1;
        Origin = origin;
    }

    /// <summary>The cell id, <c>0xXXYY00CC</c> with CC = x * 8 + y + 1. Retail: <c>m_DID.id</c>.</summary>
    public override uint Id { get; }

    /// <summary>The landblock that owns the cell. Retail: <c>myLandBlock_</c>.</summary>
    public LandBlock LandBlock { get; }

    /// <summary>The cell's column in its landblock, 0..7 west→east.</summary>
    public int CellX { get; }

    /// <summary>The cell's row in its landblock, 0..7 south→north.</summary>
    public int CellY { get; }

    /// <summary>The cell's position origin: its centre, <c>((2x + 1) * 12, (2y + 1) * 12, 0)</c>, landblock-local.
    /// Retail: <c>pos.frame.m_fOrigin</c>.</summary>
    public Vector3 Origin { get; }

    /// <summary>The cell's water: none, some corners, or all four corners water. Retail: <c>CObjCell::water_type</c>.</summary>
    public WaterType WaterType { get; internal set; }

    /// <summary>The owning landblock's water type. Retail: <c>CObjCell::get_block_water_type</c> (acclient.c:346438).</summary>
    public WaterType BlockWaterType => LandBlock.WaterType;

    /// <summary>The first triangle (retail <c>polygons[0]</c>); it wins on the shared diagonal.</summary>
    public Polygon Polygon0 => _polygon0;

    /// <summary>The second triangle (retail <c>polygons[1]</c>).</summary>
    public Polygon Polygon1 => _polygon1;

    /// <summary>
    /// The triangle under <paramref name="origin"/> (landblock-local; x and y only): the first of the two whose outline
    /// contains the point, edges included. Returns false, with a null polygon, when the point lies outside the cell.
    /// </summary>
    // retail: CLandCell::find_terrain_poly (acclient.c:354858)
    public bool FindTerrainPoly(Vector3 origin, [NotNullWhen(true)] out Polygon? walkable)
    {
        if (_polygon0.PointInPoly2D(origin, Sidedness.Positive))
        {
            walkable = _polygon0;
            return true;
        }

        if (_polygon1.PointInPoly2D(origin, Sidedness.Positive))
        {
            walkable = _polygon1;
            return true;
        }

        walkable = null;
        return false;
    }

    /// <summary>True when <paramref name="point"/> (landblock-local) lies over this cell.</summary>
    // retail: CLandCell::point_in_cell (acclient.c:354880)
    public override bool PointInCell(Vector3 point) => FindTerrainPoly(point, out _);

    /// <summary>
    /// The terrain height, in metres, under <paramref name="point"/> (landblock-local): the z where a vertical line
    /// through it meets the cell's triangle. Returns false when the point lies outside the cell.
    /// </summary>
    /// <remarks>Retail's way: <c>find_terrain_poly</c> then <c>Plane::set_height</c> (as in
    /// <c>CLandBlock::adjust_scene_obj_height</c>, acclient.c:352193).</remarks>
    public bool TryGetHeight(Vector3 point, out float z)
    {
        if (FindTerrainPoly(point, out Polygon? poly) && poly.Plane.SetHeight(ref point))
        {
            z = point.Z;
            return true;
        }

        z = 0f;
        return false;
    }

    /// <summary>
    /// The depth of water, in metres, that an object standing at <paramref name="point"/> (landblock-local) sinks into:
    /// 0 in a dry cell, 0.9 in a cell entirely water, and in a partly-water cell 0.45 or 0.1 by the nearest corner
    /// (<see cref="LandBlock.CalcWaterDepth"/>).
    /// </summary>
    // retail: CObjCell::get_water_depth (acclient.c:347232)
    public float GetWaterDepth(Vector3 point) => WaterType switch
    {
        WaterType.NotWater => 0f,
        WaterType.EntirelyWater => EntirelyWaterDepth,
        _ => LandBlock.CalcWaterDepth(Id, point),
    };

    /// <summary>Water depth, in metres, in a cell entirely water. Retail: 0.89999998 (0.9f).</summary>
    public const float EntirelyWaterDepth = 0.9f;

    /// <summary>
    /// The surface character (solid or water) of the terrain under <paramref name="pos"/>: the type of the cell corner
    /// nearest to it. <paramref name="pos"/> may be in any landblock; it is moved into this cell's landblock first.
    /// </summary>
    // retail: CLandCell::find_terrain (acclient.c:354950)
    public SurfChar FindTerrain(in Position pos)
    {
        Vector3 vc = new Position(Id, Vector3.Zero).GetOffset(pos);
        return TerrainTypes.SurfCharOf(LandBlock.GetTerrain(Id, vc));
    }

    /// <summary>
    /// The surface character under <paramref name="pos"/> when <paramref name="walkable"/> is one of this cell's
    /// triangles; <see cref="SurfChar.Solid"/> otherwise.
    /// </summary>
    // retail: CLandCell::walkable_surface_type (acclient.c:355121)
    internal SurfChar WalkableSurfaceType(Polygon walkable, in Position pos)
    {
        if (!ReferenceEquals(walkable, _polygon0) && !ReferenceEquals(walkable, _polygon1))
        {
            return SurfChar.Solid;
        }

        return FindTerrain(pos);
    }

    /// <inheritdoc />
    public override string ToString() =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture, $"LandCell 0x{Id:X8} ({WaterType})");

    /// <summary>The building on this cell, or null. Retail: <c>CSortCell::building</c>.</summary>
    public BuildingObj? Building { get; set; }

    /// <summary>Keeps <paramref name="building"/> unless the cell already holds one: the first building wins.</summary>
    // retail: CSortCell::add_building (acclient.c:356073)
    internal void AddBuilding(BuildingObj building)
    {
        Building ??= building;
    }

    /// <summary>The cell's restriction object (an object id; 0 for none), set from the landblock info's restriction table when
    /// the block's static objects are made. Retail: <c>CLandCell</c> +216, written at acclient.c:352869–352884.</summary>
    public uint RestrictionObj { get; internal set; }

    /// <summary>The building's shell against the check spheres; OK without a building.</summary>
    // retail: CSortCell::find_collisions (acclient.c:356106)
    internal TransitionState FindBuildingCollisions(Transition transition) =>
        Building is null ? TransitionState.Ok : Building.FindBuildingCollisions(transition);
}
