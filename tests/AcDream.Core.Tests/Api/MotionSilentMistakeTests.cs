using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The motion API's silent mistakes (issue #23): each was accepted without a word and did something other than asked.
/// </summary>
public sealed class MotionSilentMistakeTests
{
    // default(MovementParameters) is all zeros (speed 0, no flags): DoMotion returned 0 and nothing moved. It is refused.
    [Fact]
    public void DefaultMovementParameters_AreRefused_AtEveryEntry_AndNothingChanges()
    {
        var (obj, mm, mi, table) = MotionFixture.Create(new PlayerWeenie());
        MovementParameters zero = default;
        int pending = mi.PendingMotions.Count;
        bool autonomous = obj.LastMoveWasAutonomous;

        AssertRefused(() => mm.DoMotion(MotionCommand.WalkForward, zero));
        AssertRefused(() => mm.StopMotion(MotionCommand.WalkForward, zero));
        AssertRefused(() => mm.DoInterpretedMotion(MotionCommand.WalkForward, zero));
        AssertRefused(() => mm.StopInterpretedMotion(MotionCommand.WalkForward, zero));
        AssertRefused(() => mi.DoMotion(MotionCommand.WalkForward, zero));
        AssertRefused(() => mi.StopMotion(MotionCommand.WalkForward, zero));
        AssertRefused(() => mi.DoInterpretedMotion(MotionCommand.WalkForward, zero));
        AssertRefused(() => mi.StopInterpretedMotion(MotionCommand.WalkForward, zero));
        AssertRefused(() => mi.RawState.ApplyMotion(MotionCommand.WalkForward, zero));
        AssertRefused(() => mi.InterpretedState.ApplyMotion(MotionCommand.WalkForward, zero));

        Assert.Equal(pending, mi.PendingMotions.Count);
        Assert.Equal(autonomous, obj.LastMoveWasAutonomous);
        Assert.Equal(MotionCommand.Ready, mi.RawState.ForwardCommand);
        Assert.Equal(MotionCommand.Ready, mi.InterpretedState.ForwardCommand);
        Assert.Equal(System.Numerics.Vector3.Zero, table.Velocity);

        // new MovementParameters() is retail's defaults and walks: 3.12 m/s at speed 1.
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, new MovementParameters()));
        Assert.Equal(3.12f, table.Velocity.Y);
    }

    [Fact]
    public void MovementParameters_WithOneFieldSet_AreNotTheDefault()
    {
        // Zero speed or no flags alone are legal values (a caller may stop a motion at speed 0, or ask for no state
        // change): only all fields zero is refused.
        var (_, mm, _, _) = MotionFixture.Create(new PlayerWeenie());
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, new MovementParameters { Speed = 0f }));
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, new MovementParameters { Speed = 0.5f, Flags = 0 }));
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, default(MovementParameters) with { Speed = 1f }));
    }

    private static void AssertRefused(Action a)
    {
        var e = Assert.Throws<ArgumentException>(a);
        Assert.Contains("default(MovementParameters) is all zeros; use new MovementParameters() for retail's defaults", e.Message);
    }

    // A part array without a motion table: SetupIssues said None, yet DoMotion(WalkForward) moved 0 m.
    [Fact]
    public void PartArrayWithoutAMotionTable_IsReported_AndWithOneNot()
    {
        TerrainWorld terrain = SyntheticTerrain.Metres();
        SyntheticTerrain.AddBlock(terrain, 0x80, 0x80, (_, _) => 10);
        var world = new PhysicsWorld(terrain);

        PhysicsObj without = world.CreateObject(1);
        without.PartArray = new SimplePartArray(SetupPhysics.Human);
        Assert.True(without.EnterWorld(SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(0x80, 0x80, 4, 4), 100f, 100f)));
        world.Player = without;
        without.Weenie = new PlayerWeenie();
        Assert.Equal(ObjectSetupIssues.NoMotionTable, without.SetupIssues);

        PhysicsObj with = world.CreateObject(2);
        with.PartArray = new SimplePartArray(SetupPhysics.Human) { MotionPlayer = new SpeedOnlyMotionPlayer() };
        Assert.True(with.EnterWorld(SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(0x80, 0x80, 4, 4), 110f, 100f)));
        with.GetOrCreateMotionInterpreter();
        with.Weenie = RemoteCreatureWeenie.Creature;
        Assert.Equal(ObjectSetupIssues.None, with.SetupIssues);

        // A client's own movement manager drives the body itself: no motion table is needed.
        PhysicsObj own = world.CreateObject(3);
        own.PartArray = new SimplePartArray(SetupPhysics.Human);
        own.Movement = new BasicMovementManager();
        Assert.True(own.EnterWorld(SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(0x80, 0x80, 4, 4), 120f, 100f)));
        Assert.Equal(ObjectSetupIssues.None, own.SetupIssues);
    }

    // Jump(5) jumped as extent 1 (get_jump_v_z clamps) but charged stamina for 5: ceil((0 + 0.5) * 5 * 8 + 2) = 22 against
    // ceil((0 + 0.5) * 1 * 8 + 2) = 6. Retail's only caller (ClientCombatSystem::DoJump) passes the power bar's level, within
    // [0, 1]; an extent outside it is refused.
    [Theory]
    [InlineData(5f)]
    [InlineData(1.0001f)]
    [InlineData(-0.5f)]
    public void Jump_ExtentOutsideZeroToOne_IsRefused_AndNothingChanges(float extent)
    {
        var (obj, _, mi, _) = MotionFixture.Create(new PlayerWeenie { JumpSkill = 100, Strength = 100 }, gravity: true);
        MotionFixture.SetOnGround(obj);
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => mi.Jump(extent, out _));
        Assert.Equal("extent", e.ParamName);
        Assert.Throws<ArgumentOutOfRangeException>(() => mi.JumpIsAllowed(extent, out _));
        Assert.True(MotionInterp.OnGround(obj));
        Assert.Equal(0f, mi.JumpExtent);
    }

    [Theory]
    // Load 0 (burden 0): cost ceil(0.5 * extent * 8 + 2): extent 1 -> 6, 0.5 -> 4, 0 -> 2.
    [InlineData(1f, 6)]
    [InlineData(0.5f, 4)]
    [InlineData(0f, 2)]
    public void Jump_InRange_ChargesTheStaminaOfItsExtent(float extent, int cost)
    {
        var (obj, _, mi, _) = MotionFixture.Create(new PlayerWeenie { JumpSkill = 100, Strength = 100 }, gravity: true);
        MotionFixture.SetOnGround(obj);
        Assert.Equal(MotionError.None, mi.Jump(extent, out int charged));
        Assert.Equal(cost, charged);
    }
}
