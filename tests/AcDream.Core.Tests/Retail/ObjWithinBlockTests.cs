using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Scenery;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CPhysicsObj::obj_within_block</c> (acclient.c:318306) as <see cref="SceneryGenerator.ObjWithinBlock"/>: the shape
/// decides the test (physics BSP: the sorting sphere; else cylinders; else spheres through <c>LandDefs::within_block</c>;
/// else the origin), each with the bounds <c>r ≤ x, y &lt; 192 − r</c>.
/// </summary>
public class ObjWithinBlockTests
{
    private static readonly Sphere Sorting = new(new Vector3(0f, 0f, 1f), 2f);

    // The tree 0x020002D3's cylinder as holtburger's notes measure it: r 1.53, height 34.606, low point z -3.8.
    private static readonly CylSphere[] Tree = [new(new Vector3(0f, 0f, -3.8f), 1.53f, 34.606f)];

    private static Frame At(float x, float y, double heading = 0.0) => Frame.FromHeading(new Vector3(x, y, 50f), heading);

    [Theory]
    [InlineData(2f, 2f, true)]
    [InlineData(1.99f, 100f, false)]
    [InlineData(100f, 1.99f, false)]
    [InlineData(189.99f, 189.99f, true)]
    [InlineData(190f, 100f, false)]
    [InlineData(100f, 190f, false)]
    public void APhysicsBspObject_TestsItsSortingSphere(float x, float y, bool inside) =>
        Assert.Equal(inside, SceneryGenerator.ObjWithinBlock(At(x, y), true, Sorting, Tree, true));

    [Fact]
    public void TheSortingSphere_TurnsWithTheFrame()
    {
        // Heading 90 faces east: local +Y is global +X, so a centre 3 m ahead lies 3 m east of the origin.
        var ahead = new Sphere(new Vector3(0f, 3f, 0f), 2f);
        Assert.True(SceneryGenerator.ObjWithinBlock(At(187.5f, 100f, 0.0), true, ahead, [], false));   // centre (187.5, 103)
        Assert.False(SceneryGenerator.ObjWithinBlock(At(187.5f, 100f, 90.0), true, ahead, [], false)); // 190.5 + 2 > 192
        Assert.True(SceneryGenerator.ObjWithinBlock(At(-0.5f, 100f, 90.0), true, ahead, [], false));   // centre at x = 2.5
        Assert.False(SceneryGenerator.ObjWithinBlock(At(-1.5f, 100f, 90.0), true, ahead, [], false));  // centre at x = 1.5
    }

    [Theory]
    [InlineData(1.53f, 100f, true)]
    [InlineData(1.52f, 100f, false)]
    [InlineData(190.46f, 100f, true)]
    [InlineData(190.47f, 100f, false)] // (float)(192 - 1.53): the far bound is strict
    [InlineData(100f, 190.47f, false)]
    public void ACylinderObject_TestsEachCylindersLowPoint(float x, float y, bool inside) =>
        Assert.Equal(inside, SceneryGenerator.ObjWithinBlock(At(x, y), false, Sorting, Tree, true));

    [Fact]
    public void EveryCylinder_MustBeInside()
    {
        CylSphere[] two = [Tree[0], new(new Vector3(5f, 0f, 0f), 1f, 2f)];
        Assert.True(SceneryGenerator.ObjWithinBlock(At(100f, 100f), false, Sorting, two, false));
        Assert.False(SceneryGenerator.ObjWithinBlock(At(186.5f, 100f), false, Sorting, two, false)); // the second reaches 192.5
        Assert.True(SceneryGenerator.ObjWithinBlock(At(186.5f, 100f), false, Sorting, Tree, false));
    }

    [Fact]
    public void WithoutBspOrCylinders_SpheresUseWithinBlock_ElseTheOrigin()
    {
        Assert.False(SceneryGenerator.ObjWithinBlock(At(1f, 100f), false, Sorting, [], true)); // sphere r 2 at x = 1
        Assert.True(SceneryGenerator.ObjWithinBlock(At(1f, 100f), false, Sorting, [], false)); // no shape: the origin
        Assert.True(SceneryGenerator.ObjWithinBlock(At(0f, 0f), false, Sorting, [], false));
        Assert.False(SceneryGenerator.ObjWithinBlock(At(-0.001f, 0f), false, Sorting, [], false));
        Assert.False(SceneryGenerator.ObjWithinBlock(At(192f, 5f), false, Sorting, [], false));
    }

    [Fact]
    public void APhysicsBsp_TakesPrecedenceOverCylinders()
    {
        // The cylinder would fail at x = 1.0, the sorting sphere (r 0.5) passes.
        var small = new Sphere(Vector3.Zero, 0.5f);
        Assert.True(SceneryGenerator.ObjWithinBlock(At(1f, 100f), true, small, Tree, true));
        Assert.False(SceneryGenerator.ObjWithinBlock(At(1f, 100f), false, small, Tree, true));
    }
}
