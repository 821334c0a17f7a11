using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Cost of unpacking a landblock with its indoor cells from retail entries, per structure (time and bytes allocated), and of
/// the whole load into a world: a flat landblock 0x4040FFFF, its info (16 cells, one building, 8 static objects), a shell
/// GfxObj of 40 boxes (240 polygons, a BspBuilder tree in retail's layout), an environment of 16 structures (a room of 4 boxes
/// each: 24 physics polygons, 2 portals) and 16 cells, and a two-part Setup. The entries are built once in the set-up.
/// </summary>
[MemoryDiagnoser]
public class RetailDataBenchmarks
{
    private const int Cells = 16;
    private readonly Dictionary<uint, byte[]> _entries = new();
    private byte[] _setup = null!;

    private sealed class Source(Dictionary<uint, byte[]> entries) : IRetailDataSource
    {
        public bool TryGetEntry(uint id, out ReadOnlyMemory<byte> bytes)
        {
            bool ok = entries.TryGetValue(id, out byte[]? b);
            bytes = b;
            return ok;
        }
    }

    /// <summary>Writes every entry.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _entries[0x4040FFFF] = RetailEntries.LandBlock(0x4040FFFF, true, new ushort[81], new byte[81]);
        var objects = new (uint, Frame)[8];
        for (int i = 0; i < objects.Length; i++)
        {
            objects[i] = (0x02000001u + (uint)i, new Frame(new Vector3(10f + i, 20f, 0f), Quaternion.Identity));
        }

        _entries[0x4040FFFE] = RetailEntries.LandBlockInfo(0x4040FFFE, Cells, objects,
            [new BuildingDef(0x01000100, new Frame(new Vector3(100f, 100f, 0f), Quaternion.Identity), 4, [new DoorDef(3, 0x0100, 0, [0x0100, 0x0101])])]);

        var shell = new List<Polygon>();
        for (int i = 0; i < 40; i++)
        {
            BoxShapes.AddBox(shell, new Vector3(i % 8 * 2f, i / 8 * 2f, 0f), new Vector3(i % 8 * 2f + 1f, i / 8 * 2f + 1f, 3f));
        }

        BspTree shellBsp = BspBuilder.Build(shell.ToArray());
        (List<Vector3> sv, PolyDef[] sd) = RetailEntries.Defs(shellBsp.Polygons.ToArray());
        _entries[0x01000100] = RetailEntries.GfxObj(0x01000100, sv, sd, shellBsp, Vector3.Zero, drawing: sd);

        var room = new List<Polygon>();
        BoxShapes.AddBox(room, new Vector3(0f, 0f, -0.2f), new Vector3(6f, 6f, 0f));
        BoxShapes.AddBox(room, new Vector3(0f, 6f, 0f), new Vector3(6f, 6.2f, 3f));
        BoxShapes.AddBox(room, new Vector3(-0.2f, 0f, 0f), new Vector3(0f, 6f, 3f));
        BoxShapes.AddBox(room, new Vector3(6f, 0f, 0f), new Vector3(6.2f, 6f, 3f));
        Polygon[] portals =
        [
            BoxShapes.Quad(new(2f, 0f, 0f), new(4f, 0f, 0f), new(4f, 0f, 2.5f), new(2f, 0f, 2.5f), 0),
            BoxShapes.Quad(new(2f, 6f, 0f), new(4f, 6f, 0f), new(4f, 6f, 2.5f), new(2f, 6f, 2.5f), 1),
        ];
        BspTree roomBsp = BspBuilder.Build(room.ToArray());
        var verts = new List<Vector3>();
        (_, PolyDef[] drawing) = RetailEntries.Defs(portals, verts);
        (_, PolyDef[] phys) = RetailEntries.Defs(roomBsp.Polygons.ToArray(), verts);
        BspTree cellBsp = BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(new Vector3(0f, 0f, -0.5f), new Vector3(6f, 6f, 3f)));
        var structs = new Action<RetailDataWriter>[Cells];
        for (int i = 0; i < Cells; i++)
        {
            uint id = (uint)i;
            structs[i] = w => RetailEntries.CellStruct(w, id, verts, drawing, [0, 1], cellBsp, phys, roomBsp);
        }

        _entries[0x0D000001] = RetailEntries.Environment(0x0D000001, structs);
        for (int i = 0; i < Cells; i++)
        {
            uint id = 0x40400100u + (uint)i;
            var f = new Frame(new Vector3(100f + 7f * (i % 4), 60f + 7f * (i / 4), 0f), Quaternion.Identity);
            _entries[id] = RetailEntries.EnvCell(id, 0, 1, (ushort)i, f,
                [new PortalDef(7, 0, 0xFFFF, -1), new PortalDef(1, 1, (ushort)(0x0100 + (i + 1) % Cells), 0)], visible: [0x0100, 0x0101]);
        }

        var sw = new RetailDataWriter();
        sw.UInt32(0x02000001).UInt32(0).UInt32(2).UInt32(0x01000010).UInt32(0x01000011).UInt32(0).UInt32(0).UInt32(1)
            .UInt32(0x65).Frame(Frame.Identity).Frame(Frame.Identity).UInt32(0).UInt32(0).UInt32(2)
            .Vector3(new Vector3(0f, 0f, 0.48f)).Single(0.48f).Vector3(new Vector3(0f, 0f, 1.2f)).Single(0.48f)
            .Single(1.835f).Single(0.48f).Single(0.6f).Single(1.5f).Vector3(Vector3.Zero).Single(1f).Vector3(Vector3.Zero).Single(1f)
            .UInt32(0).UInt32(0x03000001).UInt32(0).UInt32(0x09000001).UInt32(0).UInt32(0);
        _setup = sw.ToArray();
    }

    /// <summary><c>CLandBlock::UnPack</c>: 81 terrain words and heights.</summary>
    [Benchmark]
    public RetailLandBlock LandBlock() => RetailLandBlock.Unpack(_entries[0x4040FFFF]);

    /// <summary><c>CLandBlockInfo::UnPack</c>: 8 objects, one building.</summary>
    [Benchmark]
    public RetailLandBlockInfo LandBlockInfo() => RetailLandBlockInfo.Unpack(_entries[0x4040FFFE]);

    /// <summary><c>CEnvCell::UnPack</c>: one cell (two portals, two visible cells).</summary>
    [Benchmark]
    public RetailEnvCell EnvCell() => RetailEnvCell.Unpack(_entries[0x40400100]);

    /// <summary><c>CEnvironment::UnPack</c>: 16 structures (24 physics polygons, trees, portals each).</summary>
    [Benchmark]
    public RetailEnvironment Environment() => RetailEnvironment.Unpack(_entries[0x0D000001]);

    /// <summary><c>CGfxObj::Serialize</c>: the 240-polygon shell with its physics BSP and a drawing part of the same size.</summary>
    [Benchmark]
    public RetailGfxObj GfxObj() => RetailGfxObj.Unpack(_entries[0x01000100]);

    /// <summary><c>CSetup::UnPack</c>: a two-part setup with two spheres.</summary>
    [Benchmark]
    public RetailSetup Setup2() => RetailSetup.Unpack(_setup);

    /// <summary>The whole landblock with its 16 cells and building, into a fresh world.</summary>
    [Benchmark]
    public RetailLandBlockContent WholeLandBlock() =>
        RetailLandBlockLoader.Load(new WorldCells(SyntheticTerrain.Metres()), 0x4040FFFF, new Source(_entries));
}
