using System;
using System.Numerics;
using AcDream.Core.Fixtures.Wire;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The server's physics messages (issue #37): an UpdatePosition body decoded alone, and decoded and applied to a remote
/// object near the player through <see cref="ServerMessageHandler.HandleMessage"/> (the instance gate, the stamps,
/// <c>HandleReceivedPosition</c>'s interpolation and leash); a VectorUpdate and a SetState decoded and applied. Each
/// invoke handles <see cref="Messages"/> messages with newer stamps; the mean is per message. The allocation column is the
/// "0 B per message" check.
/// </summary>
[MemoryDiagnoser]
public class ServerMessageBenchmarks
{
    private const int Messages = 256;
    private readonly byte[][] _positions = new byte[Messages][];
    private readonly byte[][] _vectors = new byte[Messages][];
    private readonly byte[][] _states = new byte[Messages][];
    private readonly UpdatePositionMessage _message = new();
    private ServerMessageHandler _handler = null!;
    private PhysicsObj _remote = null!;
    private ushort _round;

    /// <summary>A player and a remote creature 5 m from it on level ground; the bodies.</summary>
    [GlobalSetup]
    public void Setup()
    {
        var world = new PhysicsWorld(0.0) { Sweep = new ReplayGroundSweep() };
        PhysicsObj player = world.CreateObject(1);
        player.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        player.EnterWorld(new Position(0x80800001u, new Vector3(96f, 96f, 0f)));
        world.Player = player;
        _remote = world.CreateObject(2);
        _remote.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f, Height = 1.8f };
        _remote.EnterWorld(new Position(0x80800001u, new Vector3(101f, 96f, 0f)));
        world.Tick(0.05);
        _handler = new ServerMessageHandler(world);
        for (int i = 0; i < Messages; i++)
        {
            _positions[i] = PhysicsMessageBytes.UpdatePosition(2, 0x34, 0x80800001u, new Vector3(101f + 0.01f * i, 96f, 0f),
                Quaternion.Identity, 0, 0);
            _vectors[i] = PhysicsMessageBytes.VectorUpdate(2, new Vector3(0f, 0.01f * i, 0f), Vector3.Zero, 0, 0);
            _states[i] = PhysicsMessageBytes.SetState(2, 0x400C08, 0, 0);
        }
    }

    // Each round's stamps are newer than the last round's (positions 1..256, 257..512, ...).
    private void Stamp(byte[][] bodies, int at)
    {
        for (int i = 0; i < Messages; i++)
        {
            System.BitConverter.TryWriteBytes(bodies[i].AsSpan(at), (ushort)(_round * Messages + i + 1));
        }
    }

    /// <summary>Renews the stamps before each invoke (outside the measurement).</summary>
    [IterationSetup]
    public void NextRound()
    {
        _round++;
        Stamp(_positions, _positions[0].Length - 6);
        Stamp(_vectors, _vectors[0].Length - 2);
        Stamp(_states, _states[0].Length - 2);
    }

    /// <summary>UpdatePosition bodies decoded (no object touched).</summary>
    [Benchmark(OperationsPerInvoke = Messages)]
    public uint DecodeUpdatePosition()
    {
        uint sum = 0;
        for (int i = 0; i < Messages; i++)
        {
            PhysicsMessageDecoder.Decode(_positions[i], _message);
            sum += _message.Position.ObjCellId;
        }

        return sum;
    }

    /// <summary>UpdatePosition bodies decoded and applied to the remote (interpolation queued, leash re-armed).</summary>
    [Benchmark(OperationsPerInvoke = Messages)]
    public int HandleUpdatePosition()
    {
        int applied = 0;
        for (int i = 0; i < Messages; i++)
        {
            applied += _handler.HandleMessage(0xF748, _positions[i]) == ServerMessageResult.Applied ? 1 : 0;
        }

        return applied;
    }

    /// <summary>VectorUpdate and SetState bodies decoded and applied.</summary>
    [Benchmark(OperationsPerInvoke = 2 * Messages)]
    public int HandleVectorAndState()
    {
        int applied = 0;
        for (int i = 0; i < Messages; i++)
        {
            applied += _handler.HandleMessage(0xF74E, _vectors[i]) == ServerMessageResult.Applied ? 1 : 0;
            applied += _handler.HandleMessage(0xF74B, _states[i]) == ServerMessageResult.Applied ? 1 : 0;
        }

        return applied;
    }
}
