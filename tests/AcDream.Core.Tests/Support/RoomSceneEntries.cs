using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Tests.Support;

/// <summary>A data source over a dictionary of entries (the tests' stand-in for a client's data files).</summary>
internal sealed class DictionarySource : IRetailDataSource
{
    public Dictionary<uint, byte[]> Entries { get; } = new();

    public int Reads { get; private set; }

    public bool TryGetEntry(uint id, out ReadOnlyMemory<byte> bytes)
    {
        Reads++;
        if (Entries.TryGetValue(id, out byte[]? b))
        {
            bytes = b;
            return true;
        }

        bytes = default;
        return false;
    }
}

/// <summary>
/// <see cref="RoomScene"/> (a one-room building with a corridor on flat ground at 20 m, landblock 0x8080) as the retail entries
/// a client's data files would hold: the landblock 0x8080FFFF (all heights index 20 of the metre table), its info 0x8080FFFE
/// (two cells, the building 0x01000100 at the scene's origin with its door into the room), the shell GfxObj 0x01000100,
/// the environment 0x0D000001 (the room's and the corridor's structures) and the cells 0x80800100 and 0x80800101 — the
/// same polygons, portals, sides and cell regions as <see cref="RoomScene.Build"/>.
/// </summary>
internal static class RoomSceneEntries
{
    public const uint Block = 0x8080FFFF, Info = 0x8080FFFE, Shell = 0x01000100, Env = 0x0D000001;

    public static DictionarySource Source()
    {
        var s = new DictionarySource();
        var terrain = new ushort[81];
        var height = new byte[81];
        Array.Fill(height, (byte)BspScene.Ground);
        s.Entries[Block] = RetailEntries.LandBlock(Block, true, terrain, height);
        // The door: exact match, portal side 0 (flag 2) into the room's portal 0.
        s.Entries[Info] = RetailEntries.LandBlockInfo(Info, 2, [],
            [new BuildingDef(Shell, RoomScene.FrameFor(0f), 1, [new DoorDef(3, 0x0100, 0, [0x0100, 0x0101])])]);

        var shell = new List<Polygon>();
        BspScene.AddBox(shell, new(-0.2f, -0.2f, 0f), new(2f, 0f, 3f));
        BspScene.AddBox(shell, new(4f, -0.2f, 0f), new(6.2f, 0f, 3f));
        BspScene.AddBox(shell, new(2f, -0.2f, 2.5f), new(4f, 0f, 3f));
        BspScene.AddBox(shell, new(-0.2f, 6f, 0f), new(2f, 6.2f, 3f));
        BspScene.AddBox(shell, new(4f, 6f, 0f), new(6.2f, 6.2f, 3f));
        BspScene.AddBox(shell, new(-0.2f, 0f, 0f), new(0f, 6f, 3f));
        BspScene.AddBox(shell, new(6f, 0f, 0f), new(6.2f, 6f, 3f));
        BspScene.AddBox(shell, new(1.8f, 6.2f, 0f), new(2f, 12.2f, 3f));
        BspScene.AddBox(shell, new(4f, 6.2f, 0f), new(4.2f, 12.2f, 3f));
        BspScene.AddBox(shell, new(1.8f, 12f, 0f), new(4.2f, 12.2f, 3f));
        BspTree shellBsp = BspBuilder.Build(shell.ToArray());
        (List<Vector3> sv, PolyDef[] sd) = RetailEntries.Defs(shellBsp.Polygons.ToArray());
        s.Entries[Shell] = RetailEntries.GfxObj(Shell, sv, sd, shellBsp, new Vector3(3f, 6f, 1.5f));

        var room = new List<Polygon>
        {
            BspScene.Quad(new(0f, -0.2f, 0f), new(6f, -0.2f, 0f), new(6f, 6f, 0f), new(0f, 6f, 0f)),
            BspScene.Quad(new(0f, 6f, 0f), new(2f, 6f, 0f), new(2f, 6f, 3f), new(0f, 6f, 3f)),
            BspScene.Quad(new(4f, 6f, 0f), new(6f, 6f, 0f), new(6f, 6f, 3f), new(4f, 6f, 3f)),
            BspScene.Quad(new(0f, 0f, 0f), new(0f, 0f, 3f), new(2f, 0f, 3f), new(2f, 0f, 0f)),
            BspScene.Quad(new(4f, 0f, 0f), new(4f, 0f, 3f), new(6f, 0f, 3f), new(6f, 0f, 0f)),
            BspScene.Quad(new(0f, 0f, 0f), new(0f, 6f, 0f), new(0f, 6f, 3f), new(0f, 0f, 3f)),
            BspScene.Quad(new(6f, 0f, 0f), new(6f, 0f, 3f), new(6f, 6f, 3f), new(6f, 6f, 0f)),
        };
        Polygon door = BspScene.Quad(new(2f, -0.2f, 0f), new(4f, -0.2f, 0f), new(4f, -0.2f, 2.5f), new(2f, -0.2f, 2.5f), 100);
        Polygon roomToCorridor = BspScene.Quad(new(2f, 6f, 0f), new(4f, 6f, 0f), new(4f, 6f, 3f), new(2f, 6f, 3f), 101);
        var corr = new List<Polygon>
        {
            BspScene.Quad(new(2f, 6f, 0f), new(4f, 6f, 0f), new(4f, 12f, 0f), new(2f, 12f, 0f)),
            BspScene.Quad(new(2f, 6f, 0f), new(2f, 12f, 0f), new(2f, 12f, 3f), new(2f, 6f, 3f)),
            BspScene.Quad(new(4f, 6f, 0f), new(4f, 6f, 3f), new(4f, 12f, 3f), new(4f, 12f, 0f)),
            BspScene.Quad(new(2f, 12f, 0f), new(4f, 12f, 0f), new(4f, 12f, 3f), new(2f, 12f, 3f)),
        };
        Polygon corridorToRoom = BspScene.Quad(new(2f, 6f, 0f), new(4f, 6f, 0f), new(4f, 6f, 3f), new(2f, 6f, 3f), 200);

        s.Entries[Env] = RetailEntries.Environment(Env,
            w => Struct(w, 0, room, [door, roomToCorridor], BspBuilder.BoxCellPlanes(new(0f, -0.2f, -0.5f), new(6f, 6f, 3f))),
            w => Struct(w, 1, corr, [corridorToRoom], BspBuilder.BoxCellPlanes(new(2f, 6f, -0.5f), new(4f, 12f, 3f))));
        // Room: the door to the outdoors (exact, side 0, outside: 7; no other portal: -1), the opening to the corridor (exact,
        // side 1; the corridor's portal 0). Corridor: back to the room (exact, side 0; the room's portal 1).
        s.Entries[RoomScene.Room] = RetailEntries.EnvCell(RoomScene.Room, 1, 1, 0, RoomScene.FrameFor(0f),
            [new PortalDef(7, 100, 0xFFFF, -1), new PortalDef(1, 101, 0x0101, 0)], visible: [0x0101]);
        s.Entries[RoomScene.Corridor] = RetailEntries.EnvCell(RoomScene.Corridor, 0, 1, 1, RoomScene.FrameFor(0f),
            [new PortalDef(3, 200, 0x0100, 1)], visible: [0x0100]);
        return s;
    }

    private static void Struct(RetailDataWriter w, uint id, List<Polygon> physics, Polygon[] portals, CollisionPlane[] cellPlanes)
    {
        var verts = new List<Vector3>();
        (_, PolyDef[] drawing) = RetailEntries.Defs(portals, verts);
        BspTree physicsBsp = BspBuilder.Build(physics.ToArray());
        (_, PolyDef[] phys) = RetailEntries.Defs(physicsBsp.Polygons.ToArray(), verts);
        var list = new ushort[portals.Length];
        for (int i = 0; i < list.Length; i++)
        {
            list[i] = (ushort)i;
        }

        RetailEntries.CellStruct(w, id, verts, drawing, list, BspBuilder.BuildCell(cellPlanes), phys, physicsBsp);
    }
}
