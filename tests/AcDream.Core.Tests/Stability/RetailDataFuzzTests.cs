using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Tests.Retail;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Bad bytes for every unpacker: random buffers, every truncation of a valid entry, random byte flips, and counts set to huge
/// values. Each call either reads an entry (and its conversions into library types succeed or throw the format exception) or
/// throws <see cref="RetailDataFormatException"/> — never another exception, never a hang (a seeded loop, 1,500 mutations per
/// structure).
/// </summary>
public class RetailDataFuzzTests
{
    private const int Mutations = 1500;

    public static IEnumerable<object[]> Structures()
    {
        yield return ["CSetup"];
        yield return ["CGfxObj"];
        yield return ["CEnvironment"];
        yield return ["CEnvCell"];
        yield return ["CLandBlock"];
        yield return ["CLandBlockInfo"];
        yield return ["GfxObjDegradeInfo"];
    }

    private static byte[] Valid(string name)
    {
        switch (name)
        {
            case "CSetup":
                return SetupEntryTests.TwoPartSetup();
            case "CGfxObj":
                var polys = new List<Polygon>();
                BspScene.AddBox(polys, Vector3.Zero, new Vector3(1f, 2f, 3f));
                BspTree t = BspBuilder.Build(polys.ToArray(), 2);
                (List<Vector3> v, PolyDef[] d) = RetailEntries.Defs(t.Polygons.ToArray());
                return RetailEntries.GfxObj(0x01000001, v, d, t, Vector3.One, drawing: d, degrade: 0x11000001, surfaces: [0x08000001]);
            case "CEnvironment":
                return RetailCellTests.Room().Env;
            case "CEnvCell":
                return RetailCellTests.Cell(0x70000001, [(0x02000001, AcDream.Core.Physics.Spatial.Frame.Identity)]);
            case "CLandBlock":
                (ushort[] ter, byte[] h) = LandBlockEntryTests.Ramp();
                return RetailEntries.LandBlock(0x8080FFFF, true, ter, h);
            case "GfxObjDegradeInfo":
                return WorldEntries.DegradeInfo(0x11000001, (0x01000001, 1), (0x01000002, 2), (0, 1));
            default:
                return LandBlockEntryTests.Info();
        }
    }

    private static readonly EnvironmentEntry Env = EnvironmentEntry.UnPack(RetailCellTests.Room().Env);

    // One unpack and the conversions a loader makes; only the format exception may escape.
    private static void Read(string name, byte[] bytes)
    {
        try
        {
            switch (name)
            {
                case "CSetup":
                    SetupEntry.UnPack(bytes).ToSetupPhysics();
                    break;
                case "CGfxObj":
                    _ = GfxObjEntry.UnPack(bytes).Physics;
                    break;
                case "CEnvironment":
                    EnvironmentEntry.UnPack(bytes);
                    break;
                case "CEnvCell":
                    EnvCellEntry.UnPack(bytes).ToEnvCell(Env);
                    break;
                case "CLandBlock":
                    LandBlockEntry.UnPack(bytes).ToLandBlock(SweepScene.MetreTable());
                    break;
                case "GfxObjDegradeInfo":
                    GfxObjDegradeInfoEntry.UnPack(bytes);
                    break;
                default:
                    LandBlockInfoEntry.UnPack(bytes);
                    break;
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
        Read(name, valid); // the valid entry itself reads
        for (int n = 0; n < valid.Length; n++)
        {
            Read(name, valid.AsSpan(0, n).ToArray());
        }
    }

    [Theory]
    [MemberData(nameof(Structures))]
    public void RandomBuffers_AndMutations_OnlyEverThrowTheFormatException(string name)
    {
        var rng = new Random(0x28 + name.Length);
        byte[] valid = Valid(name);
        uint[] huge = [0xFFFFFFFF, 0x7FFFFFFF, 0x80000000, 0x00010000, 0x0000FFFF, 0x00001000, 0x4C454146, 0x4250494E];
        for (int i = 0; i < Mutations; i++)
        {
            byte[] b;
            switch (i % 4)
            {
                case 0:
                    b = new byte[rng.Next(0, 400)];
                    rng.NextBytes(b);
                    break;
                default:
                    b = ByteMutations.Mutate(rng, valid, i % 4, huge);
                    break;
            }

            Read(name, b);
        }
    }

    [Fact]
    public void TheLoader_WithOneMutatedEntry_ThrowsOnlyTheFormatOrMissingEntryException_AndAddsNothingThen()
    {
        // A mutated count or id can name an entry the source does not hold: that is the loader's ArgumentException (a missing
        // entry); anything else wrong is the format exception. Either way the world is as before.
        var rng = new Random(28);
        DictionarySource clean = RoomSceneEntries.Source();
        var ids = new List<uint>(clean.Entries.Keys);
        for (int i = 0; i < 400; i++)
        {
            var s = new DictionarySource();
            foreach (KeyValuePair<uint, byte[]> e in clean.Entries)
            {
                s.Entries[e.Key] = (byte[])e.Value.Clone();
            }

            byte[] b = s.Entries[ids[i % ids.Count]];
            if (i % 2 == 0)
            {
                for (int k = rng.Next(1, 4); k > 0; k--)
                {
                    b[rng.Next(b.Length)] = (byte)rng.Next(256);
                }
            }
            else
            {
                s.Entries[ids[i % ids.Count]] = b.AsSpan(0, rng.Next(b.Length)).ToArray();
            }

            var cells = new AcDream.Core.Physics.Cells.WorldCells(SweepScene.Terrain());
            try
            {
                LandBlockLoader.Load(cells, 0x8080FFFF, s);
            }
            catch (RetailDataFormatException)
            {
                Assert.Equal(0, cells.Terrain.LandBlockCount);
                Assert.Equal(0, cells.EnvCellCount);
            }
            catch (ArgumentException e) when (e.Message.StartsWith("The data source holds no entry", StringComparison.Ordinal))
            {
                Assert.Equal(0, cells.Terrain.LandBlockCount);
                Assert.Equal(0, cells.EnvCellCount);
            }
        }
    }

    [Fact]
    public void TheWorldDoor_WithOneMutatedEntry_ThrowsOnlyTheFormatOrMissingEntryException_AndAddsNothingThen()
    {
        // The door reads the block, its info, and the Setups and GfxObjs of its statics and buildings (the pine, grass, rocks
        // and the Setup building): one of them mutated or truncated either still builds (a missing model id only fails its
        // object), or throws the format exception (or, for a terrain entry, the missing-entry exception) with nothing added.
        var rng = new Random(35);
        DictionarySource clean = WorldSceneEntries.Source(
            [(WorldSceneEntries.Pine, WorldSceneEntries.At(50f, 60f)), (WorldSceneEntries.LowRock, WorldSceneEntries.At(96.5f, 60f)),
                (WorldSceneEntries.Grass, WorldSceneEntries.At(20f, 20f))],
            [new BuildingDef(WorldSceneEntries.Building, WorldSceneEntries.At(100f, 100f), 0, [])]);
        clean.Entries[0x11000001] = WorldEntries.DegradeInfo(0x11000001, (WorldSceneEntries.Box, 1));
        clean.Entries[WorldSceneEntries.Blade] = WorldEntries.DrawingOnlyGfxObj(WorldSceneEntries.Blade, System.Numerics.Vector3.Zero,
            System.Numerics.Vector3.One, degrade: 0x11000001);
        var ids = new List<uint>(clean.Entries.Keys);
        for (int i = 0; i < 400; i++)
        {
            var s = new DictionarySource();
            foreach (KeyValuePair<uint, byte[]> e in clean.Entries)
            {
                s.Entries[e.Key] = (byte[])e.Value.Clone();
            }

            byte[] b = s.Entries[ids[i % ids.Count]];
            if (i % 2 == 0)
            {
                for (int k = rng.Next(1, 4); k > 0; k--)
                {
                    b[rng.Next(b.Length)] = (byte)rng.Next(256);
                }
            }
            else
            {
                s.Entries[ids[i % ids.Count]] = b.AsSpan(0, rng.Next(b.Length)).ToArray();
            }

            AcDream.Core.Physics.World.PhysicsWorld world = WorldSceneEntries.World(out AcDream.Core.Physics.Cells.WorldCells cells);
            var loader = new AcDream.Core.Physics.WorldData.WorldLoader(world, s);
            try
            {
                loader.Load(WorldSceneEntries.Block);
                continue;
            }
            catch (RetailDataFormatException e)
            {
                Assert.False(string.IsNullOrEmpty(e.Structure));
            }
            catch (ArgumentException e) when (e.Message.StartsWith("The data source holds no entry", StringComparison.Ordinal))
            {
            }

            Assert.Equal(0, world.ObjectCount);
            Assert.Equal(0, cells.Terrain.LandBlockCount);
            Assert.Empty(loader.LoadedBlockIds);
        }
    }
}
