using System.Collections.Generic;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Scene;

namespace AcDream.Core.Physics.World;

// What happens to the world's objects when the landblocks (or indoor cells) under them change (docs/stability.md, "Landblocks changing under
// objects"). Called by TerrainWorld on the world that owns its cells; never inside a tick's hot path.
public sealed partial class PhysicsWorld
{
    /// <summary>True while the world's tick runs (its callbacks included).</summary>
    internal bool IsTicking => _inUseTime;

    /// <summary>
    /// Cells were loaded or replaced — landblock <paramref name="id"/> (<c>0xXXYY0000</c>, <paramref name="mask"/>
    /// <c>0xFFFF0000</c>) or one indoor cell (mask <c>0xFFFFFFFF</c>): every object standing in them, or with a shadow made for
    /// one of them, is listed again in the cells now loaded (positions, cells and contact state are kept). The objects are woken.
    /// </summary>
    internal void RehomeObjectsIn(uint id, uint mask)
    {
        if (_sweep is not RetailSweep sweep)
        {
            return;
        }

        VisitOrderList.Cursor cursor = _objects.Start();
        while (_objects.MoveNext(ref cursor, out PhysicsObj o))
        {
            // Children are shadowed with their parent (add_shadows_to_cells walks the child list).
            if (o.Parent is not null || o.CellId == 0 || ((o.CellId & mask) != id && !o.HasShadowIn(id, mask)))
            {
                continue;
            }

            o.Touch();
            o.RelistInCell();
            o.RehomeShadows(sweep);
        }
    }

    /// <summary>
    /// Cells were removed — landblock <paramref name="id"/> (mask <c>0xFFFF0000</c>: its outdoor cells) or one indoor cell
    /// (mask <c>0xFFFFFFFF</c>): every object standing in one of them leaves the world (retail's lost cell: cell 0, no shadows,
    /// not simulated, position kept) and is added to <paramref name="leftWorld"/>; objects elsewhere whose shadows reached into
    /// them are listed again in the cells still loaded.
    /// </summary>
    internal void SendObjectsOutOfWorld(uint id, uint mask, ICollection<PhysicsObj>? leftWorld)
    {
        RetailSweep? sweep = _sweep as RetailSweep;
        VisitOrderList.Cursor cursor = _objects.Start();
        while (_objects.MoveNext(ref cursor, out PhysicsObj o))
        {
            if (o.Parent is not null || o.CellId == 0)
            {
                continue;
            }

            // A landblock's terrain holds its outdoor cells only; its indoor cells stay loaded.
            if ((o.CellId & mask) == id && (mask == 0xFFFFFFFFu || (o.CellId & 0xFFFFu) < LandDefs.FirstEnvCell))
            {
                o.GoToLostCell(o.Position);
                leftWorld?.Add(o);
            }
            else if (sweep is not null && o.HasShadowIn(id, mask))
            {
                o.Touch();
                o.RehomeShadows(sweep);
            }
        }
    }
}
