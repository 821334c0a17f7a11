using System;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary><c>GfxObjDegradeInfo::UnPack</c> (acclient.c:332293): the id, the level count, then 20 bytes a level (GfxObj id,
/// mode, minimum, ideal and maximum distance).</summary>
public class GfxObjDegradeInfoEntryTests
{
    [Fact]
    public void TheLevels_AreReadInOrder()
    {
        GfxObjDegradeInfoEntry d = GfxObjDegradeInfoEntry.UnPack(WorldEntries.DegradeInfo(0x11000005, (0x01000001, 1), (0x01000002, 2)));
        Assert.Equal(0x11000005u, d.Id);
        Assert.Equal(2, d.Degrades.Length);
        Assert.Equal(new GfxObjDegradeLevel(0x01000001, 1, 0f, 25f, 50f), d.Degrades[0]);
        Assert.Equal(0x01000002u, d.Degrades[1].GfxObjId);
        Assert.Equal(2u, d.Degrades[1].DegradeMode);
    }

    [Fact]
    public void ATruncatedLevel_NamesTheStructureAndOffset()
    {
        byte[] bytes = WorldEntries.DegradeInfo(0x11000005, (0x01000001, 1));
        var e = Assert.Throws<RetailDataFormatException>(() => GfxObjDegradeInfoEntry.UnPack(bytes.AsSpan(0, 20)));
        Assert.Equal("GfxObjDegradeInfo", e.Structure);
        // The count (the u32 at offset 4, after the id) says one level of 20 bytes, but only 12 remain after it: the error
        // names the count's own offset (issue #33: a format error points at the bad field, not past it).
        Assert.Equal(4, e.Offset);
    }

    [Fact]
    public void AnIdOfAnotherKind_IsRefused()
    {
        byte[] bytes = WorldEntries.DegradeInfo(0x01000005);
        var e = Assert.Throws<RetailDataFormatException>(() => GfxObjDegradeInfoEntry.UnPack(bytes));
        Assert.Equal(0, e.Offset);
    }
}
