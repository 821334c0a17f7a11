using System.Numerics;
using AcDream.Core.Fixtures.Wire;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.WorldSceneEntries;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// A server's CreateObject (0xF745) made through the object-from-data door (issue #37 on #35): the handler's factory is
/// <see cref="ObjectFactory.MakeObject(PhysicsWorld, uint, PhysicsDesc)"/>, so the object gets the parts of its Setup
/// (<c>CPhysicsObj::makeObject(setup_id, object_id, 1)</c>) and enters the world at the description's position.
/// </summary>
public class CreateObjectFromSetupTests
{
    private const uint Id = 0x50000001;

    private static byte[] Create(uint setup) =>
        PhysicsMessageBytes.PhysicsDesc(PhysicsMessageBytes.CreateObjectStart(Id), 0x400C08,
            new PhysicsMessageBytes.Stamps(Position: 1, Instance: 1),
            position: (BspScene.OutdoorCell(100f, 100f), new Vector3(100f, 100f, BspScene.Ground), Quaternion.Identity),
            setup: setup).ToArray();

    [Fact]
    public void ACreature_FromItsSetupId_HasTheSetupsShape_AtItsPosition()
    {
        PhysicsWorld world = World(out _);
        var loader = new WorldLoader(world, Source([]));
        loader.Load(Block);
        var handler = new ServerMessageHandler(world) { ObjectFactory = loader.Objects.MakeObject };
        Assert.Equal(ServerMessageResult.Applied, handler.HandleMessage((uint)PhysicsMessageOpcode.CreateObject, Create(Pine)));
        PhysicsObj o = world.GetObjectById(Id)!;
        // The pine-like Setup: one cylinder of radius 1.53 (its Setup radius 1.53), dynamic (not STATIC).
        Assert.Equal(1.53f, o.Radius);
        Assert.False(o.State.HasFlag(PhysicsState.Static));
        Assert.Equal(BspScene.OutdoorCell(100f, 100f), o.CellId);
        Assert.Equal((100f, 100f), (o.Position.Frame.Origin.X, o.Position.Frame.Origin.Y));
    }

    [Fact]
    public void ASetupMissingFromTheSource_IsNotApplicable_AndNothingIsAdded()
    {
        PhysicsWorld world = World(out _);
        var loader = new WorldLoader(world, Source([]));
        loader.Load(Block);
        int before = world.ObjectCount;
        var handler = new ServerMessageHandler(world) { ObjectFactory = loader.Objects.MakeObject };
        Assert.Equal(ServerMessageResult.NotApplicable,
            handler.HandleMessage((uint)PhysicsMessageOpcode.CreateObject, Create(0x02000999)));
        Assert.Null(world.GetObjectById(Id));
        Assert.Equal(before, world.ObjectCount);
        Assert.Contains(0x02000999u, loader.Objects.MissingIds);
    }
}
