using System;
using System.Buffers.Binary;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// A <see cref="RetailDataFormatException"/> names the offset of the bad field itself, not the byte after it nor the place
/// where a late check noticed it: a count that cannot fit is reported at the count, even when the check runs after other
/// fields were read (a cell structure's polygon count, a vertex's uv count, a cell's visible-cell count).
/// </summary>
public class FormatErrorOffsetTests
{
    [Fact]
    public void AGfxObjSurfaceCount_InTwoBytes_IsReportedAtOffset8()
    {
        // id @0, flags @4, surface count @8: 0x80 0x10 = 16 surfaces (64 bytes), none follow.
        byte[] b = [0xE8, 0x05, 0x00, 0x01, 0, 0, 0, 0, 0x80, 0x10];
        var e = Assert.Throws<RetailDataFormatException>(() => GfxObjEntry.UnPack(b));
        Assert.Equal("CGfxObj", e.Structure);
        Assert.Equal(8, e.Offset);
        Assert.Contains("surface count count 16", e.Reason);
    }

    [Fact]
    public void AVertexUvCount_CheckedAfterThePositionAndNormal_IsReportedAtTheCount()
    {
        // GfxObj: id @0, flags @4 (0), surface count @8 (0), vertex type @9, vertex count @13 (1); CSWVertex @17: id u16 @17,
        // uv count u16 @19 (1000: 8000 bytes), position @21, normal @33; the entry ends at 45.
        var b = new byte[45];
        b[9] = 1;
        b[13] = 1;
        BinaryPrimitives.WriteUInt16LittleEndian(b.AsSpan(19), 1000);
        var e = Assert.Throws<RetailDataFormatException>(() => GfxObjEntry.UnPack(b));
        Assert.Equal("CVertexArray", e.Structure);
        Assert.Equal(19, e.Offset);
    }

    [Fact]
    public void ACellStructurePolygonCount_CheckedAfterTheVertexArray_IsReportedAtTheCount()
    {
        // CEnvironment: id @0, structure count @4 (1); CCellStruct @8: id @8, polygon count @12 (1000), physics polygon count
        // @16, portal count @20, vertex array @24 (type 1, count 0), then 16 bytes (a structure takes 32 at least): the
        // polygons (12 bytes each at least) find 16 bytes.
        var w = new RetailDataWriter();
        w.UInt32(0x0D000001).UInt32(1).UInt32(0).UInt32(1000).UInt32(0).UInt32(0).UInt32(1).UInt32(0);
        w.Bytes(new byte[16]);
        var e = Assert.Throws<RetailDataFormatException>(() => EnvironmentEntry.UnPack(w.ToArray()));
        Assert.Equal(12, e.Offset);
        Assert.Contains("polygon count count 1000", e.Reason);
    }

    [Fact]
    public void ACellVisibleCount_CheckedAfterTheFrameAndPortals_IsReportedAtTheCount()
    {
        // CEnvCell: entry id @0, flags @4, cell id @8, surface count u8 @12, portal count u8 @13, visible-cell count u16 @14.
        byte[] b = RetailEntries.EnvCell(0x80800100, 0, 0x0101, 0, Frame.Identity, []);
        BinaryPrimitives.WriteUInt16LittleEndian(b.AsSpan(14), 0xFFFF);
        var e = Assert.Throws<RetailDataFormatException>(() => EnvCellEntry.UnPack(b));
        Assert.Equal("CEnvCell", e.Structure);
        Assert.Equal(14, e.Offset);
    }

    [Fact]
    public void AMoveToSpeedBeyondTheBound_IsReportedAtTheSpeed()
    {
        // Types 8 and 9 on the wire: bitfield u32 @0, speed f32 @4, desired heading f32 @8.
        byte[] b = new byte[12];
        BinaryPrimitives.WriteSingleLittleEndian(b.AsSpan(4), 101f);
        var e = Assert.Throws<RetailDataFormatException>(() => MovementParameters.UnPackNet(b, MovementType.TurnToHeading, out _));
        Assert.Equal(4, e.Offset);
    }
    [Fact]
    public void ANegativePhysicsSphereRadius_IsReportedAtTheRadius()
    {
        // GfxObj flags 1: id @0, flags @4, surface count @8 (0), vertex type @9, vertex count @13 (0), physics polygon count
        // @17 (0); the tree @18 is one leaf: tag @18, index @22, solid @26, sphere centre @30, radius @42, polygon count @46;
        // the sort centre @50. The root's sphere is the physics sphere (BSPTREE::GetSphere); its radius field is at 42.
        var b = new byte[62];
        BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(4), 1);
        b[9] = 1;
        BinaryPrimitives.WriteUInt32LittleEndian(b.AsSpan(18), RetailEntries.Leaf);
        BinaryPrimitives.WriteSingleLittleEndian(b.AsSpan(42), -1f);
        var e = Assert.Throws<RetailDataFormatException>(() => GfxObjEntry.UnPack(b));
        Assert.Contains("negative radius", e.Reason);
        Assert.Equal(42, e.Offset);
    }
}
