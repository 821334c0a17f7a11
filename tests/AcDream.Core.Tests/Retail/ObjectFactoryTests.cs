using System;
using System.Linq;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.WorldSceneEntries;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CPhysicsObj::makeObject</c> (acclient.c:320828) and the functions under it, on synthetic entries: a GfxObj id is a
/// one-part simple setup (<c>CSetup::makeSimpleSetup</c>, 334455), a Setup id its parts (<c>CPartArray::InitParts</c>, 325273:
/// one failing part fails the object), each part's GfxObj through its degrade table (<c>LoadGfxObjArray</c>, 314891), the
/// placement frame 0x65, else key 0 (<c>SetPlacementFrame</c>, 326817), and the setup's defaults
/// (<c>CPhysicsObj::InitDefaults</c>, 320853).
/// </summary>
public class ObjectFactoryTests
{
    private static DictionarySource Models()
    {
        var s = new DictionarySource();
        AddModels(s);
        return s;
    }

    [Fact]
    public void AGfxObjId_IsOnePart_WithItsPhysicsBsp_AndItsPhysicsSphereForSorting()
    {
        var world = new PhysicsWorld();
        PhysicsObj o = new ObjectFactory(Models()).MakeObject(world, LowRock, isDynamic: false)!;
        var parts = (SimplePartArray)o.PartArray!;
        Assert.Equal(1, parts.NumParts);
        Assert.Equal(1, parts.NumCollisionParts);
        Assert.Equal(PhysicsState.Static | PhysicsState.HasPhysicsBsp, o.State & (PhysicsState.Static | PhysicsState.HasPhysicsBsp));
        // The box -1..1 × -1..1 × 0..0.4: the BSP root's sphere bounds it, centred at its middle (0, 0, 0.2).
        Assert.Equal(0.2f, parts.SortingSphere.Center.Z, 3);
        Assert.True(parts.SortingSphere.Radius >= MathF.Sqrt(2f + 0.04f) - 1e-4f);
    }

    [Fact]
    public void ASetupId_HasItsParts_CylinderSpheres_AndNoBspBit_WhenNoPartHasPhysics()
    {
        var world = new PhysicsWorld();
        PhysicsObj o = new ObjectFactory(Models()).MakeObject(world, Pine, isDynamic: false)!;
        var parts = (SimplePartArray)o.PartArray!;
        Assert.Equal(1, parts.NumParts);
        Assert.Equal(1.53f, parts.CylSpheres[0].Radius);
        Assert.Equal(34.6f, parts.CylSpheres[0].Height);
        Assert.Equal(-3.8f, parts.CylSpheres[0].LowPt.Z);
        Assert.Equal(0, parts.NumCollisionParts);
        Assert.Equal(PhysicsState.Static, o.State & (PhysicsState.Static | PhysicsState.HasPhysicsBsp));
    }

    [Fact]
    public void ADynamicObject_HasNoStaticBit_AndItsId()
    {
        var world = new PhysicsWorld();
        PhysicsObj o = new ObjectFactory(Models()).MakeObject(world, Pine, objectId: 0x50000001)!;
        Assert.Equal(PhysicsState.None, o.State & PhysicsState.Static);
        Assert.Same(o, world.GetObjectById(0x50000001));
    }

    [Fact]
    public void AMissingPart_FailsTheObject_AddsNothing_AndIsListed()
    {
        DictionarySource s = Models();
        s.Entries[0x02000030] = WorldEntries.Setup(new SetupDef(0x02000030, [Box, 0x01000099]));
        var world = new PhysicsWorld();
        var f = new ObjectFactory(s);
        Assert.Null(f.MakeObject(world, 0x02000030));
        Assert.Equal(0, world.ObjectCount);
        Assert.Contains(0x01000099u, f.MissingIds);
        Assert.Null(f.MakeObject(world, 0x02000031));
        Assert.Contains(0x02000031u, f.MissingIds);
    }

    [Fact]
    public void AnIdOfAnotherKind_FailsTheObject()
    {
        var world = new PhysicsWorld();
        Assert.Null(new ObjectFactory(Models()).MakeObject(world, 0x03000001));
        Assert.Equal(0, world.ObjectCount);
    }

    [Fact]
    public void AGfxObjNamingADegradeTable_CollidesWithItsFirstLevel()
    {
        // The root has no physics; its degrade table's first level (mode 1, a mesh) is the tall rock's box.
        DictionarySource s = Models();
        s.Entries[0x01000040] = WorldEntries.DrawingOnlyGfxObj(0x01000040, Vector3.Zero, Vector3.One, degrade: 0x11000040);
        s.Entries[0x11000040] = WorldEntries.DegradeInfo(0x11000040, (TallRock, 1), (Blade, 2));
        PhysicsObj o = new ObjectFactory(s).MakeObject(new PhysicsWorld(), 0x01000040)!;
        Assert.Equal(PhysicsState.HasPhysicsBsp, o.State & PhysicsState.HasPhysicsBsp);
        Assert.Equal(1, ((SimplePartArray)o.PartArray!).NumCollisionParts);
    }

    [Fact]
    public void ADegradeTableWhoseFirstLevelIsMissing_FailsThePart()
    {
        DictionarySource s = Models();
        s.Entries[0x01000041] = WorldEntries.DrawingOnlyGfxObj(0x01000041, Vector3.Zero, Vector3.One, degrade: 0x11000041);
        s.Entries[0x11000041] = WorldEntries.DegradeInfo(0x11000041, (0x01000098, 1));
        Assert.Null(new ObjectFactory(s).MakeObject(new PhysicsWorld(), 0x01000041));
    }

    [Fact]
    public void TheDefaultScales_AndPlacementKey0_WhenThereIsNo0x65()
    {
        DictionarySource s = Models();
        s.Entries[0x02000050] = WorldEntries.Setup(new SetupDef(0x02000050, [Box])
        {
            DefaultScales = [new Vector3(2f, 2f, 2f)],
            Placements = [(0, [new Frame(new Vector3(0f, 5f, 0f), Quaternion.Identity)])],
        });
        PhysicsObj o = new ObjectFactory(s).MakeObject(new PhysicsWorld(), 0x02000050, isDynamic: false)!;
        var parts = (SimplePartArray)o.PartArray!;
        Assert.Equal(new Vector3(0f, 5f, 0f), parts.PartBoxes[0].LocalFrame.Origin);
        Assert.Equal(1, parts.NumCollisionParts);
    }

    [Fact]
    public void AStaticWithADefaultAnimation_JoinsTheStaticAnimatingList_ADynamicOneDoesNot()
    {
        DictionarySource s = Models();
        s.Entries[0x02000060] = WorldEntries.Setup(new SetupDef(0x02000060, [Box]) { DefaultAnimation = 0x03000001 });
        s.Entries[0x02000061] = WorldEntries.Setup(new SetupDef(0x02000061, [Box]) { DefaultScript = 0x33000001 });
        var world = new PhysicsWorld();
        var f = new ObjectFactory(s);
        PhysicsObj windmill = f.MakeObject(world, 0x02000060, isDynamic: false)!;
        PhysicsObj flag = f.MakeObject(world, 0x02000061, isDynamic: false)!;
        PhysicsObj creature = f.MakeObject(world, 0x02000060)!;
        Assert.Equal(PhysicsState.HasDefaultAnim, windmill.State & (PhysicsState.HasDefaultAnim | PhysicsState.HasDefaultScript));
        Assert.Equal(PhysicsState.HasDefaultScript, flag.State & (PhysicsState.HasDefaultAnim | PhysicsState.HasDefaultScript));
        Assert.Equal(PhysicsState.None, creature.State & PhysicsState.HasDefaultAnim);
        Assert.Equal(new[] { windmill, flag }, world.StaticAnimatingObjects);
        world.RemoveObject(windmill);
        Assert.Equal(new[] { flag }, world.StaticAnimatingObjects);
    }

    [Fact]
    public void AZeroHighByteId_IsAnAnimObject_EtherealAndIgnoringCollisions()
    {
        // Retail makes Setup 0x02000000 | id (here the pine's 0x000010), ethereal, ignoring collisions, translucency 0.25.
        PhysicsObj o = new ObjectFactory(Models()).MakeObject(new PhysicsWorld(), Pine & 0x00FFFFFFu)!;
        Assert.Equal(PhysicsState.Ethereal | PhysicsState.IgnoreCollisions,
            o.State & (PhysicsState.Ethereal | PhysicsState.IgnoreCollisions));
        Assert.Equal(0.25f, ((SimplePartArray)o.PartArray!).Translucency);
    }

    [Fact]
    public void ABadSetup_IsAFormatError_AndAddsNothing()
    {
        DictionarySource s = Models();
        s.Entries[Pine] = s.Entries[Pine].AsSpan(0, 20).ToArray();
        var world = new PhysicsWorld();
        var e = Assert.Throws<AcDream.Core.Physics.Format.RetailDataFormatException>(() => new ObjectFactory(s).MakeObject(world, Pine));
        Assert.Equal("CSetup", e.Structure);
        Assert.Equal(0, world.ObjectCount);
    }

    [Fact]
    public void ADynamicBspObject_IsShadowedByItsPartBoxes_NotItsSortingSphere()
    {
        // The low rock's box (x ±1 m) at x 97.2 stays in land cell (4, 4) (96..120 m); its sorting sphere (the BSP root's,
        // radius about 1.43 m) would reach back into cell (3, 4). Retail's calc_cross_cells lists a BSP object by its parts'
        // boxes (find_bbox_cell_list, acclient.c:318275).
        PhysicsWorld world = World(out _);
        new WorldLoader(world, Source([])).Load(Block);
        var f = new ObjectFactory(Models());
        PhysicsObj rock = f.MakeObject(world, LowRock)!;
        Assert.True(rock.EnterWorld(new Position(BspScene.OutdoorCell(97.2f, 100f), At(97.2f, 100f))));
        uint[] cells = rock.ShadowObjects.ToArray().Select(x => x.CellId).ToArray();
        Assert.Equal(new[] { BspScene.OutdoorCell(100f, 100f) }, cells);
    }
}
