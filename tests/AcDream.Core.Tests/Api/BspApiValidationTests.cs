using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

public class BspApiValidationTests
{
    private static Polygon Tri() => new(0, new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitY }, new ushort[] { 0, 1, 2 });

    private static CellStruct Struct() => new(null, BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(Vector3.Zero, Vector3.One)), Array.Empty<Polygon>());

    [Fact]
    public void EnvCell_RejectsOutdoorIdsAndBadFrames()
    {
        Assert.Throws<ArgumentException>(() => new EnvCell(0x80800001u, Frame.Identity, Struct(), Array.Empty<CellPortal>()));
        Assert.Throws<ArgumentException>(() => new EnvCell(0x8080FFFFu, Frame.Identity, Struct(), Array.Empty<CellPortal>()));
        Assert.Throws<ArgumentException>(() => new EnvCell(0x80800100u, new Frame(new Vector3(float.NaN, 0f, 0f), Quaternion.Identity), Struct(), Array.Empty<CellPortal>()));
        Assert.Throws<ArgumentNullException>(() => new EnvCell(0x80800100u, Frame.Identity, null!, Array.Empty<CellPortal>()));
    }

    [Fact]
    public void EnvCell_WithoutPortals_ContainsNoPoint_AsRetail()
    {
        // CEnvCell::point_in_cell (acclient.c:347934) returns 0 when the cell has no portals.
        var cell = new EnvCell(0x80800100u, Frame.Identity, Struct(), Array.Empty<CellPortal>());
        Assert.False(cell.PointInCell(new Vector3(0.5f, 0.5f, 0.5f)));
        var withPortal = new EnvCell(0x80800100u, Frame.Identity, Struct(), new[] { new CellPortal(CellPortal.OutsideCellId, Tri(), 0) });
        Assert.True(withPortal.PointInCell(new Vector3(0.5f, 0.5f, 0.5f)));
        Assert.False(withPortal.PointInCell(new Vector3(1.5f, 0.5f, 0.5f)));
    }

    [Fact]
    public void PhysicsPart_RejectsBadScaleAndPosition()
    {
        var gfx = new GfxObjPhysics(BspBuilder.Build(new[] { Tri() }));
        var p = new Position(0x80800001u, Vector3.Zero);
        Assert.Throws<ArgumentException>(() => new PhysicsPart(gfx, p, new Vector3(1f, 1f, 0f)));
        Assert.Throws<ArgumentException>(() => new PhysicsPart(gfx, p, new Vector3(1f, float.PositiveInfinity, 1f)));
        Assert.Throws<ArgumentException>(() => new PhysicsPart(gfx, new Position(0x80800001u, new Vector3(float.NaN, 0f, 0f)), Vector3.One));
        var part = new PhysicsPart(gfx, p, Vector3.One);
        Assert.Throws<ArgumentException>(() => part.SetPosition(new Position(0x80800001u, new Vector3(0f, float.NaN, 0f))));
        Assert.Equal(p, part.Pos);
    }

    [Fact]
    public void WorldCells_FindsIndoorAndOutdoorCells_AndForgetsRemovedOnes()
    {
        WorldCells cells = BspScene.FlatWorld();
        var cell = new EnvCell(0x80800100u, Frame.Identity, Struct(), Array.Empty<CellPortal>());
        cells.AddEnvCell(cell);
        Assert.Same(cell, cells.GetVisible(0x80800100u));
        Assert.IsType<LandCell>(cells.GetVisible(0x80800001u));
        Assert.Null(cells.GetVisible(0x80800101u));
        Assert.Null(cells.GetVisible(CellPortal.OutsideCellId));
        Assert.True(cells.RemoveEnvCell(0x80800100u));
        Assert.Null(cells.GetVisible(0x80800100u));
        Assert.Throws<ArgumentNullException>(() => new WorldCells(null!));
    }
}
