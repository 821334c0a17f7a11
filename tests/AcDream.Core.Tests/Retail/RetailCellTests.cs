using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CEnvironment::UnPack</c> (acclient.c:352987), <c>CCellStruct::UnPack</c> (acclient.c:355822), <c>CEnvCell::UnPack</c>
/// (acclient.c:349133) with <c>CCellPortal::UnPack</c> (acclient.c:362378): a test per field group.
/// </summary>
public class RetailCellTests
{
    // A 4 × 4 × 3 box room: floor (id 0) and a door quad (id 1) in the south wall y = 0 as drawing polygons, the door listed
    // as the one portal; the floor as the one physics polygon; the cell region as six inward planes.
    internal static (byte[] Env, RetailCellStructParts Parts) Room()
    {
        Polygon floor = BspScene.Quad(new(0f, 0f, 0f), new(4f, 0f, 0f), new(4f, 4f, 0f), new(0f, 4f, 0f), 0);
        Polygon door = BspScene.Quad(new(1f, 0f, 0f), new(1f, 0f, 2f), new(2f, 0f, 2f), new(2f, 0f, 0f), 1);
        var verts = new List<Vector3>();
        (_, PolyDef[] drawing) = RetailEntries.Defs(new[] { floor, door }, verts);
        BspTree physicsBsp = BspBuilder.Build(new[] { floor });
        (_, PolyDef[] physics) = RetailEntries.Defs(physicsBsp.Polygons.ToArray(), verts);
        BspTree cellBsp = BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(Vector3.Zero, new Vector3(4f, 4f, 3f)));
        byte[] env = RetailEntries.Environment(0x0D000042,
            w => RetailEntries.CellStruct(w, 7, verts, drawing, [1], cellBsp, physics, physicsBsp),
            w => RetailEntries.CellStruct(w, 8, verts, drawing, [], cellBsp, physics, physicsBsp, drawingBsp: false));
        return (env, new RetailCellStructParts(verts.Count, cellBsp));
    }

    internal sealed record RetailCellStructParts(int VertexCount, BspTree CellBsp);

    private static readonly Frame CellFrame = new(new Vector3(130.5f, 11.5f, 94f), new Quaternion(0f, 0f, 1f, 0f));

    internal static byte[] Cell(uint restriction = 0, (uint, Frame)[]? statics = null) => RetailEntries.EnvCell(0xA9B40143, 1, 0x42, 0,
        CellFrame, [new PortalDef(7, 1, 0xFFFF, 0), new PortalDef(1, 1, 0x0144, 3)], visible: [0x0144, 0x0145, 0x0146],
        surfaces: [0x0101, 0x0102], statics: statics, restriction: restriction);

    [Fact]
    public void Environment_HoldsEachStructure_InOrder()
    {
        EnvironmentEntry e = EnvironmentEntry.UnPack(Room().Env);
        Assert.Equal(0x0D000042u, e.Id);
        Assert.Equal(2, e.CellStructs.Length);
        Assert.Equal(7u, e.CellStructs[0].CellStructId);
        Assert.Equal(8u, e.CellStructs[1].CellStructId);
        Assert.Null(e.GetCellStruct(2));
        Assert.True(e.CellStructs[0].HasDrawingBsp);
        Assert.False(e.CellStructs[1].HasDrawingBsp);
    }

    [Fact]
    public void CellStruct_Vertices_PortalPolygons_AndPhysicsPolygons()
    {
        (byte[] env, RetailCellStructParts parts) = Room();
        CellStructEntry s = EnvironmentEntry.UnPack(env).CellStructs[0];
        Assert.Equal(parts.VertexCount, s.Vertices.Length);
        Assert.Equal(2, s.PolygonCount);
        Assert.Equal(1, s.Portals.Length);
        Assert.Equal(1, s.Portals[0].PolyId);
        // The door quad (1,0,0) (1,0,2) (2,0,2) (2,0,0): (0,0,2) × (1,0,2) = (0·2 - 2·0, 2·1 - 0·2, 0) = (0, 2, 0): normal +y.
        Assert.Equal(new Vector3(0f, 1f, 0f), s.Portals[0].Plane.N);
        Assert.Equal(1, s.PhysicsPolygons.Length);
        Assert.Equal(new Vector3(0f, 0f, 1f), s.PhysicsPolygons[0].Plane.N);
        Assert.Same(s.PhysicsBsp, s.Structure.PhysicsBsp);
    }

    [Fact]
    public void CellStruct_CellBsp_IsTheStoredPlaneChain_EndingInALeaf()
    {
        (byte[] env, RetailCellStructParts parts) = Room();
        BspTree cell = EnvironmentEntry.UnPack(env).CellStructs[0].CellBsp;
        // Six 'BPIn' nodes, each the positive child of the one before, then the leaf the layout needs at the end.
        Assert.Equal(7, cell.Nodes.Length);
        for (int i = 0; i < 6; i++)
        {
            Assert.Equal(BspNodeType.SplitPositiveChild, cell.Nodes[i].Type);
            Assert.Equal(parts.CellBsp.Nodes[i].SplittingPlane.N, cell.Nodes[i].SplittingPlane.N);
            Assert.Equal(i + 1, cell.Nodes[i].PosNode);
        }

        Assert.True(cell.Nodes[6].IsLeaf);
        Assert.True(cell.PointInsideCellBsp(new Vector3(2f, 2f, 1f)));
        Assert.False(cell.PointInsideCellBsp(new Vector3(2f, -1f, 1f)));
    }

    [Fact]
    public void EnvCell_Ids_Surfaces_EnvironmentAndFrame()
    {
        EnvCellEntry c = EnvCellEntry.UnPack(Cell());
        Assert.Equal(0xA9B40143u, c.Id);
        Assert.Equal(1u, c.Flags & EnvCellEntry.SeenOutsideFlag);
        Assert.Equal(new uint[] { 0x08000101, 0x08000102 }, c.SurfaceIds.ToArray());
        Assert.Equal(0x0D000042u, c.EnvironmentId);
        Assert.Equal(0, c.CellStructIndex);
        Assert.Equal(CellFrame.Origin, c.Frame.Origin);
        Assert.Equal(-1f, c.Frame.LocalToGlobalVec(Vector3.UnitX).X, 5); // the 180° yaw
    }

    [Fact]
    public void EnvCell_Portals_AndVisibleCells()
    {
        EnvCellEntry c = EnvCellEntry.UnPack(Cell());
        // Flags 7: exact match, portal side 0 (bit 2), outdoors (bit 4: other cell -1 whatever the stored word).
        Assert.Equal(CellPortal.OutsideCellId, c.Portals[0].OtherCellId);
        Assert.True(c.Portals[0].ExactMatch);
        Assert.Equal(0, c.Portals[0].PortalSide);
        // Flags 1: portal side 1, the block prefix on the stored word.
        Assert.Equal(0xA9B40144u, c.Portals[1].OtherCellId);
        Assert.Equal(1, c.Portals[1].PortalSide);
        Assert.Equal(3, c.Portals[1].OtherPortalId);
        Assert.Equal(new uint[] { 0xA9B40144, 0xA9B40145, 0xA9B40146 }, c.VisibleCells.ToArray());
    }

    [Fact]
    public void EnvCell_StaticObjects_AndRestriction()
    {
        var f = new Frame(new Vector3(131f, 12f, 94f), Quaternion.Identity);
        EnvCellEntry c = EnvCellEntry.UnPack(Cell(0x7000_0001, [(0x02000AB1, f)]));
        Assert.Equal(0x02000AB1u, c.StaticObjects[0].Id);
        Assert.Equal(f.Origin, c.StaticObjects[0].Frame.Origin);
        Assert.Equal(0x70000001u, c.RestrictionObject);
        Assert.True(EnvCellEntry.UnPack(Cell()).StaticObjects.IsEmpty);
        Assert.Equal(0u, EnvCellEntry.UnPack(Cell()).RestrictionObject);
    }

    [Fact]
    public void ToEnvCell_PlacesTheStructure_AndLooksUpThePortalPolygonsById()
    {
        EnvironmentEntry e = EnvironmentEntry.UnPack(Room().Env);
        EnvCell cell = EnvCellEntry.UnPack(Cell()).ToEnvCell(e);
        Assert.Equal(0xA9B40143u, cell.CellId);
        Assert.Same(e.CellStructs[0].Structure, cell.Structure);
        Assert.Same(e.CellStructs[0].Portals[0], cell.Portals[0].Portal);
        Assert.True(cell.Portals[0].IsOutside);
        // The room point (2, 2, 1) lies at 130.5 - 2, 11.5 - 2, 95 under the 180° yaw.
        Assert.True(cell.PointInCell(new Vector3(128.5f, 9.5f, 95f)));
    }

    [Fact]
    public void APortalNamingAPolygonNotAmongThePortals_IsAFormatError()
    {
        EnvironmentEntry e = EnvironmentEntry.UnPack(Room().Env);
        byte[] bytes = RetailEntries.EnvCell(0xA9B40143, 0, 0x42, 0, CellFrame, [new PortalDef(1, 0, 0x0144, 0)]);
        var ex = Assert.Throws<RetailDataFormatException>(() => EnvCellEntry.UnPack(bytes).ToEnvCell(e));
        Assert.Contains("polygon 0", ex.Reason);
        // entry id 4, flags 4, cell id 4, counts 4, environment 2, index 2, frame 28 = 48: the portal; its polygon id at 50.
        Assert.Equal(50, ex.Offset);
    }

    [Fact]
    public void ACellIdThatIsNotIndoor_IsAFormatError_AtTheInnerId()
    {
        byte[] bytes = RetailEntries.EnvCell(0xA9B40010, 0, 0x42, 0, CellFrame, []);
        var ex = Assert.Throws<RetailDataFormatException>(() => EnvCellEntry.UnPack(bytes));
        Assert.Equal(8, ex.Offset);
    }

    [Fact]
    public void APortalIndexPastThePolygons_IsAFormatError()
    {
        var verts = new List<Vector3> { Vector3.Zero, Vector3.UnitX, Vector3.UnitY };
        BspTree phys = BspBuilder.Build(new[] { BspScene.Quad(Vector3.Zero, Vector3.UnitX, Vector3.One, Vector3.UnitY) });
        (_, PolyDef[] physDefs) = RetailEntries.Defs(phys.Polygons.ToArray(), verts);
        byte[] env = RetailEntries.Environment(0x0D000001, w => RetailEntries.CellStruct(w, 0, verts, [new PolyDef(0, [0, 1, 2])], [1],
            BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(Vector3.Zero, Vector3.One)), physDefs, phys));
        var ex = Assert.Throws<RetailDataFormatException>(() => EnvironmentEntry.UnPack(env));
        Assert.Contains("portal polygon index 1", ex.Reason);
    }
}
