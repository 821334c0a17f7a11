using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// Scene entries (0x12…) as <c>Scene::UnPack</c> (acclient.c:463119) and <c>ObjectDesc::UnPack</c> (462929) read them:
/// the published spot values of the real Scene 0x12000074 (DatReaderWriter's EOR test) written to the decompiled layout
/// and read back, and bad bytes refused with the structure and offset.
/// </summary>
public class SceneEntryTests
{
    /// <summary>Scene 0x12000074 as published: three spots; object 0 a Setup 0x02000247 (freq 0.352, displacement 7.38 /
    /// 7.02, scale 0.7-1.5, rotation 360); object 2 a server spot (id 0, freq 1, displacement -0.66 / 1.38, scale 1, rotation
    /// 360, weenie 1). Object 1 is not published: a stand-in tree. Base frames are not published: identity, origin 0.</summary>
    internal static ObjectDesc[] Published() =>
    [
        new(0x02000247, Frame.Identity, 0.352f, 7.38f, 7.02f, 0.7f, 1.5f, 360f, 0f, 90f, 0, 0, 0),
        new(0x020002D3, Frame.FromHeading(new Vector3(1f, -2f, 0.5f), 45.0), 0.1f, 3f, 3f, 0.9f, 1.1f, 0f, 0.8f, 1f, 1, 7, 0),
        new(0, Frame.Identity, 1f, -0.66f, 1.38f, 1f, 1f, 360f, 0f, 90f, 0, 0, 1),
    ];

    [Fact]
    public void PublishedScene0x12000074_ReadsBack()
    {
        byte[] bytes = RegionSceneBytes.Scene(0x12000074, Published());
        Assert.Equal(4 + 4 + 3 * 76, bytes.Length); // Scene::Pack sizes 76 * n + 4 after the id (acclient.c:463063)
        SceneEntry s = SceneEntry.UnPack(bytes);
        Assert.Equal(0x12000074u, s.Id);
        Assert.Equal(3, s.Objects.Count);
        ObjectDesc o0 = s.Objects[0];
        Assert.Equal(0x02000247u, o0.ObjectId);
        Assert.Equal(0.352f, o0.Frequency);
        Assert.Equal(7.38f, o0.DisplaceX);
        Assert.Equal(7.02f, o0.DisplaceY);
        Assert.Equal(0.7f, o0.MinScale);
        Assert.Equal(1.5f, o0.MaxScale);
        Assert.Equal(360f, o0.MaxRotation);
        Assert.Equal(0u, o0.WeenieObj);
        ObjectDesc o2 = s.Objects[2];
        Assert.Equal(0u, o2.ObjectId);
        Assert.Equal(1f, o2.Frequency);
        Assert.Equal(-0.66f, o2.DisplaceX);
        Assert.Equal(1.38f, o2.DisplaceY);
        Assert.Equal(1u, o2.WeenieObj);
        ObjectDesc o1 = s.Objects[1];
        Assert.Equal(new Vector3(1f, -2f, 0.5f), o1.BaseFrame.Origin);
        Assert.Equal(45.0, o1.BaseFrame.Heading, 4);
        Assert.Equal((0.8f, 1f, 1u, 7u), (o1.MinSlope, o1.MaxSlope, o1.Align, o1.Orient));
    }

    [Fact]
    public void TheSpotLayout_IsTheDecompiledOne()
    {
        // Disk offsets of a spot (acclient.h:57271 / ObjectDesc::UnPack): id 0, frame 4 (origin, w x y z), freq 32,
        // displace x 36, y 40, min scale 44, max scale 48, max rot 52, min slope 56, max slope 60, align 64, orient 68,
        // weenie 72. The first spot starts after the scene id and the count (byte 8).
        byte[] b = RegionSceneBytes.Scene(0x12000074, Published());
        float F(int at) => BitConverter.ToSingle(b, 8 + at);
        uint U(int at) => BitConverter.ToUInt32(b, 8 + at);
        Assert.Equal(0x02000247u, U(0));
        Assert.Equal(1f, F(16)); // quaternion w of the identity
        Assert.Equal(0.352f, F(32));
        Assert.Equal(7.38f, F(36));
        Assert.Equal(7.02f, F(40));
        Assert.Equal(0.7f, F(44));
        Assert.Equal(1.5f, F(48));
        Assert.Equal(360f, F(52));
        Assert.Equal(90f, F(60));
        Assert.Equal(1u, BitConverter.ToUInt32(b, 8 + 2 * 76 + 72)); // object 2's weenie_obj
    }

    [Fact]
    public void AnEmptyScene_HasNoObjects() => Assert.Empty(SceneEntry.UnPack(RegionSceneBytes.Scene(0x12000001, [])).Objects);

    [Fact]
    public void BadBytes_AreRefused_NamingTheStructureAndOffset()
    {
        byte[] good = RegionSceneBytes.Scene(0x12000074, Published());

        byte[] wrongId = (byte[])good.Clone();
        wrongId[3] = 0x13;
        AssertFormat(wrongId, "Scene", 0);

        byte[] bigCount = (byte[])good.Clone();
        BitConverter.TryWriteBytes(bigCount.AsSpan(4), 4u); // 4 spots need 304 bytes, 228 remain
        AssertFormat(bigCount, "Scene", 4); // the error names the count's own offset (issue #33)

        // A cut inside the last spot: the count is checked against the bytes before any spot is read.
        AssertFormat(good.AsSpan(0, 8 + 2 * 76 + 40).ToArray(), "Scene", 4);

        byte[] badRotation = (byte[])good.Clone();
        BitConverter.TryWriteBytes(badRotation.AsSpan(8 + 16), 2f); // w = 2: not a unit quaternion
        AssertFormat(badRotation, "ObjectDesc", 8 + 4);

        byte[] nanFreq = (byte[])good.Clone();
        BitConverter.TryWriteBytes(nanFreq.AsSpan(8 + 76 + 32), float.NaN);
        AssertFormat(nanFreq, "ObjectDesc", 8 + 76 + 32);
    }

    private static void AssertFormat(byte[] bytes, string structure, int offset)
    {
        RetailDataFormatException e = Assert.Throws<RetailDataFormatException>(() => SceneEntry.UnPack(bytes));
        Assert.Equal(structure, e.Structure);
        Assert.Equal(offset, e.Offset);
    }
}
