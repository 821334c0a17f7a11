using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class BspObjectCollisionTests
{
    // A crate: one part whose physics BSP is the box -0.5..0.5 x -0.5..0.5 x 0..1.2 (part-local, part frame = object frame),
    // HAS_PHYSICS_BSP, standing at (104, 100) on the flat ground (z = 20): its west face is the plane x = 103.5.
    private static PhysicsObj Crate(PhysicsWorld world, uint id, float x, float y, Frame? partFrame = null, float partScale = 1f)
    {
        var polys = new List<Polygon>();
        BspScene.AddBox(polys, new Vector3(-0.5f, -0.5f, 0f), new Vector3(0.5f, 0.5f, 1.2f));
        var gfx = new GfxObjPhysics(BspBuilder.Build(polys.ToArray()));
        PhysicsObj obj = world.CreateObject(id);
        var parts = new SimplePartArray(1, 0) { SortingSphere = new Sphere(new Vector3(0f, 0f, 0.6f), 1f) };
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.6f), 0.6f) });
        obj.PartArray = parts;
        obj.SetState(PhysicsState.ReportCollisions | PhysicsState.HasPhysicsBsp);
        Assert.True(obj.EnterWorld(ObjectScene.At(x, y)));
        parts.SetPhysicsParts(new[] { gfx }, new[] { partFrame ?? Frame.Identity }, new[] { new Vector3(partScale) });
        return obj;
    }

    [Fact]
    public void Walker_IsStoppedByAnObjectsPartBsp_AndRecordsIt()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        PhysicsObj crate = Crate(world, 10, 104f, 100f);
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        float maxX = 0f;
        SweepScene.Run(world, 60, _ => maxX = Math.Max(maxX, c.Position.Frame.Origin.X));

        // The walker's sphere (r = 0.5, centre 0.5 above the origin) may come no closer to the face x = 103.5 than its
        // radius: the origin stays at x <= 103.0; the box is 1.2 m high (> the 0.6 m step up), so it does not climb it.
        Assert.True(maxX <= 103.0f + 0.001f, $"max x {maxX}");
        Assert.True(c.Position.Frame.Origin.X > 102.85f);
        Assert.Equal(ObjectScene.GroundZ, c.Position.Frame.Origin.Z, 3);
        Assert.Contains(c.CollisionRecords.ToArray(), r => r.ObjectId == crate.Id);
    }

    [Fact]
    public void PartFrameAndScale_PlaceTheBspInPartSpace()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        // The part sits 0.5 m east of the object's origin (104, 100) and is scaled by 2: its box -0.5..0.5 becomes
        // 103.5..105.5 around x = 104.5. Coming from the east, the walker (r = 0.5) meets the face x = 105.5 and its origin
        // stays at x >= 106.0 (without the part's offset and scale the face would be at 104.5 and it would reach 105.0).
        Crate(world, 10, 104f, 100f, new Frame(new Vector3(0.5f, 0f, 0f), System.Numerics.Quaternion.Identity), 2f);
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(108f, 100f, heading: 270f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        float minX = float.MaxValue;
        SweepScene.Run(world, 60, _ => minX = Math.Min(minX, c.Position.Frame.Origin.X));

        Assert.True(minX >= 106.0f - 0.001f, $"min x {minX}");
        Assert.True(c.Position.Frame.Origin.X < 106.15f);
    }

    [Fact]
    public void BspObject_IsShadowedInTheCellsItsSortingSphereCovers()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        // At (95.5, 100): the sorting sphere (r = 1) reaches over the cell edge x = 96 into the neighbouring cell.
        PhysicsObj crate = Crate(world, 10, 95.5f, 100f);
        sweep.CalcCrossCells(crate);
        Assert.Equal(2, crate.NumShadowObjects);
        Assert.True(ObjectScene.CellLists(sweep.Cells.GetVisible(ObjectScene.Cell(95f, 100f))!, crate));
        Assert.True(ObjectScene.CellLists(sweep.Cells.GetVisible(ObjectScene.Cell(97f, 100f))!, crate));
    }
}
