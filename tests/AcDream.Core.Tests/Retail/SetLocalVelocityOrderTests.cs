using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CPhysicsObj::set_local_velocity</c> (acclient.c:318617) rotates the local velocity with its own sum, row by row
/// <c>m[0]*vx + m[3]*vy + m[6]*vz</c> (then m[1], m[4], m[7] and m[2], m[5], m[8]; acclient.c:318622–318630), left to right.
/// <c>Frame::localtoglobalvec</c> adds the z product first. The port sums in set_local_velocity's order. Under the library's
/// arithmetic model (float products exact in double, one rounding to float) the two orders agree on every input sampled
/// here — a difference needs a double rounding of the 53-bit sum to reach the 24-bit result — so this pins the value
/// (matrix entries and rows), not a visible change.
/// </summary>
public class SetLocalVelocityOrderTests
{
    private static Vector3 RetailOrder(in Frame f, Vector3 v) => new(
        (float)((double)f.M11 * v.X + (double)f.M21 * v.Y + (double)f.M31 * v.Z),
        (float)((double)f.M12 * v.X + (double)f.M22 * v.Y + (double)f.M32 * v.Z),
        (float)((double)f.M13 * v.X + (double)f.M23 * v.Y + (double)f.M33 * v.Z));

    [Fact]
    public void SumsInSetLocalVelocitysOrder_OverTiltedFrames()
    {
        var world = new PhysicsWorld();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 100f));
        var rng = new Random(1234);
        for (int i = 0; i < 2000; i++)
        {
            var q = Quaternion.Normalize(new Quaternion((float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f,
                                                        (float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() + 0.1f));
            var frame = new Frame(new Vector3(10f, 10f, 100f), q);
            var local = new Vector3((float)(rng.NextDouble() * 20 - 10), (float)(rng.NextDouble() * 20 - 10),
                                    (float)(rng.NextDouble() * 20 - 10));
            obj.SetFrame(frame);
            obj._velocity = Vector3.Zero;
            obj.SetLocalVelocity(local);
            Frame now = obj.Position.Frame;
            Vector3 expected = RetailOrder(in now, local);
            Assert.Equal(expected, obj.Velocity);
        }
    }
}
