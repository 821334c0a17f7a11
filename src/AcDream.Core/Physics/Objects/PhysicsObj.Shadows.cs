using System;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;

namespace AcDream.Core.Physics.Objects;

/// <summary>The object's shadows: its entries in the shadow lists of every cell it overlaps.</summary>
public sealed partial class PhysicsObj
{
    private ShadowObj[] _shadowObjects = Array.Empty<ShadowObj>();

    /// <summary>Shadows made on the first placement: enough for one sphere on a cell corner (4 cells), so that walking
    /// around allocates nothing; more are made only for objects overlapping more cells.</summary>
    public const int InitialShadowCapacity = 4;

    /// <summary>Number of shadows in use. Retail: <c>num_shadow_objects</c>.</summary>
    public int NumShadowObjects { get; private set; }

    /// <summary>The shadows in use, one per overlapped cell (a shadow's <see cref="ShadowObj.Cell"/> is null when that
    /// cell is not loaded). Retail: <c>shadow_objects</c>.</summary>
    public ReadOnlySpan<ShadowObj> ShadowObjects => _shadowObjects.AsSpan(0, NumShadowObjects);

    /// <summary>
    /// Puts a shadow of the object (and of its attached children) in every cell of <paramref name="cellArray"/>; a particle
    /// emitter gets one shadow, in <paramref name="ownCell"/>. Shadows are reused: the object's shadow array grows only past
    /// its largest cell count so far. Call <see cref="RemoveShadowsFromCells"/> first.
    /// </summary>
    /// <param name="cellArray">The cells the object overlaps (a sweep's cell array).</param>
    /// <param name="ownCell">The object's own cell (used for particle emitters only).</param>
    // retail: CPhysicsObj::add_shadows_to_cells (acclient.c:321977)
    public void AddShadowsToCells(CellArray cellArray, ObjCell? ownCell)
    {
        ArgumentNullException.ThrowIfNull(cellArray);
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

            for (int i = 0; i < n; i++)
            {
                ObjCell? cell = cells[i].Cell;
                if (cell is not null)
                {
                    // Retail also hands the parts to the cell for drawing (CPartArray::AddPartsShadow): renderer only.
                    cell.AddShadowObject(_shadowObjects[i]);
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
    public void RemoveShadowsFromCells()
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
}
