using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support.Geometry;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// The real geometry of ../shared/data/geometry (22 EnvCells of two Holtburg cellars and the shell GfxObj 0x01000A2B) written
/// into retail's byte layout and read back by the unpackers: the polygons' vertices are the dump's, their planes are
/// <c>CPolygon::make_plane</c>'s over those vertices (bit for bit today's path's, and within 1e-4 of the dump's planes, which
/// the dumping client computed with its own arithmetic), the portals and frames are the dump's. The dumps hold no BSP trees:
/// the trees written are today's path's (BspBuilder over the physics polygons; the hull-plane chain for the cell region) in
/// retail's node layout.
/// </summary>
public class RetailGeometryDumpTests
{
    private static void AssertPlaneNear(DumpPolygon dump, Polygon p)
    {
        Assert.True(Vector3.Distance(dump.Normal, p.Plane.N) < 1e-4f, $"normal {p.Plane.N} vs dump {dump.Normal}");
        Assert.True(MathF.Abs(dump.D - p.Plane.D) < 1e-3f, $"d {p.Plane.D} vs dump {dump.D}");
    }

    [GeometryDataFact]
    public void EveryCell_PolygonsPlanesPortalsAndFrame_EqualTheDump()
    {
        List<CellDump> dumps = CellarScene.ReadDumps(GeometryTestData.Dir!);
        Assert.Equal(22, dumps.Count); // the README table: cellar-ascent 10, cellar-rooms 6, cellar-lip 3, flap-doorway 3
        foreach (CellDump d in dumps)
        {
            Frame frame = CellarScene.FrameOf(d.WorldTransform);
            Polygon[] today = CellarScene.PolygonsOf(d.PhysicsPolygons);
            (EnvCell cell, EnvCellEntry entry, EnvironmentEntry env) = CellarScene.Unpacked(d, frame, BspBuilder.Build(today),
                BspBuilder.BuildCell(CellarScene.CellPlanesOf(d)), dumps);

            // Physics polygons: the dump's vertices, make_plane's plane.
            ReadOnlySpan<Polygon> physics = env.CellStructs[0].PhysicsPolygons;
            Assert.Equal(d.PhysicsPolygons.Length, physics.Length);
            foreach (Polygon p in physics)
            {
                DumpPolygon dp = d.PhysicsPolygons[p.PolyId];
                Assert.Equal(dp.Vertices, p.Vertices.ToArray());
                Assert.Equal(today[p.PolyId].Plane.N, p.Plane.N);
                Assert.Equal(today[p.PolyId].Plane.D, p.Plane.D);
                AssertPlaneNear(dp, p);
            }

            // Portals: other cell, side and exact match from the flags, the polygon the dump names.
            Assert.Equal(d.Portals.Length, cell.Portals.Length);
            for (int i = 0; i < d.Portals.Length; i++)
            {
                DumpPortal dp = d.Portals[i];
                CellPortal cp = cell.Portals[i];
                Assert.Equal(dp.OtherCellId == 0xFFFF ? CellPortal.OutsideCellId : CellarScene.Block | dp.OtherCellId, cp.OtherCellId);
                Assert.Equal((dp.Flags & 2) != 0 ? 0 : 1, cp.PortalSide);
                Assert.Equal((dp.Flags & 1) != 0, cp.ExactMatch);
                Assert.Equal((int)dp.PolygonId, (int)cp.Portal.PolyId);
                Assert.Equal(d.PortalPolygons[dp.PolygonId].Vertices, cp.Portal.Vertices.ToArray());
                AssertPlaneNear(d.PortalPolygons[dp.PolygonId], cp.Portal);
            }

            // Frame: the dump's translation; the rotation within float rounding of the dump's (re-normalised on read).
            Assert.Equal(d.CellId, cell.CellId);
            Assert.Equal(new Vector3(d.WorldTransform.M41, d.WorldTransform.M42, d.WorldTransform.M43), entry.Frame.Origin);
            Vector3 x = cell.Pos.Frame.LocalToGlobalVec(Vector3.UnitX);
            Assert.True(Vector3.Distance(new Vector3(d.WorldTransform.M11, d.WorldTransform.M12, d.WorldTransform.M13), x) < 1e-5f);
        }
    }

    [GeometryDataFact]
    public void TheShellGfxObj_PhysicsPolygonsAndPlanes_EqualTheDump()
    {
        DumpPolygon[] shell = CellDump.ReadGfxObjPolygons(Path.Combine(GeometryTestData.Dir!, "cellar-ascent", "0x01000A2B.gfxobj.json"));
        BspTree built = BspBuilder.Build(CellarScene.PolygonsOf(shell));
        (List<Vector3> verts, PolyDef[] defs) = RetailEntries.Defs(built.Polygons.ToArray());
        GfxObjEntry g = GfxObjEntry.UnPack(RetailEntries.GfxObj(0x01000A2B, verts, defs, built, Vector3.Zero));
        Assert.Equal(74, g.PhysicsPolygons.Length);   // README: 74 physics polys
        Assert.Equal(61, g.Vertices.Length);          // README: 61 distinct vertices
        foreach (Polygon p in g.PhysicsPolygons)
        {
            Assert.Equal(shell[p.PolyId].Vertices, p.Vertices.ToArray());
            AssertPlaneNear(shell[p.PolyId], p);
        }

        Assert.Equal(built.Nodes.Length, g.PhysicsBsp!.Nodes.Length);
    }
}
