using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.WorldData;

// A read block's life in the world: its cells added, retail's two grab passes (buildings, then statics and the objects lost
// in its cells), and its release (CLandBlock::release_all, notify_change_size, Destroy).
public sealed partial class WorldLoader
{
    /// <summary>The block's terrain and indoor cells (when read with it) go into the world; objects lost in them wait for
    /// <see cref="InitDynObjs"/>.</summary>
    // retail: LScape::update_block (acclient.c:307785), the CLandBlockStruct::generate at full detail (lines 308169–308205)
    internal LoadedBlock AddCells(PendingBlock p)
    {
        var b = new LoadedBlock(p);
        _blocks.Add(p.BlockId, b);
        _cells.Terrain.AddLandBlock(p.LandBlock, initObjects: false);

        foreach (EnvCell c in p.EnvCells)
        {
            _cells.AddEnvCell(c, initObjects: false);
        }

        return b;
    }

    /// <summary>Retail's two passes over the loaded blocks: every block's buildings, then each block's static objects (the
    /// first time; later, the scenery's heights and the statics' shadows), its indoor cells' statics and the objects lost in
    /// its cells.</summary>
    // retail: LScape::grab_visible_cells (acclient.c:306570)
    internal void GrabVisibleCells(IReadOnlyList<LoadedBlock> blocks)
    {
        for (int i = 0; i < blocks.Count; i++)
        {
            LoadedBlock b = blocks[i];
            if (!b.BuildingsDone)
            {
                b.BuildingsDone = true;
                InitBuildings(b);
            }
        }

        for (int i = 0; i < blocks.Count; i++)
        {
            LoadedBlock b = blocks[i];
            if (!b.StaticsDone)
            {
                b.StaticsDone = true;
                InitStaticObjs(b);
                InitEnvCellStaticsOnce(b);
            }
            else
            {
                AdjustSceneObjHeight(b);
                RecalcStaticShadows(b);
            }

            b.Block ??= new WorldBlock(b.Pending.BlockId, b.Pending.LandBlock, b.Pending.Info, b.Pending.EnvCells, b.Objects,
                b.Missing.ToArray());
            InitDynObjs(b);
        }
    }

    private void InitEnvCellStaticsOnce(LoadedBlock b)
    {
        if (b.Block is null)
        {
            InitEnvCellStatics(b);
        }
    }

    /// <summary>Once per load: the objects lost in the block's land cells (x, then y) and in its indoor cells come back.</summary>
    // retail: CLandBlock::init_dyn_objs (acclient.c:351558); the indoor cells' init_objects runs as they become visible
    internal void InitDynObjs(LoadedBlock b)
    {
        if (b.DynObjsInitDone)
        {
            return;
        }

        b.DynObjsInitDone = true;
        _world.InitLandBlockObjCells(b.Pending.LandBlock);

        foreach (EnvCell c in b.Pending.EnvCells)
        {
            c.InitObjects(_world);
        }
    }

    /// <summary>The block's cells are released: their shadows dropped and their moving objects sent to their lost cells
    /// (land cells x, then y; then the indoor cells).</summary>
    // retail: CLandBlock::release_objs (acclient.c:351533); the indoor cells' as CEnvCell::release_visible releases them
    private void ReleaseObjs(LoadedBlock b)
    {
        LandBlock land = b.Pending.LandBlock;
        for (int x = 0; x < LandDefs.BlockSide; x++)
        {
            for (int y = 0; y < LandDefs.BlockSide; y++)
            {
                land.GetCell(x, y).ReleaseObjects(_world);
            }
        }

        foreach (EnvCell c in b.Pending.EnvCells)
        {
            c.ReleaseObjects(_world);
        }

        b.DynObjsInitDone = false;
    }

    /// <summary>The block leaves the world: its static objects and buildings are destroyed, then its indoor cells and
    /// terrain go (the objects standing in them go to their lost cells, to come back when the block returns).</summary>
    // retail: CLandBlock::release_all (acclient.c:352086) -> release_objs (acclient.c:351533), release_visible, and the
    // block's destruction (CLandBlock::Destroy, acclient.c:351958); CLandBlock::notify_change_size (acclient.c:352429)
    internal void Release(LoadedBlock b)
    {
        _blocks.Remove(b.Pending.BlockId);
        ReleaseObjs(b);
        DestroyStaticObjects(b);
        DestroyBuildings(b);
        foreach (EnvCell c in b.Pending.EnvCells)
        {
            _cells.RemoveEnvCell(c.CellId);
        }

        _cells.Terrain.RemoveLandBlock(b.Pending.BlockId);
    }

    /// <summary>Each scenery object (the statics after the landblock info's) set on the terrain under it again when it
    /// stands more than 0.0002 m off it.</summary>
    // retail: CLandBlock::adjust_scene_obj_height (acclient.c:352193)
    private static void AdjustSceneObjHeight(LoadedBlock b)
    {
        int first = b.Pending.Info is { } info ? info.Objects.Length : 0;
        List<PhysicsObj> statics = b.StaticObjects;
        for (int i = first; i < statics.Count; i++)
        {
            PhysicsObj o = statics[i];
            if (o.IsRemoved || o.Cell is not LandCell cell)
            {
                continue;
            }

            Frame frame = o.Position.Frame;
            Vector3 v = frame.Origin;
            if (!cell.FindTerrainPoly(v, out Polygon? walkable))
            {
                continue;
            }

            // retail inlines Plane::set_height here: z unchanged on a plane vertical within EPSILON
            walkable.Plane.SetHeight(ref v);
            if (Math.Abs((double)v.Z - frame.Origin.Z) > PhysicsGlobals.Epsilon)
            {
                frame.Origin = v;
                o.SetInitialFrame(frame);
            }
        }
    }

    /// <summary>Each static object not shadowed in every cell its list named (a neighbour was not loaded) is shadowed
    /// again.</summary>
    // retail: CLandBlock::init_static_objs (acclient.c:352786), its second-call branch (is_completely_visible,
    // calc_cross_cells_static)
    private void RecalcStaticShadows(LoadedBlock b)
    {
        foreach (PhysicsObj o in b.StaticObjects)
        {
            if (!o.IsRemoved && !o.IsCompletelyVisible)
            {
                o.CalcCrossCellsStatic(_sweep);
            }
        }
    }
}
