using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Managers;

// Global detection: a cylinder with object id 0. The detector is a voyeur of every loaded cell its radius reaches; the cells
// send it EnteredDetection / LeftDetection as objects come and go (ObjCell.Objects.cs), and each check reports them.
public sealed partial class DetectionManager
{
    /// <summary>Distance the detector moves before its cell list is found again, metres: 5.0 (<c>UpdateCellList</c>).</summary>
    internal const double CellListUpdateDistance = 5.0;

    // Retail CELLARRAY *cell_array: the cells the detector watches (null until InitializeGlobalDetection). Two arrays are
    // kept and swapped, so an update allocates nothing (retail builds a new one each time and copies its ids).
    private CellArray? _cellArray;
    private CellArray? _newCellArray;

    // Retail Position last_global_update: where the cell list was last found (cell 0 until the first update).
    private Position _lastGlobalUpdate;

    /// <summary>The cells global detection watches, in the order found; empty without global detection.</summary>
    internal IReadOnlyList<uint> GlobalDetectionCellIds
    {
        get
        {
            var ids = new List<uint>();
            if (_cellArray is not null)
            {
                foreach (CellInfo c in _cellArray.Cells)
                {
                    ids.Add(c.CellId);
                }
            }

            return ids;
        }
    }

    /// <summary>The loaded cells a sphere of the cylinder's radius around the detector reaches (cells not loaded are not
    /// asked for).</summary>
    // retail: DetectionManager::FindCellList (acclient.c:327153)
    private void FindCellList(DetectionCylsphere detcyl, CellArray newCellArray)
    {
        newCellArray.Clear();
        newCellArray.DoNotLoadCells = true;
        if (PhysicsObj.World.Sweep is not RetailSweep sweep)
        {
            return;
        }

        // retail: CObjCell::find_cell_list (acclient.c:347321): the sphere's centre (0, 0, 0) made global from the position
        Position p = PhysicsObj.Position;
        System.Span<Sphere> sphere = stackalloc Sphere[1];
        sphere[0] = new Sphere(p.LocalToGlobal(p, System.Numerics.Vector3.Zero), detcyl.Radius);
        CellList.FindCellList(sweep.Cells, p, sphere, newCellArray, false, null);
    }

    /// <summary>Starts global detection: the detection objects' table, and the detector as a voyeur of every cell of its cell
    /// list. False when it was started already.</summary>
    // retail: DetectionManager::InitializeGlobalDetection (acclient.c:327193)
    private bool InitializeGlobalDetection(DetectionCylsphere detcyl)
    {
        if (_detectionObjects is not null || _cellArray is not null)
        {
            return false;
        }

        _detectionObjects = new Dictionary<uint, DetectionEntry>(32);
        _cellArray = new CellArray();
        FindCellList(detcyl, _cellArray);
        for (int i = 0; i < _cellArray.NumCells; i++)
        {
            _cellArray.CellAt(i)?.AddVoyeur(PhysicsObj);
        }

        return true;
    }

    /// <summary>Once the detector moved <see cref="CellListUpdateDistance"/> or more since the last update: it becomes a
    /// voyeur of the new cell list, then stops watching the old one (so a cell in both keeps it, with no report).</summary>
    // retail: DetectionManager::UpdateCellList (acclient.c:327327)
    private void UpdateCellList(DetectionCylsphere detcyl)
    {
        if (_cellArray is null)
        {
            InitializeGlobalDetection(detcyl);
            if (_cellArray is null)
            {
                return;
            }
        }

        Position here = PhysicsObj.Position;
        if (_lastGlobalUpdate.DistanceInDouble(here) >= CellListUpdateDistance)
        {
            _lastGlobalUpdate = here;
            CellArray newCells = _newCellArray ??= new CellArray();
            FindCellList(detcyl, newCells);
            for (int i = 0; i < newCells.NumCells; i++)
            {
                newCells.CellAt(i)?.AddVoyeur(PhysicsObj);
            }

            RemoveVoyeurFromCells(_cellArray);
            // retail: the old array emptied and refilled with the new ids; here the two arrays swap.
            _newCellArray = _cellArray;
            _newCellArray.Clear();
            _cellArray = newCells;
        }
    }

    /// <summary>Ends global detection: the detection objects are dropped and the detector stops watching its cells.</summary>
    // retail: DetectionManager::CleanupGlobalDetection (acclient.c:327456)
    private void CleanupGlobalDetection()
    {
        if (_detectionObjects is not null)
        {
            DestroyContents(_detectionObjects);
            _detectionObjects = null;
            _numPendingGlobalDetectUpdates = 0;
        }

        if (_cellArray is not null)
        {
            RemoveVoyeurFromCells(_cellArray);
            _cellArray = null;
        }
    }

    // The remove_voyeur loops of UpdateCellList and CleanupGlobalDetection: each cell looked up again by id (it may have
    // been unloaded since).
    private void RemoveVoyeurFromCells(CellArray cells)
    {
        if (PhysicsObj.World.Sweep is not RetailSweep sweep)
        {
            return;
        }

        for (int i = 0; i < cells.NumCells; i++)
        {
            sweep.Cells.GetVisible(cells.Cells[i].CellId)?.RemoveVoyeur(PhysicsObj);
        }
    }

    /// <summary>The detection objects' table of global detection alone (the hash part of
    /// <see cref="InitializeGlobalDetection"/>, no cells). For tests of the report state machine.</summary>
    internal bool InitializeGlobalDetectionObjects()
    {
        if (_detectionObjects is not null)
        {
            return false;
        }

        _detectionObjects = new Dictionary<uint, DetectionEntry>(32);
        return true;
    }
}
