using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Data;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Tests.Support.Geometry;

/// <summary>
/// The real Holtburg cellars of ../shared/data/geometry on the real terrain of 0xA9B4: every dumped EnvCell with a physics BSP
/// built from its physics polygons (BspBuilder) and a cell region built from the convex hull of its drawing polygons (the
/// dumps carry no BSP trees), and the building shell GfxObj 0x01000A2B placed with the first cellar's cell frame (its door
/// openings coincide with that cellar's outdoor portals: the wall x = -5.8 with the 0x0145 doorway y 5.4..7.3, z 0..2.5).
/// </summary>
internal sealed class CellarScene
{
    /// <summary>Landblock prefix of the cells.</summary>
    public const uint Block = 0xA9B40000;

    private CellarScene(WorldCells cells, Dictionary<uint, (EnvCell Cell, CellDump Dump)> env, List<(Vector3[] World, uint Cell)> walls)
    {
        Cells = cells;
        Env = env;
        WorldPolygons = walls;
    }

    /// <summary>The cell source (terrain of the Holtburg blocks, the env cells, the building on its land cell).</summary>
    public WorldCells Cells { get; }

    /// <summary>The env cells by full id, with their dumps.</summary>
    public Dictionary<uint, (EnvCell Cell, CellDump Dump)> Env { get; }

    /// <summary>Every physics polygon of the cells and the shell in landblock coordinates (0 = the shell).</summary>
    public List<(Vector3[] World, uint Cell)> WorldPolygons { get; }

    /// <summary>Builds the scene from the geometry folder and the terrain folder. With <paramref name="throughRetailBytes"/>,
    /// every cell, its environment and the shell GfxObj are first written in retail's byte layout (the BspBuilder trees
    /// written as retail nodes: <see cref="RetailEntries.Tree"/>) and the scene is built from what the library's unpackers
    /// read back.</summary>
    public static CellarScene Load(string geometryDir, string terrainDir, bool throughRetailBytes = false)
    {
        var dumps = new List<CellDump>();
        foreach (string sub in new[] { "cellar-ascent", "cellar-rooms", "cellar-lip", "flap-doorway" })
        {
            foreach (string f in Directory.GetFiles(Path.Combine(geometryDir, sub), "0x*.json"))
            {
                if (!f.EndsWith(".gfxobj.json", StringComparison.Ordinal))
                {
                    dumps.Add(CellDump.Read(f));
                }
            }
        }

        var ids = new HashSet<uint>();
        foreach (CellDump d in dumps)
        {
            ids.Add(d.CellId);
        }

        var cells = new WorldCells(Holtburg.World(Holtburg.Read(terrainDir)));
        var env = new Dictionary<uint, (EnvCell, CellDump)>();
        var polys = new List<(Vector3[], uint)>();
        foreach (CellDump d in dumps)
        {
            Frame frame = FrameOf(d.WorldTransform);
            Polygon[] physics = ToPolygons(d.PhysicsPolygons);
            var portalPolys = new Polygon[d.Portals.Length];
            var portals = new CellPortal[d.Portals.Length];
            for (int i = 0; i < d.Portals.Length; i++)
            {
                DumpPortal p = d.Portals[i];
                DumpPolygon pp = d.PortalPolygons[p.PolygonId];
                portalPolys[i] = ToPolygon(pp, (short)p.PolygonId);
                uint other = p.OtherCellId == 0xFFFF ? CellPortal.OutsideCellId : Block | p.OtherCellId;
                // Flags: bit 1 exact match, bit 2 portal side (set: the neighbour lies behind the portal's plane).
                portals[i] = new CellPortal(other, portalPolys[i], (p.Flags & 2) != 0 ? 0 : 1, BackPortal(dumps, other, d.CellId), (p.Flags & 1) != 0);
            }

            EnvCell cell;
            if (throughRetailBytes)
            {
                cell = ThroughRetailBytes(d, frame, BspBuilder.Build(physics), BspBuilder.BuildCell(HullPlanes(d)), dumps);
            }
            else
            {
                var structure = new CellStruct(BspBuilder.Build(physics), BspBuilder.BuildCell(HullPlanes(d)), portalPolys);
                cell = new EnvCell(d.CellId, frame, structure, portals);
            }

            cells.AddEnvCell(cell);
            env[d.CellId] = (cell, d);
            foreach (DumpPolygon p in d.PhysicsPolygons)
            {
                polys.Add((Array.ConvertAll(p.Vertices, v => frame.LocalToGlobal(v)), d.CellId));
            }
        }

        // The building shell, placed with the first cellar's frame; its doors are that cellar's outdoor portals.
        Frame bf = env[Block | 0x0145].Item1.Pos.Frame;
        DumpPolygon[] shell = CellDump.ReadGfxObjPolygons(Path.Combine(geometryDir, "cellar-ascent", "0x01000A2B.gfxobj.json"));
        var doors = new List<BldPortal>();
        foreach ((EnvCell c, CellDump d) in env.Values)
        {
            for (int i = 0; i < d.Portals.Length; i++)
            {
                if (d.Portals[i].OtherCellId == 0xFFFF && Vector3.Distance(c.Pos.Frame.Origin, bf.Origin) < 0.01f)
                {
                    doors.Add(new BldPortal(c.CellId, i));
                }
            }
        }

        uint landCell = Holtburg.CentreCell(bf.Origin.X, bf.Origin.Y);
        BspTree shellBsp = BspBuilder.Build(ToPolygons(shell));
        GfxObjPhysics shellPhysics = new(shellBsp);
        if (throughRetailBytes)
        {
            (List<Vector3> verts, PolyDef[] defs) = RetailEntries.Defs(shellBsp.Polygons.ToArray());
            shellPhysics = RetailGfxObj.Unpack(RetailEntries.GfxObj(0x01000A2B, verts, defs, shellBsp, Vector3.Zero)).Physics!;
        }

        var part = new PhysicsPart(shellPhysics, new Position(landCell, bf), Vector3.One);
        var building = new BuildingObj(part, doors.ToArray());
        foreach (DumpPolygon p in shell)
        {
            polys.Add((Array.ConvertAll(p.Vertices, v => bf.LocalToGlobal(v)), 0u));
        }

        // The shell spans x -12..8, y -8..8 about (130.5, 11.5): world x 122.5..142.5, y 3.5..19.5, one land cell column
        // (x / 24 = 5) and row (y / 24 = 0).
        cells.Terrain.GetLandCell(landCell)!.Building = building;
        return new CellarScene(cells, env, polys);
    }

    /// <summary>
    /// The cell written as retail entries and read back: an environment 0x0D00CCCC (CCCC the cell's low word) holding one
    /// structure — the vertex array of the drawing and physics polygons, the drawing polygons (ids = their dump index), the
    /// portal list, the cell tree and physics tree given — and the cell entry (frame, portals with the dump's flags, the back
    /// portal's index).
    /// </summary>
    public static EnvCell ThroughRetailBytes(CellDump d, in Frame frame, BspTree physicsBsp, BspTree cellBsp, List<CellDump> dumps) =>
        Unpacked(d, frame, physicsBsp, cellBsp, dumps).Cell;

    /// <summary>As <see cref="ThroughRetailBytes"/>, with the unpacked entries.</summary>
    public static (EnvCell Cell, RetailEnvCell Entry, RetailEnvironment Environment) Unpacked(CellDump d, in Frame frame, BspTree physicsBsp,
        BspTree cellBsp, List<CellDump> dumps)
    {
        var verts = new List<Vector3>();
        var drawing = new List<PolyDef>();
        (_, List<ushort[]> drawIds) = RetailEntries.Mesh(Array.ConvertAll(d.PortalPolygons, p => (IReadOnlyList<Vector3>)p.Vertices), verts);
        for (int i = 0; i < drawIds.Count; i++)
        {
            drawing.Add(new PolyDef((short)i, drawIds[i]));
        }

        (_, PolyDef[] physics) = RetailEntries.Defs(physicsBsp.Polygons.ToArray(), verts);
        var portalList = new List<ushort>();
        var portals = new PortalDef[d.Portals.Length];
        for (int i = 0; i < d.Portals.Length; i++)
        {
            DumpPortal p = d.Portals[i];
            if (!portalList.Contains(p.PolygonId))
            {
                portalList.Add(p.PolygonId);
            }

            uint other = p.OtherCellId == 0xFFFF ? CellPortal.OutsideCellId : Block | p.OtherCellId;
            portals[i] = new PortalDef(p.Flags, (short)p.PolygonId, p.OtherCellId, (short)BackPortal(dumps, other, d.CellId));
        }

        ushort low = (ushort)(d.CellId & 0xFFFF);
        byte[] env = RetailEntries.Environment(0x0D000000u | low,
            w => RetailEntries.CellStruct(w, 0, verts, drawing, portalList.ToArray(), cellBsp, physics, physicsBsp));
        byte[] cell = RetailEntries.EnvCell(d.CellId, 0, low, 0, frame, portals);
        RetailEnvironment e = RetailEnvironment.Unpack(env);
        RetailEnvCell c = RetailEnvCell.Unpack(cell);
        return (c.ToEnvCell(e), c, e);
    }

    /// <summary>Reads every EnvCell dump of the four cellar folders.</summary>
    public static List<CellDump> ReadDumps(string geometryDir)
    {
        var dumps = new List<CellDump>();
        foreach (string sub in new[] { "cellar-ascent", "cellar-rooms", "cellar-lip", "flap-doorway" })
        {
            foreach (string f in Directory.GetFiles(Path.Combine(geometryDir, sub), "0x*.json"))
            {
                if (!f.EndsWith(".gfxobj.json", StringComparison.Ordinal))
                {
                    dumps.Add(CellDump.Read(f));
                }
            }
        }

        return dumps;
    }

    /// <summary>The library polygons of a dump's polygon list (ids = index), as today's path builds them.</summary>
    public static Polygon[] PolygonsOf(DumpPolygon[] polys) => ToPolygons(polys);

    /// <summary>The inward hull planes today's path builds the cell region from.</summary>
    public static CollisionPlane[] CellPlanesOf(CellDump d) => HullPlanes(d);

    /// <summary>True for an indoor (env cell) id: low word 0x0100 and above.</summary>
    public static bool IsIndoor(uint id) => (id & 0xFFFF) >= 0x0100;

    /// <summary>The cell frame of a dump: translation M41..M43, rotation from the upper 3 × 3 (row vectors).</summary>
    public static Frame FrameOf(Matrix4x4 m)
    {
        Matrix4x4 r = m;
        r.M41 = 0f;
        r.M42 = 0f;
        r.M43 = 0f;
        return new Frame(new Vector3(m.M41, m.M42, m.M43), Quaternion.Normalize(Quaternion.CreateFromRotationMatrix(r)));
    }

    private static int BackPortal(List<CellDump> dumps, uint other, uint self)
    {
        foreach (CellDump d in dumps)
        {
            if (d.CellId != other)
            {
                continue;
            }

            for (int i = 0; i < d.Portals.Length; i++)
            {
                if ((Block | d.Portals[i].OtherCellId) == self)
                {
                    return i;
                }
            }
        }

        return -1;
    }

    private static Polygon[] ToPolygons(DumpPolygon[] polys)
    {
        var result = new Polygon[polys.Length];
        for (int i = 0; i < polys.Length; i++)
        {
            result[i] = ToPolygon(polys[i], (short)i);
        }

        return result;
    }

    private static Polygon ToPolygon(DumpPolygon p, short id)
    {
        var vids = new ushort[p.Vertices.Length];
        for (int i = 0; i < vids.Length; i++)
        {
            vids[i] = (ushort)i;
        }

        return new Polygon(id, p.Vertices, vids);
    }

    // Inward planes of the convex hull of the cell's drawing polygons (walls, floor, ceiling and portals): every plane
    // through three vertices with all vertices on its front (1 mm), once each.
    private static CollisionPlane[] HullPlanes(CellDump d)
    {
        var pts = new List<Vector3>();
        foreach (DumpPolygon p in d.PortalPolygons)
        {
            foreach (Vector3 v in p.Vertices)
            {
                if (!pts.Exists(q => Vector3.DistanceSquared(q, v) < 1e-6f))
                {
                    pts.Add(v);
                }
            }
        }

        var planes = new List<CollisionPlane>();
        for (int a = 0; a < pts.Count; a++)
        {
            for (int b = a + 1; b < pts.Count; b++)
            {
                for (int c = b + 1; c < pts.Count; c++)
                {
                    Vector3 n = Vector3.Cross(pts[b] - pts[a], pts[c] - pts[a]);
                    if (n.LengthSquared() < 1e-8f)
                    {
                        continue;
                    }

                    n = Vector3.Normalize(n);
                    for (int sign = 0; sign < 2; sign++, n = -n)
                    {
                        float dd = -Vector3.Dot(n, pts[a]);
                        bool front = true;
                        foreach (Vector3 q in pts)
                        {
                            if (Vector3.Dot(n, q) + dd < -1e-3f)
                            {
                                front = false;
                                break;
                            }
                        }

                        if (front && !planes.Exists(pl => Vector3.Dot(pl.N, n) > 0.99999f && MathF.Abs(pl.D - dd) < 1e-3f))
                        {
                            planes.Add(new CollisionPlane(n, dd));
                        }
                    }
                }
            }
        }

        return planes.ToArray();
    }
}
