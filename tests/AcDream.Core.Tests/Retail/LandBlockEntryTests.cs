using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CLandBlock::UnPack</c> (acclient.c:351520) with <c>CLandBlockStruct::UnPack</c> (acclient.c:354108), and
/// <c>CLandBlockInfo::UnPack</c> (acclient.c:351048) with <c>CBldPortal::UnPack</c> (acclient.c:362498): a test per field group.
/// </summary>
public class LandBlockEntryTests
{
    internal static (ushort[] Terrain, byte[] Height) Ramp()
    {
        var terrain = new ushort[81];
        var height = new byte[81];
        for (int i = 0; i < 81; i++)
        {
            terrain[i] = (ushort)(i << 2);
            height[i] = (byte)(i / 9); // x = i / 9: height index x
        }

        return (terrain, height);
    }

    [Fact]
    public void LandBlock_InfoFlag_Terrain_Heights_AndAlignment()
    {
        (ushort[] t, byte[] h) = Ramp();
        byte[] bytes = RetailEntries.LandBlock(0x8080FFFF, true, t, h);
        // 4 + 4 + 162 + 81 = 251, padded to 252.
        Assert.Equal(252, bytes.Length);
        LandBlockEntry b = LandBlockEntry.UnPack(bytes);
        Assert.Equal(0x8080FFFFu, b.Id);
        Assert.True(b.HasInfo);
        Assert.Equal(t, b.Terrain.ToArray());
        Assert.Equal(h, b.Height.ToArray());
    }

    [Fact]
    public void LandBlock_ToLandBlock_UsesTheHeightTable()
    {
        (ushort[] t, byte[] h) = Ramp();
        LandBlock lb = LandBlockEntry.UnPack(RetailEntries.LandBlock(0x8080FFFF, false, t, h)).ToLandBlock(SweepScene.MetreTable());
        // The metre table maps index i to i metres: vertex (8, 0) (index 72, height index 8) stands 8 m high.
        Assert.Equal(8f, lb.Vertices[72].Z);
    }

    [Fact]
    public void LandBlock_ATruncatedHeightArray_IsAFormatError_AtTheMissingByte()
    {
        (ushort[] t, byte[] h) = Ramp();
        byte[] bytes = RetailEntries.LandBlock(0x8080FFFF, false, t, h).AsSpan(0, 200).ToArray();
        var e = Assert.Throws<RetailDataFormatException>(() => LandBlockEntry.UnPack(bytes));
        Assert.Equal("CLandBlockStruct", e.Structure);
        Assert.Equal(200, e.Offset);
    }

    internal static byte[] Info(bool restrictions = true) => RetailEntries.LandBlockInfo(0x8080FFFE, 2,
        [(0x02000345, new Frame(new Vector3(10f, 20f, 20f), Quaternion.Identity))],
        [new BuildingDef(0x01000777, new Frame(new Vector3(100f, 100f, 20f), Quaternion.Identity), 3,
            [new DoorDef(1, 0x0100, 0, [0x0100, 0x0101, 0x0102]), new DoorDef(3, 0x0101, 2, [0x0101, 0x0100])])],
        restrictions ? [(0x80800100, 0x70000002)] : null);

    [Fact]
    public void Info_CellCount_AndObjects()
    {
        LandBlockInfoEntry i = LandBlockInfoEntry.UnPack(Info());
        Assert.Equal(0x8080FFFEu, i.Id);
        Assert.Equal(2, i.NumCells);
        Assert.Equal(0x80800100u, i.CellId(0));
        Assert.Equal(0x80800101u, i.CellId(1));
        Assert.Equal(0x02000345u, i.Objects[0].Id);
        Assert.Equal(new Vector3(10f, 20f, 20f), i.Objects[0].Frame.Origin);
    }

    [Fact]
    public void Info_Buildings_TheirDoors_AndTheOddCountPadding()
    {
        LandBlockInfoEntry i = LandBlockInfoEntry.UnPack(Info());
        BuildingInfo b = i.Buildings[0];
        Assert.Equal(0x01000777u, b.ModelId);
        Assert.Equal(3u, b.NumLeaves);
        Assert.Equal(2, b.Portals.Length);
        // Door 0: three visible cells (odd: two bytes of padding follow), door 1 read after the padding.
        Assert.Equal(new uint[] { 0x80800100, 0x80800101, 0x80800102 }, b.Portals[0].VisibleCells);
        Assert.Equal(0x80800101u, b.Portals[1].OtherCellId);
        Assert.Equal(2, b.Portals[1].OtherPortalId);
        Assert.Equal(0, b.Portals[1].PortalSide);          // flag 2
        Assert.Equal(1, b.Portals[0].ToBldPortal().PortalSide);
    }

    [Fact]
    public void Info_RestrictionTable_WhenFlagged()
    {
        LandBlockInfoEntry i = LandBlockInfoEntry.UnPack(Info());
        Assert.Equal(1, i.BuildingFlags);
        Assert.Equal(0x70000002u, i.RestrictionTable[0x80800100]);
        Assert.Equal(0x70000002u, i.GetRestrictionIid(0x80800100));
        Assert.Equal(0u, i.GetRestrictionIid(0x80800101));
        Assert.Empty(LandBlockInfoEntry.UnPack(Info(restrictions: false)).RestrictionTable);
    }

    [Fact]
    public void Info_AnObjectCountBeyondTheBytes_IsRefused()
    {
        var w = new RetailDataWriter();
        w.UInt32(0x8080FFFE).UInt32(0).UInt32(1000);
        var e = Assert.Throws<RetailDataFormatException>(() => LandBlockInfoEntry.UnPack(w.ToArray()));
        Assert.Equal("CLandBlockInfo", e.Structure);
        Assert.Contains("object count", e.Reason);
        Assert.Contains("1000", e.Reason);
        Assert.Equal(8, e.Offset);   // the count's own field (id @0, cell count @4, object count @8), not the byte after it
    }
}
