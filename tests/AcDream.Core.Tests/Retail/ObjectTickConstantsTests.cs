using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>Pins the enum values, object defaults and profile constants of the object tick to the decompilation.</summary>
public class ObjectTickConstantsTests
{
    private static int Bits(float f) => BitConverter.SingleToInt32Bits(f);

    [Fact]
    public void PhysicsState_ValuesAreRetail_AcclientH2815()
    {
        Assert.Equal(0x1u, (uint)PhysicsState.Static);
        Assert.Equal(0x4u, (uint)PhysicsState.Ethereal);
        Assert.Equal(0x8u, (uint)PhysicsState.ReportCollisions);
        Assert.Equal(0x100u, (uint)PhysicsState.AlignPath);
        Assert.Equal(0x400u, (uint)PhysicsState.Gravity);
        Assert.Equal(0x800u, (uint)PhysicsState.LightingOn);
        Assert.Equal(0x1000u, (uint)PhysicsState.ParticleEmitter);
        Assert.Equal(0x4000u, (uint)PhysicsState.Hidden);
        Assert.Equal(0x20000u, (uint)PhysicsState.Inelastic);
        Assert.Equal(0x400000u, (uint)PhysicsState.EdgeSlide);
        Assert.Equal(0x800000u, (uint)PhysicsState.Sledding);
        // The bit tested first in update_object (0x1000000) is FROZEN, not hidden.
        Assert.Equal(0x1000000u, (uint)PhysicsState.Frozen);
    }

    [Fact]
    public void TransientState_ValuesAreRetail_AcclientH3688()
    {
        Assert.Equal(0x1u, (uint)TransientState.Contact);
        Assert.Equal(0x2u, (uint)TransientState.OnWalkable);
        Assert.Equal(0x4u, (uint)TransientState.Sliding);
        Assert.Equal(0x8u, (uint)TransientState.WaterContact);
        Assert.Equal(0x10u, (uint)TransientState.StationaryFall);
        Assert.Equal(0x20u, (uint)TransientState.StationaryStop);
        Assert.Equal(0x40u, (uint)TransientState.StationaryStuck);
        Assert.Equal(0x80u, (uint)TransientState.Active);
        Assert.Equal(0x100u, (uint)TransientState.CheckEthereal);
    }

    [Fact]
    public void HookTypes_AreProcessFpHookCases_Acclient320571()
    {
        Assert.Equal(0, (int)PhysicsHookType.Scale);
        Assert.Equal(1, (int)PhysicsHookType.Translucency);
        Assert.Equal(2, (int)PhysicsHookType.PartTranslucency);
        Assert.Equal(3, (int)PhysicsHookType.Luminosity);
        Assert.Equal(4, (int)PhysicsHookType.Diffusion);
        Assert.Equal(5, (int)PhysicsHookType.PartLuminosity);
        Assert.Equal(6, (int)PhysicsHookType.PartDiffusion);
        Assert.Equal(7, (int)PhysicsHookType.CallPes);
    }

    [Fact]
    public void SetPositionFlagsAndErrors_AreRetail()
    {
        // SetPositionSimple passes 4098 = 0x1002 (TELEPORT | SEND_POSITION_EVENT) or 4114 = 0x1012 (+ SLIDE), acclient.c:323420.
        Assert.Equal(4098u, (uint)(SetPositionFlags.Teleport | SetPositionFlags.SendPositionEvent));
        Assert.Equal(4114u, (uint)(SetPositionFlags.Teleport | SetPositionFlags.SendPositionEvent | SetPositionFlags.Slide));
        Assert.Equal(3, (int)SetPositionError.NoCell);
        Assert.Equal(0x100, (int)SetPositionError.InvalidArguments);
    }

    [Fact]
    public void NewObject_HasConstructorDefaults_Acclient319489()
    {
        var world = new PhysicsWorld();
        PhysicsObj obj = world.CreateObject(7);
        Assert.Equal(0x400C08u, (uint)obj.State); // 4197384 = EDGE_SLIDE | LIGHTING_ON | GRAVITY | REPORT_COLLISIONS
        Assert.Equal(TransientState.None, obj.TransientState);
        Assert.Equal(0x7F7FFFFF, Bits(obj.PlayerDistance)); // FLT_MAX
        Assert.Equal(new Vector3(0f, 0f, 1f), obj.PlayerVector);
        Assert.Equal(0x3F733333, Bits(obj.Friction)); // DEFAULT_FRICTION 0.95f
        Assert.Equal(0x3D4CCCCD, Bits(obj.Elasticity)); // DEFAULT_ELASTICITY 0.05f
        Assert.Equal(0f, obj.Translucency);
        Assert.Equal(1f, obj.MassInv);
        Assert.Equal(1f, obj.Scale);
        Assert.Equal(0u, obj.CellId);
        Assert.Null(obj.PositionManager);
        Assert.Null(obj.Movement);
        Assert.Null(obj.PartArray);
    }

    [Fact]
    public void Profiles_RetailSlices0Point2_AceSlices0Point1_BothGateAtAThirtieth()
    {
        Assert.False(PhysicsProfile.Retail.AccumulateBelowMinQuantum);
        Assert.Equal(0.2, PhysicsProfile.Retail.MaxQuantum);
        Assert.Equal(1.0 / 30.0, PhysicsProfile.Retail.MinQuantum);
        Assert.Equal(2.0, PhysicsProfile.Retail.HugeQuantum);
        Assert.True(PhysicsProfile.AceCompatible.AccumulateBelowMinQuantum);
        Assert.Equal(0.1, PhysicsProfile.AceCompatible.MaxQuantum);
        Assert.Equal(1.0 / 30.0, PhysicsProfile.AceCompatible.MinQuantum);
        Assert.Equal("Retail", PhysicsProfile.Retail.ToString());
        Assert.Same(PhysicsProfile.Retail, new PhysicsWorld().Profile);
    }

    [Fact]
    public void SleddingSteepCos_IsCosTenDegreesInDouble()
    {
        // calc_friction compares against cos(10 deg) = 0.98480775301220802, evaluated in double (the argument's bits are
        // pinned in AngleConstantsTests).
        Assert.Equal(0.984807753012208, PhysicsObj.SleddingSteepCos, 15);
    }

    [Fact]
    public void AutonomyAndConstraintDistances_AreRetail()
    {
        var world = new PhysicsWorld();
        PhysicsObj outdoor = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        PhysicsObj indoor = world.CreateObject();
        indoor.StorePosition(new Position(0xA9B40105u, new Vector3(1f, 1f, 1f)));
        Assert.Equal(100.0, outdoor.AutonomyBlipDistance);
        Assert.Equal(20.0, indoor.AutonomyBlipDistance);
        world.Player = indoor;
        Assert.Equal(25.0, indoor.AutonomyBlipDistance);
        Assert.Equal(10.0, outdoor.StartConstraintDistance);
        Assert.Equal(5.0, indoor.StartConstraintDistance);
        Assert.Equal(50.0, outdoor.MaxConstraintDistance);
        Assert.Equal(20.0, indoor.MaxConstraintDistance);
    }

    [Fact]
    public void GetOrCreateMotionInterpreter_CreatesAMovementManager_WithRetailNoWeenieSpeed4_AndActivates()
    {
        // get_minterp (acclient.c:319279) creates the movement manager when absent; CMotionInterp::get_max_speed
        // (acclient.c:343485) returns 1.0 * 4.0 when there is no weenie object.
        var world = new PhysicsWorld(3.0);
        PhysicsObj obj = world.CreateObject();
        IMotionInterpreter? minterp = obj.GetOrCreateMotionInterpreter();
        Assert.NotNull(minterp);
        Assert.IsType<AcDream.Core.Physics.Motion.MovementManager>(obj.Movement);
        Assert.IsType<AcDream.Core.Physics.Motion.MotionInterp>(minterp);
        Assert.Equal(4.0, minterp!.MaxSpeed);
        Assert.Equal(4.0, minterp.AdjustedMaxSpeed);
        Assert.Equal(4.0, BasicMovementManager.NoWeenieMaxSpeed);
        Assert.True(obj.IsActive);
        Assert.Equal(3.0, obj.UpdateTime);
        Assert.Same(minterp, obj.GetOrCreateMotionInterpreter()); // created once
    }
}
