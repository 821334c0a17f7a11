using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using Xunit;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// The misuse suite's span members (a span cannot be passed through reflection), called directly with every bad sphere and
/// cylinder sphere: refused with the state unchanged, or accepted and then 30 ticks that neither throw nor leave a NaN.
/// </summary>
public class SpanInputsTests
{
    public static TheoryData<string> BadSpheres()
    {
        var d = new TheoryData<string>();
        var s = new MisuseScene();
        BadValues.TryGood(typeof(Sphere), s, out object? good);
        foreach ((string label, object? _) in BadValues.For(typeof(Sphere), good))
        {
            d.Add(label);
        }

        return d;
    }

    private static Sphere Bad(string label)
    {
        BadValues.TryGood(typeof(Sphere), null, out object? good);
        foreach ((string l, object? v) in BadValues.For(typeof(Sphere), good))
        {
            if (l == label)
            {
                return (Sphere)v!;
            }
        }

        throw new ArgumentException(label);
    }

    private static void Check(MisuseScene s, Action call, string what)
    {
        PublicState before = PublicState.Capture(s);
        try
        {
            call();
        }
        catch (ArgumentException)
        {
            Assert.True(PublicState.Diff(before, PublicState.Capture(s)).Count == 0, what + ": refused but changed the state");
            return;
        }

        s.Tick(30);
        Assert.True(PublicState.Capture(s).NonFinite.Count == 0, what + ": accepted and left a non-finite value");
    }

    [Theory]
    [MemberData(nameof(BadSpheres))]
    public void SetSpheres_BadSphere(string label)
    {
        var s = new MisuseScene();
        Sphere b = Bad(label);
        Check(s, () => s.WalkerParts.SetSpheres([b]), "SetSpheres " + label);
    }

    [Theory]
    [MemberData(nameof(BadSpheres))]
    public void SetCylSpheres_BadCylinder(string label)
    {
        var s = new MisuseScene();
        Sphere b = Bad(label);
        Check(s, () => s.WalkerParts.SetCylSpheres([new CylSphere(b.Center, b.Radius, 1f)]), "SetCylSpheres " + label);
        Check(s, () => s.WalkerParts.SetCylSpheres([new CylSphere(Vector3.Zero, 0.5f, b.Radius)]), "SetCylSpheres height " + label);
    }

    public static TheoryData<string> BadPartInputs()
    {
        var d = new TheoryData<string>();
        foreach (string l in new[] { "scale 0", "scale -1", "scale subnormal", "scale 1e30", "scale NaN", "frame default",
                     "frame origin 1e30", "frame origin 192.0001", "frame NaN quaternion" })
        {
            d.Add(l);
        }

        return d;
    }

    [Theory]
    [MemberData(nameof(BadPartInputs))]
    public void SetPhysicsParts_BadFrameOrScale_IsRefused(string label)
    {
        // Part scales have the object scale's domain per component ([0.01, 100]); part frames the child frame's domain
        // (unit quaternion, offset within ±192 m).
        var s = new MisuseScene();
        var polys = new System.Collections.Generic.List<Polygon>();
        Support.BspScene.AddBox(polys, new Vector3(-0.5f, -0.5f, 0f), new Vector3(0.5f, 0.5f, 1.2f));
        var gfx = new Physics.Collision.Bsp.GfxObjPhysics(Physics.Collision.Bsp.BspBuilder.Build(polys.ToArray()));
        Physics.Spatial.Frame frame = Physics.Spatial.Frame.Identity;
        var scale = Vector3.One;
        switch (label)
        {
            case "scale 0": scale = new Vector3(1f, 0f, 1f); break;
            case "scale -1": scale = new Vector3(-1f); break;
            case "scale subnormal": scale = new Vector3(1e-45f); break;
            case "scale 1e30": scale = new Vector3(1f, 1f, 1e30f); break;
            case "scale NaN": scale = new Vector3(float.NaN); break;
            case "frame default": frame = default; break;
            case "frame origin 1e30": frame.Origin = new Vector3(1e30f, 0f, 0f); break;
            case "frame origin 192.0001": frame.Origin = new Vector3(0f, 192.0001f, 0f); break;
            case "frame NaN quaternion": frame.SetQuaternionRaw(float.NaN, 0f, 0f, 0f); break;
            default: throw new ArgumentException(label);
        }

        PublicState before = PublicState.Capture(s);
        Assert.ThrowsAny<ArgumentException>(() => s.WalkerParts.SetPhysicsParts([gfx], [frame], [scale]));
        Assert.Empty(PublicState.Diff(before, PublicState.Capture(s)));
        s.WalkerParts.SetPhysicsParts([gfx], [Physics.Spatial.Frame.Identity], [Vector3.One]); // the control: accepted
        Assert.Equal(1, s.WalkerParts.NumCollisionParts);
    }
}
