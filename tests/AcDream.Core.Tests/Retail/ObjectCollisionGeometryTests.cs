using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class ObjectCollisionGeometryTests
{
    [Fact]
    public void Constants_MatchRetail()
    {
        // CObjCell::add_shadow_object grows the list by 5 (acclient.c:346804).
        Assert.Equal(5, ObjCell.ShadowListGrowth);
        // report_collision_end drops records older than 1.0 s (acclient.c:321712).
        Assert.Equal(1.0, PhysicsObj.CollisionRecordLifetime);
        Assert.Equal(0x3FF0000000000000L, BitConverter.DoubleToInt64Bits(PhysicsObj.CollisionRecordLifetime));
    }

    [Fact]
    public void ShadowList_DoublesWhenFull_KeepingRetailOrder()
    {
        // A cell's list starts with 5 slots (one retail growth step). Retail's add_shadow_object then grows by 5
        // (acclient.c:346804): 10, 15, 20. Ours doubles: the 6th shadow makes 10 slots, the 11th 20, the 21st 40; the
        // shadows stay in the order they were added, as retail lists them.
        var terrain = new TerrainWorld(TerrainTestData.IdentityTable());
        terrain.AddLandBlock(0xA9B4FFFFu, new byte[81], TerrainTestData.Terrain(1));
        LandCell cell = terrain.GetLandCell(0xA9B40001u)!;
        var world = new PhysicsWorld();
        var shadows = new ShadowObj[21];
        int[] capacityAfter = new int[22];
        for (int i = 0; i < shadows.Length; i++)
        {
            shadows[i] = new ShadowObj(world.CreateObject((uint)(i + 1)));
            cell.AddShadowObject(shadows[i]);
            capacityAfter[i + 1] = cell.ShadowCapacity;
        }

        Assert.Equal(5, capacityAfter[5]);
        Assert.Equal(10, capacityAfter[6]);
        Assert.Equal(10, capacityAfter[10]);
        Assert.Equal(20, capacityAfter[11]);
        Assert.Equal(40, capacityAfter[21]);
        for (int i = 0; i < shadows.Length; i++)
        {
            Assert.Same(shadows[i], cell.ShadowObjects[i]);
            Assert.Same(cell, shadows[i].Cell);
        }
    }

    [Fact]
    public void FindTimeOfCollision_SolvesTheApproachQuadratic()
    {
        // From disp (-2, 0, 0) moving (1, 0, 0), touching at distance 1: a = 1, b = 2, c = 4 - 1 = 3, disc = 4 - 3 = 1,
        // b - sqrt = 1 >= 0 -> t = 1 / 1 = 1.
        Assert.Equal(1.0, Sphere.FindTimeOfCollision(new Vector3(1f, 0f, 0f), new Vector3(-2f, 0f, 0f), 1f), 12);
        // Moving (4, 0, 0): a = 16, b = 8, disc = 64 - 48 = 16 -> t = (8 - 4) / 16 = 0.25.
        Assert.Equal(0.25, Sphere.FindTimeOfCollision(new Vector3(4f, 0f, 0f), new Vector3(-2f, 0f, 0f), 1f), 12);
        // Already inside (c = 0.25 - 1 < EPSILON), not moving (a = 0), or passing by (disc = 4 - 7 < 0): -1.
        Assert.Equal(-1.0, Sphere.FindTimeOfCollision(new Vector3(1f, 0f, 0f), new Vector3(-0.5f, 0f, 0f), 1f));
        Assert.Equal(-1.0, Sphere.FindTimeOfCollision(Vector3.Zero, new Vector3(-2f, 0f, 0f), 1f));
        Assert.Equal(-1.0, Sphere.FindTimeOfCollision(new Vector3(1f, 0f, 0f), new Vector3(-2f, 2f, 0f), 1f));
    }

    [Fact]
    public void SphereOverlap_CountsTouching()
    {
        // |(3, 4, 0)| = 5.
        Assert.True(Sphere.CollidesWithSphere(new Vector3(3f, 4f, 0f), 5f));
        Assert.False(Sphere.CollidesWithSphere(new Vector3(3f, 4f, 0f), 4.999f));
    }

    [Fact]
    public void CylSphereOverlap_IsARadialAndAHeightBandTest()
    {
        // Cylinder r = 1, h = 2 (mid-height 1); check sphere r = 0.5: radsum 1.5, height band |1 - dz| <= 0.5 - EPS + 1.
        var cyl = new CylSphere(Vector3.Zero, 1f, 2f);
        var s = new Sphere(Vector3.Zero, 0.5f);
        Assert.True(cyl.CollidesWithSphere(s, new Vector3(1.4f, 0f, 1f), 1.5f));
        Assert.False(cyl.CollidesWithSphere(s, new Vector3(1.6f, 0f, 1f), 1.5f));
        // dz = 2.4: |1 - 2.4| = 1.4 <= 1.4998; dz = 2.6: 1.6 > 1.4998; dz = -0.45: 1.45 <= 1.4998.
        Assert.True(cyl.CollidesWithSphere(s, new Vector3(0f, 0f, 2.4f), 1.5f));
        Assert.False(cyl.CollidesWithSphere(s, new Vector3(0f, 0f, 2.6f), 1.5f));
        Assert.True(cyl.CollidesWithSphere(s, new Vector3(0f, 0f, -0.45f), 1.5f));
    }

    [Fact]
    public void DetermineQuadrant_FrontBackLeftRightHighMiddleLow()
    {
        // Facing north (heading 0): local +x = east, +y = north. Height 3: low below 1, middle below 2, high from 2.
        var self = new Position(0x80800001u, Frame.FromHeading(new Vector3(10f, 10f, 0f), 0f));
        Assert.Equal(0x10 | 0x20 | 0x1, PhysicsObj.DetermineQuadrant(self, 3f, new Position(0x80800001u, new Vector3(11f, 11f, 2.5f))));
        Assert.Equal(0x8 | 0x40 | 0x4, PhysicsObj.DetermineQuadrant(self, 3f, new Position(0x80800001u, new Vector3(9f, 9f, 0.5f))));
        Assert.Equal(0x10 | 0x40 | 0x2, PhysicsObj.DetermineQuadrant(self, 3f, new Position(0x80800001u, new Vector3(10f, 9f, 1.5f))));
    }
}
