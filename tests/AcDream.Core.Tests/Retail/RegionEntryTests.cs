using System;
using System.Linq;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// Region entries (0x13…) as <c>CRegionDesc::UnPack</c> (acclient.c:299775) reads them: the height table, the calendar, sky
/// and sounds walked byte for byte, the scene types (<c>CSceneType::unpack</c>, 304484) and the terrain types; the lookups
/// <c>NumSceneType</c> / <c>SceneCount</c> / <c>GetScene</c> (303305 / 303317 / 303333).
/// </summary>
public class RegionEntryTests
{
    internal static RegionDef Def(bool sky = true, int sounds = 2, bool scenes = true, string name = "Dereth") => new(
        SceneTypes:
        [
            new SceneTypeDef(0, [0x12000074, 0x12000075]),
            new SceneTypeDef(-1, [0x12000001]),
            new SceneTypeDef(1, []),
        ],
        TerrainTypes:
        [
            new TerrainTypeDef("BarrenRock", 0xFF808080, [0, -1, 1, 2]),
            new TerrainTypeDef("Grassland", 0xFF00A000, [1]),
            new TerrainTypeDef("Ice", 0xFFFFFFFF, []),
        ],
        Name: name,
        Sky: sky,
        SoundTables: sounds,
        ScenePart: scenes);

    [Fact]
    public void AWholeRegion_ReadsItsHeightsSceneTypesAndTerrainTypes()
    {
        RegionEntry r = RegionEntry.UnPack(RegionSceneBytes.Region(Def()));
        Assert.Equal(0x13000000u, r.Id);
        Assert.Equal(1u, r.RegionNumber);
        Assert.Equal("Dereth", r.Name);
        Assert.Equal(0x13u, r.PartsMask); // sky 0x10, sound 0x01, scenes 0x02
        Assert.Equal(2, r.SoundTableCount);
        for (int i = 0; i < 256; i++)
        {
            Assert.Equal(2f * i, r.LandHeightTable[(byte)i]);
        }

        Assert.Equal(3, r.SceneTypes.Count);
        Assert.Equal(0, r.SceneTypes[0].SoundTableIndex);
        Assert.Equal(-1, r.SceneTypes[1].SoundTableIndex);
        Assert.Equal([0x12000074u, 0x12000075u], r.SceneTypes[0].Scenes.ToArray());
        Assert.Equal(3, r.TerrainTypes.Count);
        Assert.Equal("Grassland", r.TerrainTypes[1].Name);
        Assert.Equal(0xFF00A000u, r.TerrainTypes[1].Color);
        Assert.Equal([0, -1, 1, 2], r.TerrainTypes[0].SceneTypes.ToArray());
    }

    [Fact]
    public void TheLookups_AreRetails()
    {
        RegionEntry r = RegionEntry.UnPack(RegionSceneBytes.Region(Def()));
        Assert.Equal(4, r.NumSceneType(0));
        Assert.Equal(1, r.NumSceneType(1));
        Assert.Equal(0, r.NumSceneType(2));
        Assert.Equal(0, r.NumSceneType(3));          // a type the region does not have
        Assert.Equal(2, r.SceneCount(0, 0));
        Assert.Equal(0, r.SceneCount(0, 1));         // -1 in the data: a null scene type counts 0
        Assert.Equal(1, r.SceneCount(0, 2));
        Assert.Equal(0, r.SceneCount(0, 3));         // a scene type with no scenes
        Assert.Equal(0, r.SceneCount(0, 4));         // a slot past the list
        Assert.Equal(0, r.SceneCount(31, 0));
        Assert.Equal(0x12000075u, r.GetScene(0, 0, 1));
        Assert.Equal(0u, r.GetScene(0, 0, 2));      // index past the list: the null id
        Assert.Equal(0x12000001u, r.GetScene(1, 0, 0));
        Assert.Equal(0u, r.GetScene(0, 1, 0));
    }

    [Fact]
    public void WithoutSkyOrSounds_TheTablesReadTheSame()
    {
        RegionDef def = Def(sky: false, sounds: 0) with
        {
            SceneTypes = [new SceneTypeDef(-1, [0x12000074, 0x12000075]), new SceneTypeDef(-1, [0x12000001]), new SceneTypeDef(-1, [])],
        };
        RegionEntry r = RegionEntry.UnPack(RegionSceneBytes.Region(def));
        Assert.Equal(0x02u, r.PartsMask);
        Assert.Equal(0, r.SoundTableCount);
        Assert.Equal(0x12000075u, r.GetScene(0, 0, 1));
    }

    [Fact]
    public void WithoutScenes_TerrainSlotsMustBeEmpty()
    {
        RegionDef none = Def(scenes: false) with
        {
            TerrainTypes = [new TerrainTypeDef("BarrenRock", 1, [-1, -1])],
        };
        RegionEntry r = RegionEntry.UnPack(RegionSceneBytes.Region(none));
        Assert.Empty(r.SceneTypes);
        Assert.Equal(2, r.NumSceneType(0));
        Assert.Equal(0, r.SceneCount(0, 0));

        // Retail would read through a null scene description here.
        Assert.Equal("CTerrainDesc", Assert.Throws<RetailDataFormatException>(() => RegionEntry.UnPack(RegionSceneBytes.Region(Def(scenes: false)))).Structure);
    }

    [Theory]
    [InlineData("")]
    [InlineData("D")]
    [InlineData("De")]
    [InlineData("Der")]
    [InlineData("Dere")]
    [InlineData("Deret")]
    [InlineData("Dereth")]
    [InlineData("Dereth!")]
    public void Names_OfEveryLengthModuloFour_PadToTheEntrysWord(string name)
    {
        RegionEntry r = RegionEntry.UnPack(RegionSceneBytes.Region(Def(name: name)));
        Assert.Equal(name, r.Name);
        Assert.Equal(0x12000075u, r.GetScene(0, 0, 1));
    }

    [Fact]
    public void ALongName_TakesThe0xFFFFEscape()
    {
        string name = new('x', 70000);
        byte[] bytes = RegionSceneBytes.Region(Def(name: name));
        Assert.Equal(0xFFFF, BitConverter.ToUInt16(bytes, 12));
        Assert.Equal(70000u, BitConverter.ToUInt32(bytes, 14));
        Assert.Equal(name, RegionEntry.UnPack(bytes).Name);
    }

    [Fact]
    public void TheBytesAfterTheTerrainTypes_AreNotRead()
    {
        var tail = new byte[333];
        new Random(35).NextBytes(tail);
        Assert.Equal(3, RegionEntry.UnPack(RegionSceneBytes.Region(Def() with { Tail = tail })).TerrainTypes.Count);
        Assert.Equal(3, RegionEntry.UnPack(RegionSceneBytes.Region(Def() with { Tail = [] })).TerrainTypes.Count);
    }

    [Fact]
    public void BadBytes_AreRefused_NamingTheStructureAndOffset()
    {
        AssertFormat(RegionSceneBytes.Region(Def() with { Id = 0x12000000 }), "CRegionDesc", 0);
        AssertFormat(RegionSceneBytes.Region(Def() with { Version = 4 }), "CRegionDesc", 8);

        // Height 7 is 900 m: after id, number, version (12), the name (2 + 6 bytes), the eight LandDefs values (32).
        float[] h = RegionSceneBytes.MetreHeights();
        h[7] = 900f;
        AssertFormat(RegionSceneBytes.Region(Def() with { Heights = h }), "CRegionDesc", 12 + 8 + 32 + 4 * 7);

        Assert.Equal("SkyObjectReplace",
            Assert.Throws<RetailDataFormatException>(() => RegionEntry.UnPack(RegionSceneBytes.Region(Def() with { SkyReplaceIndex = 2 }))).Structure);
        Assert.Equal("CSceneDesc",
            Assert.Throws<RetailDataFormatException>(() => RegionEntry.UnPack(RegionSceneBytes.Region(Def(sounds: 1)))).Structure);

        byte[] good = RegionSceneBytes.Region(Def());
        for (int n = 0; n < good.Length - 4; n += 7)
        {
            Assert.Throws<RetailDataFormatException>(() => RegionEntry.UnPack(good.AsSpan(0, n)));
        }
    }

    private static void AssertFormat(byte[] bytes, string structure, int offset)
    {
        RetailDataFormatException e = Assert.Throws<RetailDataFormatException>(() => RegionEntry.UnPack(bytes));
        Assert.Equal(structure, e.Structure);
        Assert.Equal(offset, e.Offset);
    }
}
