using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// A <see cref="SimplePartArray"/> belongs to one object: it records that object's frame, cell, scale and fades, and wakes that
/// object when it changes. Giving it to a second object is refused (<see cref="ArgumentException"/>, nothing changes); it is
/// released when its object takes another part array (or none) and may then be given to another object.
/// </summary>
public class SharedPartArrayRefusedTests
{
    [Fact]
    public void SecondObject_IsRefused_StateUnchanged()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = TickTestContext.CreateObject(world, new Vector3(5f, 10f, 0f), id: 1);
        var parts = (SimplePartArray)a.PartArray!;
        PhysicsObj b = world.CreateObject(2);
        var own = new SimplePartArray(1, 1);
        b.PartArray = own;

        Assert.Throws<ArgumentException>(() => b.PartArray = parts);

        Assert.Same(own, b.PartArray);
        Assert.Same(parts, a.PartArray);
        Assert.Same(a, parts.Owner);
        Assert.Same(b, own.Owner);
        // The part array still follows a: placing b does not move a's parts.
        Assert.True(b.EnterWorld(new Position(TickTestContext.OutdoorCell, new Vector3(9f, 10f, 0f))));
        Assert.Equal(new Vector3(5f, 10f, 0f), parts.Frame.Origin);
    }

    [Fact]
    public void SameObjectAgain_IsAccepted()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = TickTestContext.CreateObject(world, new Vector3(5f, 10f, 0f), id: 1);
        IPartArray parts = a.PartArray!;
        a.PartArray = parts;
        Assert.Same(parts, a.PartArray);
    }

    [Fact]
    public void Released_WhenItsObjectTakesAnother_ThenAnotherObjectMayTakeIt()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = world.CreateObject(1);
        PhysicsObj b = world.CreateObject(2);
        var parts = new SimplePartArray(1, 1);
        a.PartArray = parts;
        a.PartArray = null;
        Assert.Null(parts.Owner);

        b.PartArray = parts;
        Assert.Same(b, parts.Owner);
        Assert.Throws<ArgumentException>(() => a.PartArray = parts);
        Assert.Null(a.PartArray);
    }
}
