using System;
using System.Collections.Generic;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Scenery;
using AcDream.Core.Tests.Retail;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Bad bytes for the region and scene unpackers, as <see cref="RetailDataFuzzTests"/> feeds the others: every truncation,
/// random buffers, byte flips, huge counts and splices. Each call reads an entry (and its lookups and a generation from it
/// work) or throws <see cref="RetailDataFormatException"/> — never another exception, never a hang.
/// </summary>
public class RegionSceneFuzzTests
{
    private const int Mutations = 1500;

    public static IEnumerable<object[]> Structures()
    {
        yield return ["CRegionDesc"];
        yield return ["Scene"];
    }

    private static byte[] Valid(string name) => name == "Scene"
        ? RegionSceneBytes.Scene(0x12000074, SceneEntryTests.Published())
        : RegionSceneBytes.Region(RegionEntryTests.Def());

    private static void Read(string name, byte[] bytes)
    {
        try
        {
            if (name == "Scene")
            {
                SceneEntry s = SceneEntry.UnPack(bytes);
                var list = new List<ScenePlacement>();
                SceneryGenerator.Generate(SceneryScene.Block(SceneryScene.Word(1, 1)), SceneryScene.Region(), _ => s, null, list);
            }
            else
            {
                RegionEntry r = RegionEntry.UnPack(bytes);
                for (uint t = 0; t < 33; t++)
                {
                    for (uint slot = 0; slot < 33; slot++)
                    {
                        r.GetScene(t, slot, (uint)r.SceneCount(t, slot) / 2);
                    }
                }
            }
        }
        catch (RetailDataFormatException e)
        {
            Assert.InRange(e.Offset, 0, bytes.Length);
            Assert.False(string.IsNullOrEmpty(e.Structure));
        }
    }

    [Theory]
    [MemberData(nameof(Structures))]
    public void EveryTruncation_IsAFormatError_OrAShorterValidEntry(string name)
    {
        byte[] valid = Valid(name);
        Read(name, valid);
        for (int n = 0; n < valid.Length; n++)
        {
            Read(name, valid.AsSpan(0, n).ToArray());
        }
    }

    [Theory]
    [MemberData(nameof(Structures))]
    public void RandomBuffers_AndMutations_OnlyEverThrowTheFormatException(string name)
    {
        var rng = new Random(0x35 + name.Length);
        byte[] valid = Valid(name);
        uint[] huge = [0xFFFFFFFF, 0x7FFFFFFF, 0x80000000, 0x00010000, 0x0000FFFF, 0x00001000, 3, 0x13000000];
        for (int i = 0; i < Mutations; i++)
        {
            byte[] b;
            switch (i % 4)
            {
                case 0:
                    b = new byte[rng.Next(0, 1200)];
                    rng.NextBytes(b);
                    if (b.Length >= 12 && rng.Next(2) == 0)
                    {
                        // A plausible header, so that the random bytes reach past the id and version checks.
                        BitConverter.TryWriteBytes(b.AsSpan(0), name == "Scene" ? 0x12000001u : 0x13000000u);
                        BitConverter.TryWriteBytes(b.AsSpan(name == "Scene" ? 4 : 8), name == "Scene" ? 1u : 3u);
                    }

                    break;
                default:
                    b = ByteMutations.Mutate(rng, valid, i % 4, huge);
                    break;
            }

            Read(name, b);
        }
    }
}
