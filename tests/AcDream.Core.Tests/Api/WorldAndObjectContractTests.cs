using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// Silent mistakes at the world and object API (issue #23): a clock in milliseconds, an object entered without a part array,
/// two objects of one id, and the causes of a refused <see cref="PhysicsObj.SetParent"/>.
/// </summary>
public sealed class WorldAndObjectContractTests
{
    private const int Bx = 0x80;
    private const int By = 0x80;

    // Flat landblock 0x8080 at index 10 of the one-metre table: the ground is the plane z = 10.
    private static TerrainWorld Flat() => SyntheticTerrain.FlatBlock(Bx, By, 10);

    private static Position Spawn(TerrainWorld terrain) => SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(Bx, By, 4, 4), 100f, 100f);

    // ---- 1. A clock in milliseconds ----

    [Fact]
    public void ClockInMilliseconds_EveryFrameIsDiscarded_AndCounted()
    {
        // 60 fps with the clock in ms: each frame is 16.7 "seconds", above HugeQuantum (2 s): update_object discards it
        // (update_time = now) and the walker never moves. Retail behaviour stays; the world counts the discarded frames.
        var world = new PhysicsWorld();
        PhysicsObj walker = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        walker.SetVelocity(new Vector3(0f, 1f, 0f));
        Assert.Equal(0L, world.DiscardedFrames);
        Assert.Equal(0.0, world.LastDiscardedFrameSeconds);
        for (int frame = 1; frame <= 10; frame++)
        {
            world.Tick(frame * 16.7);
        }

        Assert.Equal(new Vector3(10f, 10f, 0f), walker.Position.Frame.Origin);
        Assert.Equal(10L, world.DiscardedFrames);
        Assert.Equal(10 * 16.7 - 9 * 16.7, world.LastDiscardedFrameSeconds);
    }

    [Fact]
    public void ClockInSeconds_NoFrameIsDiscarded_AndAGapOfExactlyHugeQuantumIsKept()
    {
        var world = new PhysicsWorld();
        PhysicsObj walker = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        walker.SetVelocity(new Vector3(0f, 1f, 0f));
        for (int frame = 1; frame <= 10; frame++)
        {
            world.Tick(frame * 0.0167);
        }

        // 2 s exactly is not above HugeQuantum: ten 0.2 s steps.
        world.Tick(10 * 0.0167 + 2.0);
        Assert.Equal(0L, world.DiscardedFrames);
        Assert.True(walker.Position.Frame.Origin.Y > 12f);
    }

    [Fact]
    public void ClockGoingBack_IsCountedAsADiscardedFrame_WithItsNegativeLength()
    {
        // CPhysics::UseTime resyncs last_update to a clock that went back; the (negative) frame is discarded.
        var world = new PhysicsWorld();
        TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        world.Tick(1.0);
        Assert.Equal(0L, world.DiscardedFrames);

        Assert.False(world.Tick(0.5));

        Assert.Equal(1L, world.DiscardedFrames);
        Assert.Equal(-0.5, world.LastDiscardedFrameSeconds);
        Assert.Equal(0.5, world.LastUpdate);
    }

    [Fact]
    public void AGapAboveHugeQuantum_IsCounted_WithItsLength()
    {
        var world = new PhysicsWorld();
        TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        world.Tick(0.05);
        Assert.True(world.Tick(5.05));
        Assert.Equal(1L, world.DiscardedFrames);
        Assert.Equal(5.05 - 0.05, world.LastDiscardedFrameSeconds);
        world.Tick(5.10);
        Assert.Equal(1L, world.DiscardedFrames);
    }

    // ---- 2. EnterWorld without a part array ----

    [Fact]
    public void EnterWorld_WithoutAPartArray_ReturnsFalse_AndChangesNothing()
    {
        // Retail's enter_cell does nothing for an object without a part array: it could never be placed in a cell.
        TerrainWorld terrain = Flat();
        var world = new PhysicsWorld(terrain);
        PhysicsObj obj = world.CreateObject(1);

        Assert.False(obj.EnterWorld(Spawn(terrain)));

        Assert.Equal(0u, obj.CellId);
        Assert.Equal(new Position(0, Frame.Identity), obj.Position);
        Assert.False(obj.IsActive);
    }

    [Fact]
    public void EnterWorld_WithAPartArray_ReturnsTrue_AndIsInACell()
    {
        TerrainWorld terrain = Flat();
        var world = new PhysicsWorld(terrain);
        PhysicsObj obj = world.CreateObject(1);
        obj.PartArray = new SimplePartArray(1, 1);

        Assert.True(obj.EnterWorld(Spawn(terrain)));

        Assert.NotEqual(0u, obj.CellId);
    }

    [Fact]
    public void EnterWorld_WithAParent_ReturnsFalse()
    {
        var world = new PhysicsWorld();
        PhysicsObj parent = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), id: 1);
        PhysicsObj child = world.CreateObject(2);
        child.PartArray = new SimplePartArray(1, 1);
        Assert.True(child.SetParent(parent, 0, Frame.Identity));

        Assert.False(child.EnterWorld(new Position(TickTestContext.OutdoorCell, new Vector3(5f, 5f, 0f))));
    }

    [Fact]
    public void BoolReturns_SayWhatTheDocsSay()
    {
        // SetParent: true when attached, false when the parent already holds the child (nothing changes).
        var world = new PhysicsWorld();
        PhysicsObj parent = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), id: 1);
        PhysicsObj child = TickTestContext.CreateObject(world, new Vector3(12f, 10f, 0f), id: 2);
        Assert.True(child.SetParent(parent, 0, Frame.Identity));
        Assert.False(child.SetParent(parent, 0, Frame.Identity));
        Assert.Equal(1, parent.Children!.Count);

        // SetActive: false only when activation is refused (a STATIC object); deactivation answers true.
        PhysicsObj still = TickTestContext.CreateObject(world, new Vector3(14f, 10f, 0f), id: 3);
        Assert.True(still.SetActive(false));
        still.SetState(still.State | PhysicsState.Static);
        Assert.False(still.SetActive(true));
        Assert.False(still.IsActive);

        // Tick / UseTime: false below MinQuantum (nothing runs), true once objects were visited.
        Assert.False(world.Tick(0.01));
        Assert.True(world.Tick(0.05));
    }

    // ---- 4. Two objects with one id ----

    [Fact]
    public void CreateObject_WithAnIdInUse_IsRefused_NamingTheId()
    {
        var world = new PhysicsWorld();
        PhysicsObj first = world.CreateObject(0x50000001);

        var e = Assert.Throws<ArgumentException>(() => world.CreateObject(0x50000001));

        Assert.Contains("0x50000001", e.Message, StringComparison.Ordinal);
        Assert.Equal("id", e.ParamName);
        Assert.Equal(1, world.ObjectCount);
        Assert.Same(first, world.GetObjectById(0x50000001));
    }

    [Fact]
    public void CreateObject_IdOfARemovedObject_IsFree_AndIdZeroRepeats()
    {
        var world = new PhysicsWorld();
        PhysicsObj first = world.CreateObject(7);
        world.RemoveObject(first);
        PhysicsObj again = world.CreateObject(7);
        Assert.Same(again, world.GetObjectById(7));

        world.CreateObject();
        world.CreateObject();
        Assert.Equal(3, world.ObjectCount);
        Assert.Null(world.GetObjectById(0));
    }

    // ---- 6. SetParent names the cause ----

    [Fact]
    public void SetParent_Self_NamesTheCause()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), id: 1);

        var e = Assert.Throws<ArgumentException>(() => a.SetParent(a, 0, Frame.Identity));

        Assert.Equal("parent", e.ParamName);
        Assert.StartsWith("An object cannot be its own parent.", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void SetParent_FromAnotherWorld_NamesTheCause()
    {
        var world = new PhysicsWorld();
        var other = new PhysicsWorld();
        PhysicsObj a = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), id: 1);
        PhysicsObj b = TickTestContext.CreateObject(other, new Vector3(10f, 10f, 0f), id: 2);

        var e = Assert.Throws<ArgumentException>(() => a.SetParent(b, 0, Frame.Identity));

        Assert.Equal("parent", e.ParamName);
        Assert.StartsWith("The parent belongs to another world.", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void SetParent_ARemovedParent_NamesTheCause()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), id: 1);
        PhysicsObj b = TickTestContext.CreateObject(world, new Vector3(12f, 10f, 0f), id: 2);
        world.RemoveObject(b);

        var e = Assert.Throws<ArgumentException>(() => a.SetParent(b, 0, Frame.Identity));

        Assert.Equal("parent", e.ParamName);
        Assert.StartsWith("The parent was removed from its world.", e.Message, StringComparison.Ordinal);
        Assert.Null(a.Parent);
        Assert.NotEqual(0u, a.CellId);
    }

    [Fact]
    public void SetParent_ZeroQuaternionFrame_NamesTheCause()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), id: 1);
        PhysicsObj b = TickTestContext.CreateObject(world, new Vector3(12f, 10f, 0f), id: 2);

        var e = Assert.Throws<ArgumentException>(() => a.SetParent(b, 0, default));

        Assert.Equal("frame", e.ParamName);
        Assert.StartsWith("The child frame must have a unit quaternion", e.Message, StringComparison.Ordinal);
        Assert.Null(a.Parent);
    }

    [Fact]
    public void SetParent_OffsetBeyondMaxChildOffset_NamesTheCause()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), id: 1);
        PhysicsObj b = TickTestContext.CreateObject(world, new Vector3(12f, 10f, 0f), id: 2);

        var e = Assert.Throws<ArgumentException>(() => a.SetParent(b, 0, new Frame(new Vector3(193f, 0f, 0f), Quaternion.Identity)));

        Assert.Equal("frame", e.ParamName);
        Assert.Contains("192 m", e.Message, StringComparison.Ordinal);
    }
}
