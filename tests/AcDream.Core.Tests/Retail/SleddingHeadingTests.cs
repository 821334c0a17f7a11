using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// A sledding object faces its velocity: UpdatePositionInternal sets the new frame's heading to
/// <c>AC1Legacy::Vector3::get_heading(m_velocityVector)</c> (acclient.c:148166), printed as
/// <c>fmod(450 - atan2(n.x, n.y) * 57.29577951308232, 360)</c>. With the project's swapped-operand reading of x87 FPATAN
/// (docs/divergences.md, "Heading: atan2 operand order") that is <c>450 - angle-from-east</c>, i.e. the compass heading.
/// </summary>
public class SleddingHeadingTests
{
    // (vx, vy) -> heading in degrees clockwise from north:
    // east (1, 0): atan2(0, 1) = 0 rad -> fmod(450 - 0, 360) = 90
    // north (0, 2): atan2(2, 0) = 90 deg -> fmod(450 - 90, 360) = 0
    // south-west (-1, -1): atan2(-1, -1) = -135 deg -> fmod(450 + 135, 360) = 225
    [Theory]
    [InlineData(1f, 0f, 90.0)]
    [InlineData(0f, 2f, 0.0)]
    [InlineData(-1f, -1f, 225.0)]
    public void Sledding_FacesItsHorizontalVelocity(float vx, float vy, double expectedHeading)
    {
        PhysicsWorld world = TickTestContext.World(100.0);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 50f));
        obj.SetState(obj.State | PhysicsState.Sledding);
        obj.SetVelocity(new Vector3(vx, vy, 0f));
        world.SetCurrentTime(100.0 + 1.0 / 30.0);
        obj.UpdateObject();
        Assert.Equal(expectedHeading, obj.Position.Frame.Heading, 3);
    }
}
