using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Tests.Support;

/// <summary>A weenie with a fixed run rate (and the player's other answers), for state-velocity tests.</summary>
internal sealed class FixedRateWeenie(float rate, bool isThePlayer = true) : IMotionWeenie
{
    public bool IsThePlayer { get; } = isThePlayer;
    public bool IsCreature => true;
    public bool IsPlayer => true;
    public bool IsImpenetrable => false;
    public bool IsPK => false;
    public bool IsPKLite => false;

    public bool InqRunRate(out float r)
    {
        r = rate;
        return true;
    }

    public bool InqJumpVelocity(float extent, out float vz)
    {
        vz = 5f;
        return true;
    }

    public bool CanJump(float extent) => true;

    public bool JumpStaminaCost(float extent, out int cost)
    {
        cost = 1;
        return true;
    }
}

/// <summary>An object with a motion table and the retail movement manager, not in the world (no cell).</summary>
internal static class MotionFixture
{
    /// <summary>Creates the object; <paramref name="gravity"/> false clears GRAVITY so every motion may start
    /// (contact_allows_move), true keeps retail's default state (then the object is in the air until placed).</summary>
    public static (PhysicsObj Obj, MovementManager Mm, MotionInterp Mi, SpeedOnlyMotionPlayer Table) Create(
        IMotionWeenie? weenie, bool gravity = false)
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject(1);
        obj.Weenie = weenie;
        var table = new SpeedOnlyMotionPlayer();
        obj.PartArray = new SimplePartArray(1, 0) { MotionPlayer = table };
        if (!gravity)
        {
            obj.SetState((PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.Gravity);
        }

        MovementManager mm = MovementManager.Of(obj);
        return (obj, mm, mm.GetOrCreateMotionInterpreter(), table);
    }

    /// <summary>Puts the object on the ground (CONTACT and ON_WALKABLE) without a sweep.</summary>
    public static void SetOnGround(PhysicsObj obj)
    {
        obj._transientState |= TransientState.Contact;
        obj.SetOnWalkable(true);
    }

    /// <summary>Parameters with the given speed and hold key (retail's defaults otherwise).</summary>
    public static MovementParameters Params(float speed = 1f, HoldKey key = HoldKey.Invalid) =>
        new() { Speed = speed, HoldKeyToApply = key };
}
