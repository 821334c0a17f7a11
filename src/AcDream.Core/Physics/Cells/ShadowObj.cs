using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// An object's presence in one cell it overlaps: the cell lists it so that sweeps through that cell test the object.
/// Retail: <c>CShadowObj</c> (acclient.h, PORTAL/cphysobj/CShadowObj.c). An object owns its shadows (one per cell,
/// reused from tick to tick); a cell only points at them.
/// </summary>
internal sealed class ShadowObj
{
    /// <summary>Creates a shadow of <paramref name="physObj"/>.</summary>
    internal ShadowObj(PhysicsObj physObj)
    {
        PhysObj = physObj;
    }

    /// <summary>The object the shadow stands for. Retail: <c>physobj</c>.</summary>
    public PhysicsObj PhysObj { get; private set; }

    /// <summary>The id of the cell the shadow was made for. Retail: <c>cell_id</c>.</summary>
    public uint CellId { get; internal set; }

    /// <summary>The cell that lists the shadow, or null (cell not loaded, or removed). Retail: <c>cell</c>.</summary>
    public ObjCell? Cell { get; internal set; }

    /// <summary>The shadow's index in <see cref="Cell"/>'s list while it is listed there (the index of its
    /// <see cref="ObstacleSummary"/>; kept by the cell's add and remove).</summary>
    // non-retail: retail finds a shadow by a search of the list
    internal int Slot { get; set; }

    /// <summary>Points the shadow at <paramref name="physObj"/>.</summary>
    // retail: CShadowObj::set_physobj (acclient.c:329718)
    internal void SetPhysObj(PhysicsObj physObj) => PhysObj = physObj;
}
