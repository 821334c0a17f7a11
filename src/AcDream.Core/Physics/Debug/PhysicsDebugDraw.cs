using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Debug;

/// <summary>
/// A view of what collides (library addition; retail had no such view): every collision shape of a world — objects' spheres,
/// cylinder spheres and physics-BSP polygons, buildings' shells, indoor cells' walls and portals, terrain triangles, land-cell
/// sides, contact planes and each object's last motion — handed to a client's <see cref="IDebugDrawSink"/> in one frame
/// (<see cref="DebugDrawRegion"/>), the way Box2D's debug draw and Jolt's debug renderer let a game draw the physics in its own
/// renderer. Call it per frame, between ticks: it reads the world and changes nothing, and with a struct sink it allocates
/// nothing (one scratch buffer, grown to the largest polygon, is kept by the instance).
/// </summary>
/// <remarks>The shapes are what the sweep tests (<c>CPhysicsObj::FindObjCollisions</c>, acclient.c:316158: an object with a
/// physics BSP collides through its parts' polygons, else through its cylinder spheres, else through its spheres), placed as
/// the sweep places them (scaled by the object's scale, the BSP parts by their scale's z). Not thread-safe: one instance draws
/// on one thread.</remarks>
public sealed partial class PhysicsDebugDraw
{
    private Vector3[] _scratch = new Vector3[16];

    /// <summary>Creates the view of <paramref name="world"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="world"/> is null.</exception>
    public PhysicsDebugDraw(PhysicsWorld world)
    {
        ArgumentNullException.ThrowIfNull(world);
        World = world;
    }

    /// <summary>The world drawn.</summary>
    public PhysicsWorld World { get; }

    /// <summary>Hands every loaded shape that <paramref name="flags"/> selects to <paramref name="sink"/>, in the global frame
    /// (<see cref="DebugDrawRegion.Everything"/> with frame cell 0).</summary>
    /// <param name="sink">The client's sink.</param>
    /// <param name="flags">The shapes to draw.</param>
    /// <typeparam name="TSink">The sink, a struct (so that the calls are direct and nothing is boxed).</typeparam>
    public void Draw<TSink>(ref TSink sink, DebugDrawFlags flags)
        where TSink : struct, IDebugDrawSink =>
        Draw(ref sink, flags, DebugDrawRegion.Everything());

    /// <summary>Hands the shapes of <paramref name="region"/> that <paramref name="flags"/> selects to <paramref name="sink"/>,
    /// in the region's frame: the land cells (terrain triangles, sides, buildings), then the indoor cells (walls, portals), then
    /// the objects in the world's order (shapes, contact plane, last motion). A world without cells (the free-space sweep) has
    /// objects only.</summary>
    /// <param name="sink">The client's sink.</param>
    /// <param name="flags">The shapes to draw.</param>
    /// <param name="region">Where to look and the frame to answer in.</param>
    /// <typeparam name="TSink">The sink, a struct.</typeparam>
    public void Draw<TSink>(ref TSink sink, DebugDrawFlags flags, in DebugDrawRegion region)
        where TSink : struct, IDebugDrawSink
    {
        (TerrainWorld? terrain, WorldCells? cells) = World.Sweep is RetailSweep sweep
            ? sweep.Cells switch
            {
                WorldCells c => (c.Terrain, c),
                TerrainWorld t => (t, (WorldCells?)null),
                _ => ((TerrainWorld?)null, (WorldCells?)null),
            }
            : ((TerrainWorld?)null, (WorldCells?)null);

        if (terrain is not null && (flags & (DebugDrawFlags.TerrainTriangles | DebugDrawFlags.LandCellBoundaries
                                             | DebugDrawFlags.BuildingPolygons)) != 0)
        {
            DrawLand(ref sink, flags, region, terrain);
        }

        if (cells is not null && (flags & (DebugDrawFlags.EnvCellPolygons | DebugDrawFlags.EnvCellPortals)) != 0)
        {
            foreach (EnvCell cell in cells.EnvCells)
            {
                DrawEnvCell(ref sink, flags, region, cell);
            }
        }

        if ((flags & (DebugDrawFlags.Objects | DebugDrawFlags.ContactPlanes | DebugDrawFlags.LastSweeps)) != 0)
        {
            int n = World.ObjectCount;
            for (int i = 0; i < n; i++)
            {
                Objects.PhysicsObj o = World.GetObject(i);
                if (o.CellId != 0 && region.Contains(Offset(region, o.CellId) + o.Position.Frame.Origin))
                {
                    DrawObject(ref sink, o, flags, region.FrameCellId);
                }
            }
        }
    }

    // The loaded land cells of the region: their triangles and sides, and the buildings hung on them.
    private void DrawLand<TSink>(ref TSink sink, DebugDrawFlags flags, in DebugDrawRegion region, TerrainWorld terrain)
        where TSink : struct, IDebugDrawSink
    {
        int fx = (int)(region.FrameCellId >> 24), fy = (int)((region.FrameCellId >> 16) & 0xFF);
        int x0 = 0, x1 = LandDefs.LandblocksPerSide - 1, y0 = 0, y1 = LandDefs.LandblocksPerSide - 1;
        if (region.HasBox)
        {
            const float Side = LandDefs.BlockLength;
            x0 = Math.Max(x0, fx + (int)Math.Floor(region.Min.X / Side));
            x1 = Math.Min(x1, fx + (int)Math.Floor(region.Max.X / Side));
            y0 = Math.Max(y0, fy + (int)Math.Floor(region.Min.Y / Side));
            y1 = Math.Min(y1, fy + (int)Math.Floor(region.Max.Y / Side));
        }

        for (int bx = x0; bx <= x1; bx++)
        {
            for (int by = y0; by <= y1; by++)
            {
                LandBlock? block = terrain.GetLandBlock(bx, by);
                if (block is not null)
                {
                    DrawLandBlock(ref sink, flags, region, block);
                }
            }
        }
    }

    private void DrawLandBlock<TSink>(ref TSink sink, DebugDrawFlags flags, in DebugDrawRegion region, LandBlock block)
        where TSink : struct, IDebugDrawSink
    {
        Vector3 off = Offset(region, block.Id);
        ReadOnlySpan<Vector3> v = block.Vertices;
        ReadOnlySpan<LandCell> landCells = block.Cells;
        for (int i = 0; i < landCells.Length; i++)
        {
            LandCell cell = landCells[i];
            float minX = off.X + cell.CellX * LandDefs.CellLength, minY = off.Y + cell.CellY * LandDefs.CellLength;
            if (!region.Overlaps(minX, minY, minX + LandDefs.CellLength, minY + LandDefs.CellLength))
            {
                continue;
            }

            if ((flags & DebugDrawFlags.TerrainTriangles) != 0)
            {
                Triangle(ref sink, cell.Polygon0, off, cell.Id);
                Triangle(ref sink, cell.Polygon1, off, cell.Id);
            }

            if ((flags & DebugDrawFlags.LandCellBoundaries) != 0)
            {
                int sw = cell.CellX * LandBlock.SideVertexCount + cell.CellY;
                Vector3 a = off + v[sw], b = off + v[sw + LandBlock.SideVertexCount];
                Vector3 c = off + v[sw + LandBlock.SideVertexCount + 1], d = off + v[sw + 1];
                sink.Segment(a, b, ShapeKind.LandCellBoundary, cell.Id);
                sink.Segment(b, c, ShapeKind.LandCellBoundary, cell.Id);
                sink.Segment(c, d, ShapeKind.LandCellBoundary, cell.Id);
                sink.Segment(d, a, ShapeKind.LandCellBoundary, cell.Id);
            }

            // A building is drawn once, with the cell it hangs on (CBuildingObj::add_to_cell); one a client hung on its cells by
            // hand (cell id 0) with the cell of its shell's position.
            if ((flags & DebugDrawFlags.BuildingPolygons) != 0 && cell.Building is { } building
                && BuildingCellId(building) == cell.Id)
            {
                DrawBuilding(ref sink, building, region.FrameCellId);
            }
        }
    }

    private static void Triangle<TSink>(ref TSink sink, Polygon poly, Vector3 off, uint cellId)
        where TSink : struct, IDebugDrawSink
    {
        ReadOnlySpan<Vector3> p = poly.Vertices;
        sink.Triangle(off + p[0], off + p[1], off + p[2], ShapeKind.TerrainTriangle, cellId);
    }

    // An indoor cell whose walls' and portals' bounds overlap the box: its physics BSP's polygons and its portals.
    private void DrawEnvCell<TSink>(ref TSink sink, DebugDrawFlags flags, in DebugDrawRegion region, EnvCell cell)
        where TSink : struct, IDebugDrawSink
    {
        Vector3 off = Offset(region, cell.CellId);
        ref readonly Frame frame = ref cell.Pos.Frame;
        if (region.HasBox)
        {
            // The x-y bounds of the cell's walls and portals, placed (a cell BSP's spheres are not always filled in).
            Vector2 min = new(float.MaxValue), max = new(float.MinValue);
            if (cell.Structure.PhysicsBsp is { } walls)
            {
                ReadOnlySpan<Polygon> polys = walls.Polygons;
                for (int i = 0; i < polys.Length; i++)
                {
                    Bounds(polys[i], frame, off, ref min, ref max);
                }
            }

            ReadOnlySpan<CellPortal> openings = cell.Portals;
            for (int i = 0; i < openings.Length; i++)
            {
                Bounds(openings[i].Portal, frame, off, ref min, ref max);
            }

            if (!region.Overlaps(min.X, min.Y, max.X, max.Y))
            {
                return;
            }
        }

        if ((flags & DebugDrawFlags.EnvCellPolygons) != 0 && cell.Structure.PhysicsBsp is { } bsp)
        {
            Polygons(ref sink, bsp, frame, 1f, off, ShapeKind.EnvCellPolygon, cell.CellId);
        }

        if ((flags & DebugDrawFlags.EnvCellPortals) != 0)
        {
            ReadOnlySpan<CellPortal> portals = cell.Portals;
            for (int i = 0; i < portals.Length; i++)
            {
                Polygon(ref sink, portals[i].Portal, frame, 1f, off, ShapeKind.EnvCellPortal, cell.CellId);
            }
        }
    }

    private static void Bounds(Polygon poly, in Frame frame, Vector3 off, ref Vector2 min, ref Vector2 max)
    {
        ReadOnlySpan<Vector3> v = poly.Vertices;
        for (int k = 0; k < v.Length; k++)
        {
            Vector3 p = off + frame.LocalToGlobal(v[k]);
            min = Vector2.Min(min, new Vector2(p.X, p.Y));
            max = Vector2.Max(max, new Vector2(p.X, p.Y));
        }
    }

    // Every polygon of a BSP, its vertices scaled by scale and placed by frame, then moved by off.
    private void Polygons<TSink>(ref TSink sink, BspTree bsp, in Frame frame, float scale, Vector3 off, ShapeKind kind, uint id)
        where TSink : struct, IDebugDrawSink
    {
        ReadOnlySpan<Polygon> polys = bsp.Polygons;
        for (int i = 0; i < polys.Length; i++)
        {
            Polygon(ref sink, polys[i], frame, scale, off, kind, id);
        }
    }

    private void Polygon<TSink>(ref TSink sink, Polygon poly, in Frame frame, float scale, Vector3 off, ShapeKind kind, uint id)
        where TSink : struct, IDebugDrawSink
    {
        ReadOnlySpan<Vector3> local = poly.Vertices;
        if (_scratch.Length < local.Length)
        {
            // Grown once to the largest polygon met; steady-state calls allocate nothing.
            _scratch = new Vector3[Math.Max(local.Length, 2 * _scratch.Length)];
        }

        for (int k = 0; k < local.Length; k++)
        {
            Vector3 p = local[k];
            _scratch[k] = off + frame.LocalToGlobal(new Vector3(p.X * scale, p.Y * scale, p.Z * scale));
        }

        Vector3 n = frame.LocalToGlobalVec(poly.Plane.N);
        sink.Polygon(_scratch.AsSpan(0, local.Length), n, kind, id);
    }

    // The offset of cellId's landblock in the region's frame (LandDefs::get_block_offset, acclient.c:123109).
    private static Vector3 Offset(in DebugDrawRegion region, uint cellId) => LandDefs.GetBlockOffset(region.FrameCellId, cellId);
}
