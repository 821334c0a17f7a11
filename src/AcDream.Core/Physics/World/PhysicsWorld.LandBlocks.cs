using System.Collections.Generic;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Math;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.World;

// What happens to the world's objects when the landblocks under them change (docs/stability.md, "Landblocks changing under
// objects"). Called by TerrainWorld on the world that owns its cells; never inside a tick's hot path.
public sealed partial class PhysicsWorld
{
    /// <summary>True while the world's tick runs (its callbacks included).</summary>
    internal bool IsTicking => _inUseTime;

    /// <summary>
    /// Landblock <paramref name="blockPrefix"/> (<c>0xXXYY0000</c>) was loaded or replaced: every object standing in it, or
    /// with a shadow made for one of its cells, is listed again in the cells now loaded (positions, cells and contact state
    /// are kept). The objects are woken.
    /// </summary>
    internal void RehomeObjectsInBlock(uint blockPrefix)
    {
        if (_sweep is not RetailSweep sweep)
        {
            return;
        }

        for (int i = 0; i < _count; i++)
        {
            PhysicsObj o = _objects[i];
            // Children are shadowed with their parent (add_shadows_to_cells walks the child list).
            if (o.Parent is not null || o.CellId == 0 || (!InBlock(o.CellId, blockPrefix) && !o.HasShadowInBlock(blockPrefix)))
            {
                continue;
            }

            o.Touch();
            o.RehomeShadows(sweep);
        }
    }

    /// <summary>
    /// Landblock <paramref name="blockPrefix"/> was removed: every object standing in one of its outdoor cells leaves the world
    /// (retail's lost cell: cell 0, no shadows, not simulated, position kept) and is added to <paramref name="leftWorld"/>;
    /// objects elsewhere whose shadows reached into its cells are listed again in the cells still loaded.
    /// </summary>
    internal void SendObjectsInBlockOutOfWorld(uint blockPrefix, ICollection<PhysicsObj>? leftWorld)
    {
        RetailSweep? sweep = _sweep as RetailSweep;
        for (int i = 0; i < _count; i++)
        {
            PhysicsObj o = _objects[i];
            if (o.Parent is not null || o.CellId == 0)
            {
                continue;
            }

            if (InBlock(o.CellId, blockPrefix) && (o.CellId & 0xFFFFu) < LandDefs.FirstEnvCell)
            {
                o.GoToLostCell(o.Position);
                leftWorld?.Add(o);
            }
            else if (sweep is not null && o.HasShadowInBlock(blockPrefix))
            {
                o.Touch();
                o.RehomeShadows(sweep);
            }
        }
    }

    private static bool InBlock(uint cellId, uint blockPrefix) => (cellId & 0xFFFF0000u) == blockPrefix;
}
