using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>
/// Shared scene for the manager tests: a world on <see cref="ReplayGroundSweep"/>, a player at the landblock centre and a
/// creature (one collision sphere, radius 0.5 m) standing on the ground, both outdoors in landblock 0x7F7F.
/// </summary>
public sealed class ManagerScene
{
    /// <summary>Landblock used by the scenes (its cell 1 is the south-west 24 m cell).</summary>
    public const uint Block = 0x7F7F0000u;

    /// <summary>Creates the scene with the creature at <paramref name="creatureOrigin"/> (landblock-local) facing
    /// <paramref name="creatureHeading"/>, and the player at <paramref name="playerOrigin"/> (default the block centre).</summary>
    public ManagerScene(Vector3 creatureOrigin, float creatureHeading = 0f, double startTime = 0.0, Vector3? playerOrigin = null)
    {
        World = new PhysicsWorld(startTime);
        Ground = new ReplayGroundSweep();
        World.Sweep = Ground;
        Player = World.CreateObject(1);
        Player.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        Player.EnterWorld(At(playerOrigin ?? new Vector3(96f, 96f, 0f)));
        World.Player = Player;
        CreatureParts = new SimplePartArray(1, 1) { Radius = 0.5f, Height = 1.8f };
        Creature = World.CreateObject(2);
        Creature.PartArray = CreatureParts;
        Creature.EnterWorld(At(creatureOrigin, creatureHeading));
        Ground.FailPlacements = false;
    }

    /// <summary>The world.</summary>
    public PhysicsWorld World { get; }

    /// <summary>The ground seam (placement counter, failure switch).</summary>
    public ReplayGroundSweep Ground { get; }

    /// <summary>The player.</summary>
    public PhysicsObj Player { get; }

    /// <summary>The remote creature.</summary>
    public PhysicsObj Creature { get; }

    /// <summary>The creature's part array (root-motion velocity).</summary>
    public SimplePartArray CreatureParts { get; }

    /// <summary>A position in landblock 0x7F7F at <paramref name="origin"/> (may lie outside the block; re-homed to the outdoor
    /// cell that contains it) facing <paramref name="heading"/> degrees.</summary>
    public static Position At(Vector3 origin, float heading = 0f)
    {
        var p = new Position(Block | 1u, Frame.FromHeading(origin, heading));
        p.TryAdjustToOutside();
        return p;
    }

    /// <summary>The creature's position manager, created on demand.</summary>
    public PositionManager Managers => Creature.MakePositionManager();

    /// <summary>The creature's interpolation manager (created by queuing nothing: via <see cref="PositionManager.InterpolateTo"/>
    /// only), or null.</summary>
    public InterpolationManager? Interpolation => Creature.PositionManager?.InterpolationManager;

    /// <summary>Landblock-global origin of <paramref name="p"/> relative to block 0x7F7F.</summary>
    public static Vector3 GlobalOf(in Position p)
    {
        Position b = At(Vector3.Zero);
        b.ObjCellId = Block | 1u;
        b.Frame = Frame.Identity;
        return b.GetOffset(p);
    }
}
