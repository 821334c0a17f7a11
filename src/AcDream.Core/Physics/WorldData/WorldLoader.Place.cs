using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.WorldData;

// Putting a read block's buildings, static objects and scenery into the world (retail CLandBlock's init and destroy steps).
public sealed partial class WorldLoader
{
    /// <summary>Each building of the block's info: made from its model id (GfxObj or Setup; it collides through its part 0),
    /// hung on the land cell under its origin (the first building of a cell wins), or dropped when its origin falls outside
    /// the block.</summary>
    // retail: CLandBlock::init_buildings (acclient.c:352113)
    private void InitBuildings(LoadedBlock b)
    {
        LandBlockInfoEntry? info = b.Pending.Info;
        if (info is null)
        {
            return;
        }

        foreach (BuildingInfo bi in info.Buildings)
        {
            BuildingObj? building = MakeBuilding(b, bi);
            if (building is null)
            {
                continue;
            }

            LandCell? cell = GetLandCell(b, bi.Frame.Origin);
            if (cell is null)
            {
                continue; // retail deletes it (acclient.c:352180)
            }

            building.AddToCell(cell);
            b.Buildings.Add(building);
            b.Objects.Add(new WorldObject(WorldObjectKind.Building, bi.ModelId, null, building, cell.Id, bi.Frame, 1f));
        }
    }

    /// <summary>A building from its model: its part 0 (the setup's first part at its placement frame and default scale,
    /// or the GfxObj itself) placed at the building's frame, and its doors; null when the model cannot be made.</summary>
    // retail: CBuildingObj::makeBuilding (acclient.c:719152)
    private BuildingObj? MakeBuilding(LoadedBlock b, BuildingInfo bi)
    {
        ObjectModel? model = Objects.InitPartArrayModel(bi.ModelId, out _);
        if (model is null)
        {
            b.Missing.AddRange(Objects.MissingFor(bi.ModelId));
            return null;
        }

        PhysicsPart? part = null;
        if (model.NumParts != 0 && model.PartPhysics[0] is GfxObjPhysics shell)
        {
            // retail: CPhysicsObj::set_initial_frame (acclient.c:321355) -> CPartArray::SetFrame: part 0 at the building's
            // frame combined with its placement frame
            Frame f = Frame.Combined(bi.Frame, model.PartFrames[0]);
            part = new PhysicsPart(shell, new Position(b.Pending.BlockId, f), model.DefaultScales[0]);
        }

        var doors = new BldPortal[bi.Portals.Length];
        for (int i = 0; i < doors.Length; i++)
        {
            doors[i] = bi.Portals[i].ToBldPortal();
        }

        return new BuildingObj(part, doors, bi.NumLeaves);
    }

    /// <summary>The block's static objects (each in the land cell under its origin, or dropped outside the block), the
    /// restriction table onto the land cells, then the scenery.</summary>
    // retail: CLandBlock::init_static_objs (acclient.c:352786), the first call
    private void InitStaticObjs(LoadedBlock b)
    {
        LandBlockInfoEntry? info = b.Pending.Info;
        if (info is not null)
        {
            foreach (StaticObjectInfo o in info.Objects)
            {
                LandCell? cell = GetLandCell(b, o.Frame.Origin);
                PhysicsObj? obj = MakeStatic(b, o.Id, cell is not null);
                if (obj is null || cell is null)
                {
                    continue;
                }

                obj.AddObjToCell(cell, o.Frame, _sweep);
                AddStaticObject(b, obj, WorldObjectKind.LandBlockStatic, o.Id, 1f);
            }

            LandBlockRestrictions(b, info);
        }

        GetLandScenes(b);
    }

    // retail: CLandBlock::init_static_objs (acclient.c:352786), lines 352869–352884
    private static void LandBlockRestrictions(LoadedBlock b, LandBlockInfoEntry info)
    {
        for (int x = 0; x < LandDefs.BlockSide; x++)
        {
            for (int y = 0; y < LandDefs.BlockSide; y++)
            {
                LandCell cell = b.Pending.LandBlock.GetCell(x, y);
                uint r = info.GetRestrictionIid(cell.Id);
                if (r != 0)
                {
                    cell.RestrictionObj = r;
                }
            }
        }
    }

    /// <summary>The scenery placements of the block: each made, placed at its frame when it lies within the block at scale
    /// 1, shadowed, and only then scaled.</summary>
    // retail: CLandBlock::get_land_scenes (acclient.c:352529), lines 352707–352721 (after the placement)
    private void GetLandScenes(LoadedBlock b)
    {
        foreach (SceneryItem s in b.Pending.Scenery)
        {
            LandCell? cell = b.Pending.LandBlock.GetLandCell(s.LandCellId);
            PhysicsObj? obj = MakeStatic(b, s.ObjectId, cell is not null);
            if (obj is null || cell is null)
            {
                continue;
            }

            obj.SetInitialFrame(s.Frame);
            if (!obj.ObjWithinBlock())
            {
                _world.RemoveObject(obj);
                continue;
            }

            obj.AddObjToCell(cell, s.Frame, _sweep);
            obj.SetScaleStatic(s.Scale);
            AddStaticObject(b, obj, WorldObjectKind.Scenery, s.ObjectId, s.Scale);
        }
    }

    /// <summary>Each indoor cell's static objects, made and put in their cell at their stored frame.</summary>
    // retail: CEnvCell::init_static_objects (acclient.c:347954), the first call
    private void InitEnvCellStatics(LoadedBlock b)
    {
        EnvCellEntry[] entries = b.Pending.EnvEntries;
        for (int i = 0; i < entries.Length; i++)
        {
            EnvCell cell = b.Pending.EnvCells[i];
            foreach (StaticObjectInfo o in entries[i].StaticObjects)
            {
                if (o.Id == 0)
                {
                    continue;
                }

                PhysicsObj? obj = MakeStatic(b, o.Id, true);
                if (obj is null)
                {
                    continue;
                }

                obj.AddObjToCell(cell, o.Frame, _sweep);
                AddStaticObject(b, obj, WorldObjectKind.EnvCellStatic, o.Id, 1f);
            }
        }
    }

    // makeObject(id, 0, 0); a missing entry is recorded for the block. With place false the object would be deleted at once
    // (its cell is missing): it is not created at all.
    private PhysicsObj? MakeStatic(LoadedBlock b, uint dataId, bool place)
    {
        ObjectModel? model = Objects.InitPartArrayModel(dataId, out bool animObject);
        if (model is null)
        {
            b.Missing.AddRange(Objects.MissingFor(dataId));
            return null;
        }

        return place ? Objects.Instantiate(_world, model, 0, isDynamic: false, animObject) : null;
    }

    // retail: CLandBlock::add_static_object (acclient.c:351856)
    private static void AddStaticObject(LoadedBlock b, PhysicsObj obj, WorldObjectKind kind, uint dataId, float scale)
    {
        b.StaticObjects.Add(obj);
        b.Objects.Add(new WorldObject(kind, dataId, obj, null, obj.CellId, obj.Position.Frame, scale));
    }

    // The block's land cell under a block-local origin, or null when it lies outside the block.
    // retail: LandDefs::adjust_to_outside (acclient.c:467433) then CLandBlock::get_landcell (acclient.c:352097)
    private static LandCell? GetLandCell(LoadedBlock b, Vector3 origin) =>
        GetLandCell(b.Pending.LandBlock, b.Pending.BlockId, origin);

    // The same, for a block read but not yet in the world.
    private static LandCell? GetLandCell(LandBlock landBlock, uint blockId, Vector3 origin)
    {
        uint cellId = blockId;
        Vector3 loc = origin;
        bool ok = LandDefs.AdjustToOutside(ref cellId, ref loc);
        return landBlock.GetLandCell(ok ? cellId : 0);
    }

    // retail: CLandBlock::destroy_static_objects (acclient.c:351930): each leaves the world and is deleted
    private void DestroyStaticObjects(LoadedBlock b)
    {
        foreach (PhysicsObj o in b.StaticObjects)
        {
            if (!o.IsRemoved)
            {
                _world.RemoveObject(o);
            }
        }

        b.StaticObjects.Clear();
    }

    // retail: CLandBlock::destroy_buildings (acclient.c:351376)
    private void DestroyBuildings(LoadedBlock b)
    {
        foreach (BuildingObj building in b.Buildings)
        {
            building.Remove(_cells.Terrain.GetLandCell(building.CellId));
        }

        b.Buildings.Clear();
    }
}
