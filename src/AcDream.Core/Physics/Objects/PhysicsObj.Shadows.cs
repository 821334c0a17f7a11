// PhysicsObj — shadows: add_shadows_to_cells, remove_shadows_from_cells, add_particle_shadow_to_cell, calc_cross_cells.
using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Core.Physics.Objects;

// The object's shadows: its entries in the shadow lists of every cell it overlaps.
public sealed partial class PhysicsObj
{
    private ShadowObj[] _shadowObjects = Array.Empty<ShadowObj>();

    /// <summary>Shadows made on the first placement: enough for one sphere on a cell corner (4 cells), so that walking
    /// around allocates nothing; more are made only for objects overlapping more cells.</summary>
    internal const int InitialShadowCapacity = 4;

    /// <summary>Number of shadows in use. Retail: <c>num_shadow_objects</c>.</summary>
    internal int NumShadowObjects { get; private set; }

    /// <summary>The shadows in use, one per overlapped cell (a shadow's <see cref="ShadowObj.Cell"/> is null when that
    /// cell is not loaded). Retail: <c>shadow_objects</c>.</summary>
    internal ReadOnlySpan<ShadowObj> ShadowObjects => _shadowObjects.AsSpan(0, NumShadowObjects);

    /// <summary>
    /// Puts a shadow of the object (and of its attached children) in every cell of <paramref name="cellArray"/>; a particle
    /// emitter gets one shadow, in <paramref name="ownCell"/>. Shadows are reused: the object's shadow array grows only past
    /// its largest cell count so far. Call <see cref="RemoveShadowsFromCells"/> first.
    /// </summary>
    /// <param name="cellArray">The cells the object overlaps (a sweep's cell array).</param>
    /// <param name="ownCell">The object's own cell (used for particle emitters only).</param>
    // retail: CPhysicsObj::add_shadows_to_cells (acclient.c:321977)
    internal void AddShadowsToCells(CellArray cellArray, ObjCell? ownCell)
    {
        ArgumentNullException.ThrowIfNull(cellArray);
        // non-retail: an object removed from its world (or hanging from one) never lists itself in a cell again
        if (RemovedFromWorld)
        {
            return;
        }

        if ((_state & PhysicsState.ParticleEmitter) != 0)
        {
            AddParticleShadowToCell(ownCell);
        }
        else
        {
            int n = cellArray.NumCells;
            EnsureShadowCapacity(n);
            NumShadowObjects = n;
            ReadOnlySpan<CellInfo> cells = cellArray.Cells;
            for (int i = 0; i < n; i++)
            {
                ShadowObj s = _shadowObjects[i];
                s.SetPhysObj(this);
                s.CellId = cells[i].CellId;
            }

            ObstacleSummary summary = ComputeObstacleSummary();
            for (int i = 0; i < n; i++)
            {
                ObjCell? cell = cells[i].Cell;
                if (cell is not null)
                {
                    // Retail also hands the parts to the cell for drawing (CPartArray::AddPartsShadow): renderer only.
                    cell.AddShadowObject(_shadowObjects[i], summary);
                }
                else
                {
                    _shadowObjects[i].Cell = null;
                }
            }
        }

        ChildList? children = Children;
        if (children is not null)
        {
            for (int i = 0; i < children.Count; i++)
            {
                children.GetObject(i).AddShadowsToCells(cellArray, ownCell);
            }
        }
    }

    /// <summary>Takes every shadow of the object (and of its attached children) out of its cell.</summary>
    // retail: CPhysicsObj::remove_shadows_from_cells (acclient.c:318417)
    internal void RemoveShadowsFromCells()
    {
        for (int i = 0; i < NumShadowObjects; i++)
        {
            ShadowObj s = _shadowObjects[i];
            s.Cell?.RemoveShadowObject(s);
        }

        NumShadowObjects = 0;
        ChildList? children = Children;
        if (children is not null)
        {
            for (int i = 0; i < children.Count; i++)
            {
                children.GetObject(i).RemoveShadowsFromCells();
            }
        }
    }

    // retail: CPhysicsObj::add_particle_shadow_to_cell (acclient.c:321957)
    private void AddParticleShadowToCell(ObjCell? cell)
    {
        EnsureShadowCapacity(1);
        NumShadowObjects = 1;
        ShadowObj s = _shadowObjects[0];
        s.SetPhysObj(this);
        s.CellId = CellId;
        if (cell is not null)
        {
            cell.AddShadowObject(s);
        }
        else
        {
            s.Cell = null;
        }
    }

    private void EnsureShadowCapacity(int n)
    {
        if (n <= _shadowObjects.Length)
        {
            return;
        }

        if (n < InitialShadowCapacity)
        {
            n = InitialShadowCapacity;
        }

        int old = _shadowObjects.Length;
        Array.Resize(ref _shadowObjects, n);
        for (int i = old; i < n; i++)
        {
            _shadowObjects[i] = new ShadowObj(this);
        }
    }

    /// <summary>
    /// Updates the object's shadows after committing <paramref name="transit"/> of <paramref name="sweep"/>'s pool: an object
    /// with a physics BSP is re-shadowed where it stands (<see cref="CalcCrossCells"/>), any other in the transition's cells.
    /// </summary>
    /// <remarks>An object with a physics BSP is shadowed in its own cell and the cells of its sorting sphere (retail: its
    /// parts' bounding boxes).</remarks>
    // retail: CPhysicsObj::SetPositionInternal(CTransition*) (acclient.c:322503), the shadow update at its end
    internal void UpdateCellShadows(RetailSweep sweep, Transition transit)
    {
        if ((State & PhysicsState.HasPhysicsBsp) != 0)
        {
            CalcCrossCells(sweep);
        }
        else if (transit.CellArray.NumCells != 0)
        {
            RemoveShadowsFromCells();
            AddShadowsToCells(transit.CellArray, sweep.Cells.GetVisible(CellId));
        }
    }

    /// <summary>True when the object is in a cell and has shadows, each in a loaded cell (none was made for a cell that was
    /// not loaded).</summary>
    // retail: CPhysicsObj::is_completely_visible (acclient.c:318473)
    internal bool IsCompletelyVisible
    {
        get
        {
            if (_cell is null || NumShadowObjects == 0)
            {
                return false;
            }

            ReadOnlySpan<ShadowObj> shadows = ShadowObjects;
            for (int i = 0; i < shadows.Length; i++)
            {
                if (shadows[i].Cell is null)
                {
                    return false;
                }
            }

            return true;
        }
    }

    /// <summary>True when one of the object's shadows was made for a cell whose id, masked by <paramref name="mask"/>, is
    /// <paramref name="id"/> (a landblock: mask <c>0xFFFF0000</c>; one cell: mask <c>0xFFFFFFFF</c>), loaded or not.</summary>
    internal bool HasShadowIn(uint id, uint mask)
    {
        ReadOnlySpan<ShadowObj> shadows = ShadowObjects;
        for (int i = 0; i < shadows.Length; i++)
        {
            if ((shadows[i].CellId & mask) == id)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>
    /// Lists the object's shadows again in the cells <paramref name="sweep"/> holds now (after a landblock was loaded, replaced
    /// or removed): an object with a physics BSP or cylinder spheres as <see cref="CalcCrossCells"/> does; any other in the
    /// cells its collision spheres (the sphere a sweep would use) overlap where it stands, as a placement lists them.
    /// </summary>
    // non-retail: retail never swaps the cells under an object (LScape loads blocks around the viewer before objects arrive)
    internal void RehomeShadows(RetailSweep sweep)
    {
        if ((_state & PhysicsState.Static) != 0 && HasPartBoxes)
        {
            // retail: CLandBlock::init_static_objs (acclient.c:352786) re-lists a loaded block's statics this way
            CalcCrossCellsStatic(sweep);
            return;
        }

        IPartArray? parts = PartArray;
        bool hasCyl = parts is IPartCollision pc && pc.CylSpheres.Length != 0;
        if ((State & PhysicsState.HasPhysicsBsp) != 0 || hasCyl)
        {
            CalcCrossCells(sweep);
            return;
        }

        CellArray ca = sweep.CrossCells;
        ca.Clear();
        Position p = Position;
        Span<Sphere> spheres = stackalloc Sphere[2];
        int n;
        if (parts is not null && parts.NumSpheres != 0)
        {
            ReadOnlySpan<Sphere> own = parts.Spheres;
            n = own.Length <= 2 ? own.Length : 2;
            float s = Scale;
            for (int i = 0; i < n; i++)
            {
                Vector3 c = own[i].Center;
                spheres[i] = new Sphere(p.LocalToGlobal(p, new Vector3(s * c.X, s * c.Y, s * c.Z)), s * own[i].Radius);
            }
        }
        else
        {
            Sphere d = Sphere.Dummy;
            spheres[0] = new Sphere(p.LocalToGlobal(p, d.Center), d.Radius);
            n = 1;
        }

        CellList.FindCellList(sweep.Cells, p, spheres[..n], ca, false, null);
        RemoveShadowsFromCells();
        AddShadowsToCells(ca, sweep.Cells.GetVisible(CellId));
    }

    /// <summary>
    /// Re-shadows the object where it stands: in the cells its cylinder spheres overlap, or, without them (or with a
    /// physics BSP), the cells of its sorting sphere (plus its own cell for a BSP object). Uses <paramref name="sweep"/>'s
    /// cells and its scratch cell array.
    /// </summary>
    // retail: CPhysicsObj::calc_cross_cells (acclient.c:322446)
    internal void CalcCrossCells(RetailSweep sweep)
    {
        CellArray ca = sweep.CrossCells;
        ca.Clear();
        if ((State & PhysicsState.HasPhysicsBsp) != 0 && HasPartBoxes)
        {
            // An object made from its data id has its parts' boxes: retail's part-based cell list.
            FindBboxCellList(sweep, ca);
            RemoveShadowsFromCells();
            AddShadowsToCells(ca, sweep.Cells.GetVisible(CellId));
            return;
        }

        Position p = Position;
        IPartCollision? parts = PartArray as IPartCollision;
        ReadOnlySpan<CylSphere> cyl = parts is null ? default : parts.CylSpheres;
        Span<Sphere> spheres = stackalloc Sphere[10];
        int n = 0;
        if ((State & PhysicsState.HasPhysicsBsp) == 0 && cyl.Length != 0)
        {
            n = cyl.Length <= 10 ? cyl.Length : 10;
            for (int i = 0; i < n; i++)
            {
                spheres[i] = new Sphere(p.LocalToGlobal(p, cyl[i].LowPt), cyl[i].Radius);
            }
        }
        else
        {
            // Retail: an object with a physics BSP is listed by its parts' bounding boxes (find_bbox_cell_list,
            // acclient.c:318275, above, for an object made from its data id); an object whose parts a client gave
            // (SetPhysicsParts) has no boxes: the sorting sphere stands in (divergences.md).
            Sphere sorting = parts is null ? Sphere.Dummy : parts.SortingSphere;
            spheres[0] = new Sphere(p.LocalToGlobal(p, sorting.Center), sorting.Radius);
            n = 1;
        }

        CellList.FindCellList(sweep.Cells, p, spheres[..n], ca, false, null);
        if ((State & PhysicsState.HasPhysicsBsp) != 0)
        {
            ca.AddCell(CellId, sweep.Cells.GetVisible(CellId));
        }

        RemoveShadowsFromCells();
        AddShadowsToCells(ca, sweep.Cells.GetVisible(CellId));
    }
}
