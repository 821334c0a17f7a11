using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>UpdatePhysicsInternal (acclient.c:317700), calc_acceleration (317786) and calc_friction (316090), step by step.</summary>
public class UpdatePhysicsInternalTests
{
    private const float Q = 0.0625f; // 1/16 s: exact in binary, so the hand arithmetic below is exact too

    private static PhysicsObj Airborne()
    {
        var world = new PhysicsWorld();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 100f));
        return obj;
    }

    private static PhysicsObj OnGround(Vector3 normal)
    {
        var world = new PhysicsWorld();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        TransitionResult t = TransitionResult.FreeSpace(obj.Position);
        t.ContactPlaneValid = true;
        t.ContactPlaneNormal = normal;
        obj.CommitTransition(t);
        return obj;
    }

    [Fact]
    public void OneStep_OriginGetsVTimesQPlusHalfAQSquared_VelocityGetsAQ()
    {
        PhysicsObj obj = Airborne();
        Assert.Equal(new Vector3(0f, 0f, PhysicsGlobals.Gravity), obj.Acceleration); // calc_acceleration: GRAVITY, no contact
        obj._velocity = new Vector3(1f, 2f, 3f);
        Frame f = Frame.Identity;
        obj.UpdatePhysicsInternal(Q, ref f);

        // x: v.x*q + (a.x*0.5*q)*q = 0.0625 + 0 ; y: 2*0.0625 = 0.125
        // z: (float)(3*0.0625) + (float)(-9.8000002*0.5) * q * q = 0.1875 - 4.9000001/256 = 0.1875 - 0.019140625...
        float halfAz = -4.9000001f;
        float dz = (float)(0.1875 + halfAz * (1.0 / 256.0));
        Assert.Equal(new Vector3(0.0625f, 0.125f, dz), f.Origin);
        // v += a*q: z = 3 + (-9.8000002 * 0.0625) = 3 - 0.61250001
        Assert.Equal(new Vector3(1f, 2f, (float)(3.0 + (double)PhysicsGlobals.Gravity * 0.0625)), obj.Velocity);
    }

    [Fact]
    public void FirstStepFromRest_DoesNotMoveOrigin_OnlyVelocityGainsGravity()
    {
        PhysicsObj obj = Airborne();
        Frame f = Frame.Identity;
        obj.UpdatePhysicsInternal(Q, ref f);
        // |v|^2 = 0: the integration branch is skipped (acclient.c:317700); only v += a*q runs.
        Assert.Equal(Vector3.Zero, f.Origin);
        Assert.Equal(new Vector3(0f, 0f, (float)((double)PhysicsGlobals.Gravity * 0.0625)), obj.Velocity);
    }

    [Fact]
    public void VelocityAbove50_IsClampedTo50BeforeIntegration()
    {
        PhysicsObj obj = Airborne();
        obj._velocity = new Vector3(0f, 0f, -80f); // 6400 > 2500
        Frame f = Frame.Identity;
        obj.UpdatePhysicsInternal(Q, ref f);
        // normalised (0,0,-1) * 50 -> -50; origin z = -50*0.0625 + (-4.9000001)/256 ; v = -50 - 0.61250001
        Assert.Equal((float)(-3.125 + (-4.9000001f) * (1.0 / 256.0)), f.Origin.Z);
        Assert.Equal((float)(-50.0 + (double)PhysicsGlobals.Gravity * 0.0625), obj.Velocity.Z);
    }

    [Fact]
    public void SetVelocity_Above50_IsScaledTo50_AndActivates()
    {
        PhysicsObj obj = Airborne();
        obj.SetActive(false);
        obj.SetVelocity(new Vector3(60f, 80f, 0f)); // |v| = 100 -> (0.6, 0.8, 0) * 50 = (30, 40, 0)
        Assert.Equal(30f, obj.Velocity.X, 4);
        Assert.Equal(40f, obj.Velocity.Y, 4);
        Assert.True(obj.IsActive);
        Assert.True(obj.JumpedThisFrame);
    }

    [Fact]
    public void VelocityUpdate_RoundsQuantumTimesAzToFloatBeforeAddingIt()
    {
        // acclient.c:317773: "result.z = quantum * a.z" is a float store (result is an AC1Legacy::Vector3), then
        // "v.z = result.z + v.z"; x and y keep quantum * a in double. Hand-worked with exact fractions:
        //   quantum = 0x3D088889 = 8947849/2^28 = 0.033333335071802139, a.z = -9.8f = 0xC11CCCCD = -10276045/2^20,
        //   v.z = 0xBEE7E086 = -7598147/2^24 = -0.45288485288619995.
        //   quantum * a.z = -0.32666669006149... (exact in double), as float 0xBEA740DB = -10961115/2^25 = -0.32666668295860291.
        //   0xBEA740DB + v.z = -0.77955153584480286, exactly halfway between 0xBF4790B0 (-0.77955150604248047) and
        //   0xBF4790B1 (-0.77955156564712524): ties to even gives 0xBF4790B0.
        //   Unrounded, -0.32666669006149 + v.z = -0.77955154294769 lies 7.1e-9 beyond the midpoint: 0xBF4790B1.
        // |v|² = 0.205 > 0.0625 + EPSILON, so the integration branch runs without zeroing v (the object is airborne: no friction).
        PhysicsObj obj = Airborne();
        float quantum = BitConverter.Int32BitsToSingle(0x3D088889);
        Assert.Equal(unchecked((int)0xC11CCCCD), BitConverter.SingleToInt32Bits(obj.Acceleration.Z));
        obj._velocity = new Vector3(0f, 0f, BitConverter.Int32BitsToSingle(unchecked((int)0xBEE7E086)));
        Frame f = Frame.Identity;
        obj.UpdatePhysicsInternal(quantum, ref f);
        Assert.Equal(unchecked((int)0xBF4790B0), BitConverter.SingleToInt32Bits(obj.Velocity.Z));
    }

    [Fact]
    public void SmallVelocity_BelowQuarterMetrePerSecond_IsZeroedButGravityStillMovesOrigin()
    {
        PhysicsObj obj = Airborne();
        obj._velocity = new Vector3(0.2f, 0f, 0f); // |v|^2 = 0.04; 0.04 - 0.0625 < EPSILON -> v = 0
        Frame f = Frame.Identity;
        obj.UpdatePhysicsInternal(Q, ref f);
        // Origin: v = 0 now, so only 0.5*a*q^2 in z; x does not move.
        Assert.Equal(0f, f.Origin.X);
        Assert.Equal((float)((-4.9000001f) * (1.0 / 256.0)), f.Origin.Z);
        Assert.Equal(new Vector3(0f, 0f, (float)((double)PhysicsGlobals.Gravity * 0.0625)), obj.Velocity);
    }

    [Fact]
    public void RestingOnWalkable_WithoutMovementManager_DeactivatesItself()
    {
        PhysicsObj obj = OnGround(new Vector3(0f, 0f, 1f));
        Assert.True(obj.IsActive);
        Assert.Equal(Vector3.Zero, obj.Acceleration); // CONTACT + ON_WALKABLE, not sledding: zero acceleration
        Frame f = Frame.Identity;
        obj.UpdatePhysicsInternal(Q, ref f);
        Assert.False(obj.IsActive);

        obj.SetActive(true);
        obj.Movement = new BasicMovementManager();
        obj.UpdatePhysicsInternal(Q, ref f);
        Assert.True(obj.IsActive); // a movement manager keeps it awake
    }

    [Fact]
    public void CalcAcceleration_ContactWalkable_ZeroesAccelerationAndOmega_UnlessSledding()
    {
        PhysicsObj obj = OnGround(new Vector3(0f, 0f, 1f));
        obj.SetOmega(new Vector3(0f, 0f, 1f));
        obj.CalcAcceleration();
        Assert.Equal(Vector3.Zero, obj.Acceleration);
        Assert.Equal(Vector3.Zero, obj.Omega);

        // The not-sledding condition (missing in ACE): a sledding object on the ground keeps gravity.
        obj.SetState(obj.State | PhysicsState.Sledding);
        obj.CalcAcceleration();
        Assert.Equal(new Vector3(0f, 0f, PhysicsGlobals.Gravity), obj.Acceleration);

        obj.SetState(obj.State & ~(PhysicsState.Sledding | PhysicsState.Gravity));
        obj.ClearTransientStates();
        Assert.Equal(Vector3.Zero, obj.Acceleration);
    }

    [Fact]
    public void Friction_OnWalkable_ScalesByOneMinusFToTheQuantum()
    {
        PhysicsObj obj = OnGround(new Vector3(0f, 0f, 1f));
        obj._velocity = new Vector3(4f, 0f, 0f);
        obj.CalcFriction(1.0f, 16f);
        // (1 - 0.95)^1 = 0.05 (0.95f = 0.949999988079071, so 1 - f = 0.050000011920929) -> 4 * 0.05000001 = 0.20000005
        Assert.Equal((float)(4.0 * Math.Pow(1.0 - 0.949999988079071, 1.0)), obj.Velocity.X);
        Assert.Equal(0.2f, obj.Velocity.X, 5);
    }

    [Fact]
    public void Friction_VelocityLeavingThePlane_IsNotApplied()
    {
        PhysicsObj obj = OnGround(new Vector3(0f, 0f, 1f));
        obj._velocity = new Vector3(4f, 0f, 0.3f); // v.N = 0.3 >= 0.25: no friction
        obj.CalcFriction(1.0f, 16.09f);
        Assert.Equal(new Vector3(4f, 0f, 0.3f), obj.Velocity);
    }

    [Fact]
    public void Friction_RemovesNormalComponentBelowQuarter()
    {
        PhysicsObj obj = OnGround(new Vector3(0f, 0f, 1f));
        obj.Friction = 0f; // isolate the projection: (1 - 0)^q = 1
        obj._velocity = new Vector3(4f, 0f, -2f); // v.N = -2 < 0.25: v -= (v.N) N
        obj.CalcFriction(1.0f, 20f);
        Assert.Equal(new Vector3(4f, 0f, 0f), obj.Velocity);
    }

    [Fact]
    public void SleddingFriction_FastOnSteepSlope_Is0Point2()
    {
        // N.z = 0.8 < cos 10 deg and |v|^2 = 9 >= 6.25: retail uses 0.2 (ACE inverts this test).
        PhysicsObj obj = OnGround(new Vector3(0.6f, 0f, 0.8f));
        obj.SetState(obj.State | PhysicsState.Sledding);
        obj._velocity = new Vector3(0f, 3f, 0f); // tangent: v.N = 0
        obj.CalcFriction(1.0f, 9f);
        Assert.Equal((float)(Math.Pow(1.0 - 0.2f, 1.0) * 3.0), obj.Velocity.Y); // 3 * 0.8 = 2.4
    }

    [Fact]
    public void SleddingFriction_SlowOrFlat_UsesObjectFriction_VerySlow_Stops()
    {
        PhysicsObj obj = OnGround(new Vector3(0.6f, 0f, 0.8f));
        obj.SetState(obj.State | PhysicsState.Sledding);
        obj._velocity = new Vector3(0f, 2f, 0f); // |v|^2 = 4: in [1.5625, 6.25) -> object friction 0.95
        obj.CalcFriction(1.0f, 4f);
        Assert.Equal((float)(Math.Pow(1.0 - 0.949999988079071, 1.0) * 2.0), obj.Velocity.Y);

        obj._velocity = new Vector3(0f, 1f, 0f); // |v|^2 = 1 < 1.5625: f = 1 -> pow(0, q) = 0
        obj.CalcFriction(1.0f, 1f);
        Assert.Equal(Vector3.Zero, obj.Velocity);

        PhysicsObj flat = OnGround(new Vector3(0f, 0f, 1f));
        flat.SetState(flat.State | PhysicsState.Sledding);
        flat._velocity = new Vector3(0f, 3f, 0f); // fast but N.z = 1 >= cos 10 deg -> object friction
        flat.CalcFriction(1.0f, 9f);
        Assert.Equal((float)(Math.Pow(1.0 - 0.949999988079071, 1.0) * 3.0), flat.Velocity.Y);
    }

    [Fact]
    public void Omega_RotatesFrameByOmegaTimesQuantum()
    {
        PhysicsObj obj = Airborne();
        obj.SetOmega(new Vector3(0f, 0f, 2f));
        Frame f = Frame.Identity;
        obj.UpdatePhysicsInternal(0.5f, ref f);
        // grotate by (0, 0, 1) rad: q = (cos 0.5, 0, 0, sin 0.5)
        Assert.Equal((float)Math.Cos(0.5), f.Qw, 6);
        Assert.Equal((float)Math.Sin(0.5), f.Qz, 6);
    }
}
