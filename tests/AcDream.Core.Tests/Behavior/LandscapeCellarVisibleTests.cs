using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Geometry;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The real visible-cell lists of the Holtburg cellars (../shared/data/geometry: 19 cells of 0xA9B4 with their
/// <c>VisibleCellIds</c>) drive the landscape's visible-cell table (retail <c>CEnvCell::grab_visible_cells</c> 350171,
/// <c>add_visible_cell</c> 349823, <c>release_visible</c> 350020, <c>flush_cells</c> 349879): in each cell, the visible cells
/// are the cell and the cells its list names (those the source holds: only the dumped cells have entries here); a change
/// releases the cells no longer named and adds the new ones, keeping the cells in both. The cells' geometry is a stand-in
/// (the room of <see cref="RoomSceneEntries"/>, with its door as the one portal: a cell without portals contains no point, as
/// retail's <c>point_in_cell</c>); a cell whose dump has a portal to the outside (0xFFFF) is flagged as seeing outside.
/// </summary>
public class LandscapeCellarVisibleTests
{
    private sealed record Dumped(uint Id, uint[] Visible, bool SeesOutside, Vector3 Origin);

    private static List<Dumped> ReadDumps()
    {
        var cells = new List<Dumped>();
        foreach (string file in Directory.GetFiles(GeometryTestData.Dir!, "0xA9B4*.json", SearchOption.AllDirectories).OrderBy(f => f, StringComparer.Ordinal))
        {
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(file));
            JsonElement root = doc.RootElement;
            uint id = root.GetProperty("CellId").GetUInt32();
            if (cells.Any(c => c.Id == id))
            {
                continue;
            }

            uint[] visible = root.GetProperty("VisibleCellIds").EnumerateArray().Select(v => v.GetUInt32()).ToArray();
            bool outside = root.GetProperty("Portals").EnumerateArray().Any(p => p.GetProperty("OtherCellId").GetUInt32() == 0xFFFF);
            JsonElement t = root.GetProperty("WorldTransform");
            var origin = new Vector3(t.GetProperty("M41").GetSingle(), t.GetProperty("M42").GetSingle(), t.GetProperty("M43").GetSingle());
            cells.Add(new Dumped(id, visible, outside, origin));
        }

        return cells;
    }

    private static DictionarySource Source(List<Dumped> cells)
    {
        DictionarySource room = RoomSceneEntries.Source();
        var s = new DictionarySource();
        s.Entries[RoomSceneEntries.Env] = room.Entries[RoomSceneEntries.Env];
        var height = new byte[81];
        Array.Fill(height, (byte)BspScene.Ground);
        s.Entries[0xA9B4FFFFu] = RetailEntries.LandBlock(0xA9B4FFFFu, true, new ushort[81], height);
        uint numCells = cells.Max(c => c.Id & 0xFFFFu) - 0x100u + 1u;
        s.Entries[0xA9B4FFFEu] = RetailEntries.LandBlockInfo(0xA9B4FFFEu, numCells, [], []);
        foreach (Dumped c in cells)
        {
            s.Entries[c.Id] = RetailEntries.EnvCell(c.Id, c.SeesOutside ? 1u : 0u, (ushort)(RoomSceneEntries.Env & 0xFFFF), 0,
                new Frame(c.Origin, Quaternion.Identity), [new PortalDef(7, 100, 0xFFFF, -1)], c.Visible.Select(v => (ushort)(v & 0xFFFF)).ToArray());
        }

        return s;
    }

    [GeometryDataFact]
    public void EachCellsVisibleList_DrivesGrabReleaseAndFlush()
    {
        List<Dumped> cells = ReadDumps();
        Assert.Equal(22, cells.Count); // the dumps of 0xA9B4's cells in the five folders, each once
        HashSet<uint> held = cells.Select(c => c.Id).ToHashSet();
        Landscape l = LandscapeEntries.Landscape(Source(cells), out PhysicsWorld world, out WorldCells worldCells, radius: 1);
        uint[] before = Array.Empty<uint>();
        foreach (Dumped c in cells)
        {
            LandscapeChange change = l.ChangePosition(new Position(c.Id, new Frame(c.Origin, Quaternion.Identity)));
            Assert.Equal(LandscapeStatus.Updated, change.Status);
            Assert.Equal(c.Id, l.CurrentCellId);
            // The cell first, then its list in stored order, each once, keeping only what the source holds.
            var expected = new List<uint> { c.Id };
            foreach (uint v in c.Visible)
            {
                if (held.Contains(v) && !expected.Contains(v))
                {
                    expected.Add(v);
                }
            }

            uint[] now = l.VisibleCells.Select(v => v.CellId).ToArray();
            Assert.Equal(expected.OrderBy(v => v), now.OrderBy(v => v));
            Assert.Equal(expected.Count, worldCells.EnvCellCount);
            Assert.Equal(before.Except(expected).OrderBy(v => v), change.CellsReleased.OrderBy(v => v));
            Assert.Equal(expected.Except(before), change.CellsEntered);
            Assert.All(change.CellsReleased, id => Assert.Null(worldCells.GetEnvCell(id)));
            // A cell seeing outside keeps the landscape; one that does not releases it.
            Assert.Equal(c.SeesOutside, l.HasGrid);
            before = now;
        }
    }

    [GeometryDataFact]
    public void AnObjectInACellThatIsReleased_GoesToItsLostCell_AndComesBackWhenTheCellIsVisibleAgain()
    {
        List<Dumped> cells = ReadDumps();
        HashSet<uint> held = cells.Select(c => c.Id).ToHashSet();
        Landscape l = LandscapeEntries.Landscape(Source(cells), out PhysicsWorld world, out WorldCells worldCells, radius: 1);
        // Two dumped cells that do not see each other, held or named: entering b releases a.
        Dumped a = cells.First(), b = cells.First(x => x.Id != a.Id && !x.Visible.Contains(a.Id) && !a.Visible.Contains(x.Id));
        l.ChangePosition(new Position(a.Id, new Frame(a.Origin, Quaternion.Identity)));
        // A sphere object lost in cell a, at (3, 3, 0.5) in the cell's frame: inside the stand-in room (0..6, -0.2..6, 0..3).
        var o = world.CreateObject(9);
        o.PartArray = Walkers.OneSphere(0.3f);
        var at = new Position(a.Id, new Frame(a.Origin + new Vector3(3f, 3f, 0.5f), Quaternion.Identity));
        EnvCell ac = worldCells.GetEnvCell(a.Id)!;
        Assert.True(ac.PointInCell(at.Frame.Origin), $"point {at.Frame.Origin} not in cell");
        var probe = o.SetPosition(at, AcDream.Core.Physics.Objects.SetPositionFlags.Placement | AcDream.Core.Physics.Objects.SetPositionFlags.Slide);
        Assert.Equal(AcDream.Core.Physics.Objects.SetPositionError.Ok, probe);
        Assert.Equal(a.Id, o.CellId);
        o.GoToLostCell(at);
        Assert.Equal(1, world.LostObjectCount);
        l.ChangePosition(new Position(b.Id, new Frame(b.Origin, Quaternion.Identity)));
        Assert.Null(worldCells.GetEnvCell(a.Id));
        Assert.Equal(0u, o.CellId);
        Assert.Equal(1, world.LostObjectCount);
        // Cell a visible again: flush_cells -> init_objects -> InitObjCell places the object again where it was.
        LandscapeChange back = l.ChangePosition(new Position(a.Id, new Frame(a.Origin, Quaternion.Identity)));
        Assert.Contains(a.Id, back.CellsEntered);
        Assert.Equal(a.Id, o.CellId);
        Assert.Equal(0, world.LostObjectCount);
        Assert.Contains(b.Id, held);
    }
}
