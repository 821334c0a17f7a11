using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support;
using FsCheck;
using FsCheck.Fluent;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>Property-based invariants of Frame and LandDefs over generated inputs (FsCheck).</summary>
public class FramePropertyTests
{
    private static readonly Gen<float> Unit = Gen.Choose(-1_000_000, 1_000_000).Select(i => i / 1_000_000f);

    private static readonly Gen<Frame> Frames =
        from w in Unit
        from x in Unit
        from y in Unit
        from z in Unit
        from ox in Gen.Choose(0, 192_000)
        from oy in Gen.Choose(0, 192_000)
        from oz in Gen.Choose(-50_000, 50_000)
        where (double)w * w + (double)x * x + (double)y * y + (double)z * z > 0.01
        select new Frame(new Vector3(ox / 1000f, oy / 1000f, oz / 1000f), new Quaternion(x, y, z, w));

    private static readonly Gen<Vector3> Points =
        from x in Unit
        from y in Unit
        from z in Unit
        select new Vector3(x * 10f, y * 10f, z * 10f);

    private static Config Cfg => PropertyAssert.Replayable(500, 12345UL, 0x9E3779B97F4A7C15UL);

    [Fact]
    public void LocalToGlobalThenGlobalToLocal_RoundTrips()
    {
        // Bound: origins up to 192 m have float spacing 1.5e-5; two transforms and a subtraction keep the error below 1e-4.
        PropertyAssert.Holds(Cfg, Prop.ForAll(Frames.ToArbitrary(), Points.ToArbitrary(), (f, p) =>
            Vector3.Distance(f.GlobalToLocal(f.LocalToGlobal(p)), p) < 1e-4f));
    }

    [Fact]
    public void CombineThenSetToRelative_GivesBackTheLocalFrame()
    {
        PropertyAssert.Holds(Cfg, Prop.ForAll(Frames.ToArbitrary(), Frames.ToArbitrary(), (a, b) =>
        {
            Frame ab = Frame.Combined(a, b);
            Frame back = Frame.Identity;
            back.SetToRelative(ab, a);
            // Same rotation (q or -q within 1e-4) and origin within 2e-3 m (origins up to ~330 m, float spacing 3e-5).
            double dot = (double)back.Qw * b.Qw + (double)back.Qx * b.Qx + (double)back.Qy * b.Qy + (double)back.Qz * b.Qz;
            return Math.Abs(Math.Abs(dot) - 1.0) < 1e-4 && Vector3.Distance(back.Origin, b.Origin) < 2e-3f;
        }));
    }

    [Fact]
    public void EveryOperation_KeepsTheFrameValid()
    {
        PropertyAssert.Holds(Cfg, Prop.ForAll(Frames.ToArbitrary(), Points.ToArbitrary(), (f, w) =>
        {
            Frame g = f;
            g.GRotate(w);
            g.Rotate(w);
            g.SetHeading(w.X * 100f);
            g.SetVectorHeading(w);
            Frame h = Frame.Combined(g, f);
            return g.IsValid() && h.IsValid();
        }));
    }

    [Fact]
    public void SetHeadingThenGetHeading_AgreesOnTheCircle()
    {
        PropertyAssert.Holds(Cfg, Prop.ForAll(Gen.Choose(-720_000, 720_000).ToArbitrary(), milli =>
        {
            float h = milli / 1000f;
            Frame f = Frame.Identity;
            f.SetHeading(h);
            double back = f.Heading;
            double diff = Math.Abs(((back - h) % 360.0 + 540.0) % 360.0 - 180.0);
            return diff < 1e-3 && back >= 0.0 && back < 360.0;
        }));
    }

    [Fact]
    public void AdjustToOutside_PreservesTheGlobalPosition()
    {
        Gen<(int Bx, int By, int Mx, int My)> cases =
            from blockX in Gen.Choose(1, 253)
            from blockY in Gen.Choose(1, 253)
            from milliX in Gen.Choose(-190_000, 380_000)
            from milliY in Gen.Choose(-190_000, 380_000)
            select (blockX, blockY, milliX, milliY);
        PropertyAssert.Holds(Cfg, Prop.ForAll(cases.ToArbitrary(), c =>
            {
                (int bx, int by, int mx, int my) = c;
                uint id = ((uint)bx << 24) | ((uint)by << 16) | 1u;
                var loc = new Vector3(mx / 1000f, my / 1000f, 0f);
                double gx = bx * 192.0 + loc.X, gy = by * 192.0 + loc.Y;
                if (!LandDefs.AdjustToOutside(ref id, ref loc))
                {
                    return false;
                }

                double nx = (id >> 24) * 192.0 + loc.X, ny = ((id >> 16) & 0xFF) * 192.0 + loc.Y;
                return loc.X >= 0f && loc.X < 192f && loc.Y >= 0f && loc.Y < 192f
                       && Math.Abs(nx - gx) < 1e-3 && Math.Abs(ny - gy) < 1e-3
                       && LandDefs.IsOutdoorCell(id);
            }));
    }
}
