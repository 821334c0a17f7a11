using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The heading reads and writes in one type (double, the type retail's <c>Frame::get_heading</c> returns): a heading read with
/// <see cref="Frame.Heading"/> or <see cref="Position.Heading"/> is set back with <c>SetHeading</c> without a cast; the setter
/// rounds it to float first, as retail's <c>Frame::set_heading(float)</c>.
/// </summary>
public sealed class HeadingApiTests
{
    [Fact]
    public void HeadingReadBack_SetsTheSameFrame_AsItsFloatRounding()
    {
        Frame f = Frame.FromHeading(new Vector3(10f, 10f, 0f), 33.3);
        double h = f.Heading;

        Frame a = Frame.Identity;
        a.SetHeading(h);
        Frame b = Frame.Identity;
        b.SetHeading((float)h);

        Assert.Equal(b, a);
        Assert.Equal(33.3, h, 4);
    }

    [Fact]
    public void ObjectHeading_IsSetFromItsPositionsHeading_OneType()
    {
        var world = new PhysicsWorld();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        obj.SetHeading(90.0);
        double h = obj.Position.Heading;
        Assert.Equal(90.0, h, 4);
        obj.SetHeading(h + 90.0);
        Assert.Equal(180.0, obj.Position.Heading, 4);
        // A double whose float rounding overflows is refused like an infinity.
        Assert.Throws<ArgumentException>(() => obj.SetHeading(1e39));
        Assert.Equal(180.0, obj.Position.Heading, 4);
    }

    [Fact]
    public void HeadingTo_IsTheCompassDirectionToAnotherPosition()
    {
        var a = new Position(TickTestContext.OutdoorCell, new Vector3(10f, 10f, 0f));
        Assert.Equal(90.0, a.HeadingTo(new Position(TickTestContext.OutdoorCell, new Vector3(20f, 10f, 0f))), 9);
        Assert.Equal(0.0, a.Heading); // the identity frame faces north
    }
}
