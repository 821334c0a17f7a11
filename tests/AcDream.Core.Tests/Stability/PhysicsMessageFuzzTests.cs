using System;
using System.Numerics;
using AcDream.Core.Fixtures.Wire;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using FsCheck;
using FsCheck.Fluent;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Every physics message decoder and <see cref="ServerMessageHandler.HandleMessage"/> over random bytes and over valid
/// bodies with bytes flipped and cut: a message, <see cref="RetailDataFormatException"/> or (the handler, for a value
/// outside the library's domain) <see cref="ArgumentException"/>; never another exception.
/// </summary>
public class PhysicsMessageFuzzTests
{
    private static Config Cfg => PropertyAssert.Replayable(300, 20261203UL, 0x9E3779B97F4A7C15UL);

    private static readonly uint[] Opcodes = [0xF745, 0xF747, 0xF748, 0xF749, 0xF74A, 0xF74B, 0xF74C, 0xF74E, 0xF751];

    private static readonly byte[][] Valid =
    [
        PhysicsMessageBytes.PhysicsDesc(PhysicsMessageBytes.CreateObjectStart(2), 0x400C08,
            new PhysicsMessageBytes.Stamps(Position: 1, Instance: 1), movement: [0, 0, 0x3D, 0, 0, 0, 0, 0],
            position: (0xA9B40001u, new Vector3(10f, 10f, 0f), Quaternion.Identity), parent: (1u, 1u), scale: 1f).ToArray(),
        PhysicsMessageBytes.DeleteObject(2, 0),
        PhysicsMessageBytes.UpdatePosition(2, 0x37, 0xA9B40001u, new Vector3(10f, 10f, 0f), Quaternion.Identity, 0, 1, placementId: 0x65),
        PhysicsMessageBytes.ParentEvent(1, 2, 1, 0, 0, 1),
        PhysicsMessageBytes.PickupEvent(2, 0, 1),
        PhysicsMessageBytes.SetState(2, 0x400C08, 0, 1),
        [2, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0x3D, 0, 0, 0, 0, 0],
        PhysicsMessageBytes.VectorUpdate(2, Vector3.One, Vector3.Zero, 0, 1),
        PhysicsMessageBytes.PlayerTeleport(1),
    ];

    private static bool Decodes(int kind, byte[] bytes)
    {
        try
        {
            DecodeStrict(kind, bytes);
            return true;
        }
        catch (RetailDataFormatException)
        {
            return true;
        }
    }

    private static void DecodeStrict(int kind, byte[] bytes)
    {
        switch (kind)
            {
                case 0: PhysicsMessageDecoder.Decode(bytes, new CreateObjectMessage()); break;
                case 1: PhysicsMessageDecoder.Decode(bytes, new DeleteObjectMessage()); break;
                case 2: PhysicsMessageDecoder.Decode(bytes, new UpdatePositionMessage()); break;
                case 3: PhysicsMessageDecoder.Decode(bytes, new ParentEventMessage()); break;
                case 4: PhysicsMessageDecoder.Decode(bytes, new PickupEventMessage()); break;
                case 5: PhysicsMessageDecoder.Decode(bytes, new SetStateMessage()); break;
                case 6: MovementEventDecoder.Decode(bytes, new MovementEventMessage()); break;
                case 7: PhysicsMessageDecoder.Decode(bytes, new VectorUpdateMessage()); break;
                default: PhysicsMessageDecoder.Decode(bytes, new PlayerTeleportMessage()); break;
            }
    }

    // A world with objects 1 and 2 (and the handler's player 2), the message applied.
    private static bool Handles(int kind, byte[] bytes)
    {
        var world = new PhysicsWorld(0.0);
        var h = new ServerMessageHandler(world) { PlayerId = kind % 2 == 0 ? 2u : 0u };
        PhysicsObjFactory(world, 1);
        PhysicsObjFactory(world, 2);
        try
        {
            h.HandleMessage(Opcodes[kind], bytes);
            return true;
        }
        catch (RetailDataFormatException)
        {
            return true;
        }
        catch (ArgumentException)
        {
            return true;
        }
    }

    private static void PhysicsObjFactory(PhysicsWorld world, uint id)
    {
        var o = world.CreateObject(id);
        o.PartArray = AcDream.Core.Tests.Support.Shared.Walkers.OneSphere(0.5f);
        o.EnterWorld(new AcDream.Core.Physics.Spatial.Position(0xA9B40001u, new Vector3(10f, 10f, 0f)));
    }

    [Fact]
    public void RandomBytes_EveryDecoder()
    {
        PropertyAssert.Holds(Cfg, Prop.ForAll(Gen.Choose(0, 8).ToArbitrary(),
            Gen.ArrayOf(Gen.Choose(0, 255).Select(i => (byte)i)).ToArbitrary(),
            (int kind, byte[] bytes) => Decodes(kind, bytes) && Handles(kind, bytes)));
    }

    [Fact]
    public void MutatedValidBodies_EveryDecoderAndTheHandler()
    {
        Gen<(int Kind, int At, int Value, int Cut, bool Cutting)> mutation =
            from kind in Gen.Choose(0, 8)
            from at in Gen.Choose(0, 200)
            from value in Gen.Choose(0, 255)
            from cut in Gen.Choose(0, 200)
            from cutting in Gen.Elements(false, false, true)
            select (kind, at, value, cut, cutting);
        PropertyAssert.Holds(Cfg, Prop.ForAll(mutation.ToArbitrary(), m =>
        {
            byte[] b = (byte[])Valid[m.Kind].Clone();
            if (m.Cutting)
            {
                b = b.AsSpan(0, Math.Min(m.Cut, b.Length)).ToArray();
            }
            else
            {
                b[m.At % b.Length] = (byte)m.Value;
            }

            return Decodes(m.Kind, b) && Handles(m.Kind, b);
        }));
    }

    [Fact]
    public void ValidBodies_Decode()
    {
        // The mutation tests start from bodies that decode (no exception at all).
        for (int k = 0; k < Valid.Length; k++)
        {
            DecodeStrict(k, Valid[k]);
        }
    }
}
