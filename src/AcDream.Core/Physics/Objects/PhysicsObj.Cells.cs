// PhysicsObj — cells, parent and children: set_parent, unset_parent, UpdateChild, change_cell, enter_cell, leave_cell.
using System;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
    /// <summary>The object this one is attached to (retail <c>parent</c>), or null. A parented object is not simulated.</summary>
    /// <remarks>Kept with the object's other rarely used members (most objects have no parent).</remarks>
    public PhysicsObj? Parent
    {
        get => _rare?.Parent;
        private set
        {
            if (value is not null || _rare is not null)
            {
                Rare(true)!.Parent = value;
            }

            SyncObstacleSummary();
        }
    }

    /// <summary>Objects attached to this one (retail <c>children</c>), or null when none was ever attached.</summary>
    public ChildList? Children
    {
        get => _rare?.Children;
        private set
        {
            if (value is not null || _rare is not null)
            {
                Rare(true)!.Children = value;
            }
        }
    }

    /// <summary>
    /// Attaches this object to <paramref name="parent"/> at <paramref name="frame"/> relative to part
    /// <paramref name="partIndex"/> (the parent's own frame when the part does not exist). The child leaves the world
    /// simulation: update_object skips parented objects.
    /// </summary>
    /// <param name="parent">The parent: an object of the same world, not this one.</param>
    /// <param name="partIndex">The parent's part (any value; a missing part means the parent's own frame).</param>
    /// <param name="frame">The offset from the parent: a unit quaternion and each origin component within
    /// ±<see cref="InputLimits.MaxChildOffset"/> (192 m).</param>
    /// <returns>True when attached; false when <paramref name="parent"/> already holds this object as a child.</returns>
    /// <exception cref="ArgumentException">The parent is this object or one of its descendants (a cycle), belongs to another
    /// world or was removed from it, or the frame is outside that domain (each cause named in the message; the frame's with parameter name
    /// <c>frame</c>); nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_parent (acclient.c:323002), simplified: no shadow cells
    public bool SetParent(PhysicsObj parent, uint partIndex, in Frame frame)
    {
        ThrowIfRemoved();
        ArgumentNullException.ThrowIfNull(parent);
        // non-retail: the child frame's domain (InputLimits.MaxChildOffset, unit quaternion)
        if (parent == this)
        {
            throw new ArgumentException("An object cannot be its own parent.", nameof(parent));
        }

        if (parent.World != World)
        {
            throw new ArgumentException("The parent belongs to another world.", nameof(parent));
        }

        if (parent.RemovedFromWorld)
        {
            throw new ArgumentException("The parent was removed from its world.", nameof(parent));
        }

        if (!InputLimits.IsChildFrameInDomain(frame))
        {
            throw new ArgumentException(
                "The child frame must have a unit quaternion (|q|² within 5 × EPSILON of 1) and each origin component within ±192 m (InputLimits.MaxChildOffset).",
                nameof(frame));
        }

        // non-retail: retail accepts a parent that is a descendant; the child lists would then recurse without end
        if (IsSelfOrAncestorOf(parent))
        {
            throw new ArgumentException("The parent is this object or one of its descendants (a parent cycle).", nameof(parent));
        }

        Touch();
        parent.Touch();
        parent.Children ??= new ChildList();
        if (parent.Children.IndexOf(this) >= 0)
        {
            return false;
        }

        parent.Children.Add(this, partIndex, frame);
        UnsetParent();
        LeaveCell();
        _transientState &= ~TransientState.Active;
        Parent = parent;
        if (parent.CellId != 0)
        {
            ChangeCell(parent.CellId);
            parent.UpdateChild(this, partIndex, frame);
        }

        return true;
    }

    /// <summary>True when <paramref name="obj"/> is this object or hangs (through any number of parents) from it.</summary>
    private bool IsSelfOrAncestorOf(PhysicsObj obj)
    {
        // The parent chain is acyclic (every SetParent checks this), so the walk ends at a root.
        for (PhysicsObj? o = obj; o is not null; o = o.Parent)
        {
            if (o == this)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Detaches this object from its parent; its clock restarts and its transient state is cleared.</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::unset_parent (acclient.c:320479), simplified
    public void UnsetParent()
    {
        ThrowIfRemoved();
        Touch();
        PhysicsObj? parent = Parent;
        if (parent is null)
        {
            return;
        }

        parent.Touch();
        parent.Children?.Remove(this);
        Parent = null;
        UpdateTime = World.CurrentTime;
        ClearTransientStates();
    }

    // retail: CPhysicsObj::UpdateChildrenInternal (acclient.c:321121)
    private void UpdateChildrenInternal()
    {
        ChildList? children = Children;
        if (PartArray is null || children is null)
        {
            return;
        }

        for (int i = 0; i < children.Count; i++)
        {
            UpdateChild(children.GetObject(i), children.GetPartNumber(i), children.GetFrame(i));
        }
    }

    // retail: CPhysicsObj::UpdateChild (acclient.c:320038)
    private void UpdateChild(PhysicsObj child, uint partIndex, in Frame childFrame)
    {
        IPartArray? parts = PartArray;
        Frame basis = parts is not null && partIndex < (uint)parts.NumParts ? parts.GetPartFrame((int)partIndex) : _position.Frame;
        Frame f = basis;
        f.Combine(basis, childFrame);
        child.SetFrameInternal(f);
        child.ParticleManager?.UpdateParticles();
        child.ScriptManager?.UpdateScripts();
    }

    // retail: CPhysicsObj::change_cell (acclient.c:320421)
    private void ChangeCell(uint newCellId)
    {
        if (CellId != 0)
        {
            LeaveCell();
        }

        if (newCellId != 0)
        {
            EnterCell(newCellId);
        }
        else
        {
            _position.ObjCellId = 0;
            SyncObstacleSummary();
            if ((_state & PhysicsState.ParticleEmitter) == 0)
            {
                PartArray?.SetCellId(0);
            }

            CellId = 0;
        }
    }

    // The cell the object is listed in (retail cell): set by enter_cell, cleared by leave_cell; null when the cell is not
    // loaded (or the world has no cells).
    private ObjCell? _cell;

    /// <summary>The cell whose object list holds this object (retail <c>cell</c>), or null.</summary>
    internal ObjCell? Cell => _cell;

    // retail: CPhysicsObj::enter_cell (acclient.c:318201): nothing happens for an object without a part array. The port
    // passes the cell id; the cell (for its object list) is the world's loaded cell of that id.
    private void EnterCell(uint cellId)
    {
        if (PartArray is null)
        {
            return;
        }

        ObjCell? newCell = World.Sweep is RetailSweep sweep ? sweep.Cells.GetVisible(cellId) : null;
        newCell?.AddObject(this);
        ChildList? children = Children;
        if (children is not null)
        {
            for (int i = 0; i < children.Count; i++)
            {
                children.GetObject(i).EnterCell(cellId);
            }
        }

        _position.ObjCellId = cellId;
        SyncObstacleSummary();
        if ((_state & PhysicsState.ParticleEmitter) == 0)
        {
            PartArray.SetCellId(cellId);
        }

        CellId = cellId;
        _cell = newCell;
    }

    // retail: CPhysicsObj::leave_cell (acclient.c:318243)
    private void LeaveCell()
    {
        if (CellId == 0)
        {
            return;
        }

        _cell?.RemoveObject(this);
        ChildList? children = Children;
        if (children is not null)
        {
            for (int i = 0; i < children.Count; i++)
            {
                children.GetObject(i).LeaveCell();
            }
        }

        _cell = null;
        CellId = 0;
    }

    /// <summary>The object's cell was loaded again (a new cell of the same id): it leaves the old cell's object list and
    /// enters the new one's, its position and cell id unchanged (retail: release_objects sends it to the lost cell,
    /// init_objects brings it back).</summary>
    internal void RelistInCell()
    {
        uint cellId = CellId;
        if (cellId == 0 || Parent is not null)
        {
            return;
        }

        ObjCell? now = World.Sweep is RetailSweep sweep ? sweep.Cells.GetVisible(cellId) : null;
        if (now == _cell)
        {
            return;
        }

        LeaveCell();
        EnterCell(cellId);
    }

    /// <summary>The object leaves the world for good: it leaves its cell's object list (its voyeurs told it left).</summary>
    internal void LeaveCellOnRemove()
    {
        _cell?.RemoveObject(this);
        _cell = null;
    }

    private void SetChildrenCellId(uint id)
    {
        ChildList? children = Children;
        if (children is null)
        {
            return;
        }

        for (int i = 0; i < children.Count; i++)
        {
            PhysicsObj c = children.GetObject(i);
            c._position.ObjCellId = id;
            c.SyncObstacleSummary();
            if ((c._state & PhysicsState.ParticleEmitter) == 0)
            {
                c.PartArray?.SetCellId(id);
            }
        }
    }
}
