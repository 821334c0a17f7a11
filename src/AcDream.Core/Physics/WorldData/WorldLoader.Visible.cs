using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.WorldData;

// Retail's visible-cell table (CEnvCell::visible_cell_table): the indoor cells the landscape holds, those named by the
// full-detail blocks' stab lists and by the player's cell. A change reads the cells it adds before anything changes, then
// releases the cells no longer named and flushes (each visible cell's static objects the first time, and the objects lost
// in it).
public sealed partial class WorldLoader
{
    private readonly List<VisibleCell> _visible = new();
    private readonly Dictionary<uint, VisibleCell> _visibleById = new();
    private readonly List<EnvCell> _visibleEnvCells = new();

    /// <summary>The visible indoor cells' <see cref="EnvCell"/>s, in the table's order (a view kept with it).</summary>
    internal IReadOnlyList<EnvCell> VisibleEnvCells => _visibleEnvCells;

    /// <summary>The visible indoor cells, in the order they were added.</summary>
    internal IReadOnlyList<VisibleCell> VisibleCells => _visible;

    /// <summary>The visible cell <paramref name="cellId"/>, or null.</summary>
    internal VisibleCell? GetVisibleCell(uint cellId) => _visibleById.TryGetValue(cellId, out VisibleCell? c) ? c : null;

    /// <summary>Reads indoor cell <paramref name="cellId"/> (its entry, its environment and its static objects' shapes) for
    /// the visible-cell table; null when the source lacks the cell or its environment (retail's <c>DBObj::Get</c> failing).
    /// Bad bytes throw; nothing changes.</summary>
    // retail: CEnvCell::add_visible_cell (acclient.c:349823), its read (DBObj::Get of the cell)
    internal VisibleCell? ReadVisibleCell(uint cellId)
    {
        if (!_source.TryGetEntry(cellId, out ReadOnlyMemory<byte> bytes))
        {
            return null;
        }

        EnvCellEntry entry = EnvCellEntry.UnPack(bytes.Span);
        Expect("CEnvCell", entry.Id, cellId, 8);
        if (!_source.TryGetEntry(entry.EnvironmentId, out ReadOnlyMemory<byte> envBytes))
        {
            return null;
        }

        EnvironmentEntry env = EnvironmentEntry.UnPack(envBytes.Span);
        Expect("CEnvironment", env.Id, entry.EnvironmentId);
        EnvCell cell = entry.ToEnvCell(env);
        foreach (StaticObjectInfo o in entry.StaticObjects)
        {
            if (o.Id != 0)
            {
                Objects.InitPartArrayModel(o.Id, out _);
            }
        }

        return new VisibleCell(cell, entry);
    }

    /// <summary>
    /// Makes <paramref name="ids"/> the visible cells: those visible now and not named are released (their moving objects to
    /// their lost cells, their static objects destroyed, the cell out of the world), and those named and not visible are
    /// added from <paramref name="read"/> (a named cell read as missing is skipped). <paramref name="released"/> and
    /// <paramref name="entered"/> receive the ids.
    /// </summary>
    // retail: CEnvCell::release_visible (acclient.c:350020) and grab_visible (acclient.c:350000) with add_visible_cell
    // (acclient.c:349823): a released cell named again is taken back without a reload; the rest go at flush_cells
    internal void SetVisibleCells(IReadOnlyList<uint> ids, Dictionary<uint, VisibleCell?> read, List<uint> released, List<uint> entered)
    {
        // The table is compacted in place (its order kept): no set or delegate is made, so a change that keeps the table
        // allocates nothing.
        int kept = 0;
        for (int i = 0; i < _visible.Count; i++)
        {
            VisibleCell c = _visible[i];
            uint id = c.Cell.CellId;
            if (Names(ids, id))
            {
                _visible[kept] = c;
                _visibleEnvCells[kept] = c.Cell;
                kept++;
                continue;
            }

            // retail: CEnvCell::flush_cells (acclient.c:349879), the released cells: release_objects, then the cell goes
            c.Cell.ReleaseObjects(_world);
            foreach (PhysicsObj o in c.Statics)
            {
                if (!o.IsRemoved)
                {
                    _world.RemoveObject(o);
                }
            }

            _cells.RemoveEnvCell(id);
            _visibleById.Remove(id);
            released.Add(id);
        }

        _visible.RemoveRange(kept, _visible.Count - kept);
        _visibleEnvCells.RemoveRange(kept, _visibleEnvCells.Count - kept);
        for (int i = 0; i < ids.Count; i++)
        {
            uint id = ids[i];
            if (_visibleById.ContainsKey(id) || !read.TryGetValue(id, out VisibleCell? c) || c is null)
            {
                continue;
            }

            _visible.Add(c);
            _visibleEnvCells.Add(c.Cell);
            _visibleById.Add(id, c);
            _cells.AddEnvCell(c.Cell, initObjects: false);
            entered.Add(id);
        }
    }

    private static bool Names(IReadOnlyList<uint> ids, uint id)
    {
        for (int i = 0; i < ids.Count; i++)
        {
            if (ids[i] == id)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Every visible cell: its static objects made the first time, then the objects lost in it brought back.</summary>
    // retail: CEnvCell::flush_cells (acclient.c:349879), the visible cells: init_static_objects, init_objects
    internal void FlushCells()
    {
        for (int i = 0; i < _visible.Count; i++)
        {
            VisibleCell c = _visible[i];
            if (!c.StaticsDone)
            {
                c.StaticsDone = true;
                InitStaticObjects(c);
            }

            c.Cell.InitObjects(_world);
        }
    }

    /// <summary>The cell's static objects, made and put in it at their stored frames.</summary>
    // retail: CEnvCell::init_static_objects (acclient.c:347954)
    private void InitStaticObjects(VisibleCell c)
    {
        foreach (StaticObjectInfo o in c.Entry.StaticObjects)
        {
            if (o.Id == 0)
            {
                continue;
            }

            ObjectModel? model = Objects.InitPartArrayModel(o.Id, out bool animObject);
            if (model is null)
            {
                c.Missing.AddRange(Objects.MissingFor(o.Id));
                continue;
            }

            PhysicsObj obj = Objects.Instantiate(_world, model, 0, isDynamic: false, animObject);
            obj.AddObjToCell(c.Cell, o.Frame, _sweep);
            c.Statics.Add(obj);
            c.Objects.Add(new WorldObject(WorldObjectKind.EnvCellStatic, o.Id, obj, null, c.Cell.CellId, obj.Position.Frame, 1f));
        }
    }

    /// <summary>Releases every visible cell.</summary>
    internal void ReleaseVisibleCells(List<uint> released) =>
        SetVisibleCells(Array.Empty<uint>(), new Dictionary<uint, VisibleCell?>(), released, released);

    /// <summary>One visible indoor cell: the cell, its entry, and its static objects once made.</summary>
    internal sealed class VisibleCell(EnvCell cell, EnvCellEntry entry)
    {
        public EnvCell Cell { get; } = cell;

        public EnvCellEntry Entry { get; } = entry;

        public List<PhysicsObj> Statics { get; } = new();

        public List<WorldObject> Objects { get; } = new();

        public List<uint> Missing { get; } = new();

        public bool StaticsDone { get; set; }
    }
}
