using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using Xunit;

namespace AcDream.Core.Tests.Support;

/// <summary>Scene builders and a scripted mixed scene that can be run with or without dormancy.</summary>
internal static class SceneTestContext
{
    public static Position At(float x, float y, float z = 0f)
    {
        var p = new Position(0xA9B40001u, new Vector3(x, y, z));
        Assert.True(p.TryAdjustToOutside());
        return p;
    }

    public static PhysicsObj Add(PhysicsWorld world, uint id, Position p, int spheres = 1)
    {
        PhysicsObj o = world.CreateObject(id);
        o.PartArray = new SimplePartArray(numParts: 1, numSpheres: spheres);
        Assert.True(o.EnterWorld(p));
        return o;
    }

    /// <summary>Every piece of per-object state retail keeps that a client can read, hashed bit for bit.</summary>
    public static ulong Hash(PhysicsObj o)
    {
        var h = new StateHasher();
        h.Add(o.Id);
        h.Add(o.Position);
        h.Add(o.CellId);
        h.Add(o.Velocity);
        h.Add(o.Acceleration);
        h.Add(o.Omega);
        h.Add((uint)o.TransientState);
        h.Add((uint)o.State);
        h.Add(o.UpdateTime);
        h.Add(o.PlayerVector);
        h.Add(o.PlayerDistance);
        h.Add(o.CachedVelocity);
        h.Add(o.Translucency);
        h.Add(o.JumpedThisFrame ? 1u : 0u);
        return h.Value;
    }

    public static ulong HashWorld(PhysicsWorld w)
    {
        var h = new StateHasher();
        for (int i = 0; i < w.ObjectCount; i++)
        {
            h.Add(Hash(w.GetObject(i)));
        }

        return h.Value;
    }

    /// <summary>
    /// A scripted scene: a walking player that travels 400 m east and back (so objects cross the 96 m gate both ways), resting
    /// items on a grid, sliding movers that stop and are kicked again, static objects, a fade added to a resting item, stalls
    /// of 0.45 s and 2.5 s, a late player, object maintenance switched off and on, an object removed and re-created.
    /// Calls <paramref name="afterTick"/> after every tick.
    /// </summary>
    public static void RunMixedScene(PhysicsWorld w, Action<int, PhysicsWorld> afterTick, int ticks = 260, bool descendingCreation = false)
    {
        w.Sweep = new FlatGroundSweep();
        // Items (ids 100..), statics (ids 1000..), movers (ids 2000..). Creation order may be reversed: ids decide the order.
        var specs = new (uint Id, Position P, int Kind)[0];
        var list = new System.Collections.Generic.List<(uint, Position, int)>();
        for (int i = 0; i < 144; i++)
        {
            list.Add((100u + (uint)i, At(8f + (i % 12) * 15f, 8f + (i / 12) * 15f), 0));
        }

        for (int i = 0; i < 12; i++)
        {
            list.Add((1000u + (uint)i, At(20f + i * 13f, 150f), 1));
        }

        for (int i = 0; i < 24; i++)
        {
            list.Add((2000u + (uint)i, At(30f + (i % 6) * 25f, 40f + (i / 6) * 25f), 2));
        }

        specs = list.ToArray();
        if (descendingCreation)
        {
            Array.Reverse(specs);
        }

        foreach (var (id, p, kind) in specs)
        {
            PhysicsObj o = Add(w, id, p, spheres: kind == 0 && (id & 1) == 1 ? 0 : 1);
            if (kind == 1)
            {
                o.SetState(o.State | PhysicsState.Static);
            }
            else if (kind == 2)
            {
                // Velocity from the id, not from creation order.
                var idRng = new Random((int)id);
                o.SetVelocity(new Vector3((float)(idRng.NextDouble() * 6 - 3), (float)(idRng.NextDouble() * 6 - 3), 0f));
            }
        }

        PhysicsObj player = Add(w, 1u, At(96f, 96f));
        PhysicsObj remote = Add(w, 3000u, At(100f, 60f));
        double t = w.CurrentTime;
        for (int tick = 1; tick <= ticks; tick++)
        {
            if (tick == 10)
            {
                w.Player = player;
            }

            // The player walks east for ticks 10..110 and back west for 130..230 at 8 m/s (set each tick, as a controller would).
            if (tick >= 10 && tick < 110)
            {
                player.SetVelocity(new Vector3(8f, 0.5f, 0f));
            }
            else if (tick >= 130 && tick < 230)
            {
                player.SetVelocity(new Vector3(-8f, -0.5f, 0f));
            }

            if (tick == 40 || tick == 140 || tick == 200)
            {
                // Kick some movers and some resting items.
                w.GetObjectById(2003u)!.SetVelocity(new Vector3(4f, 1f, 0f));
                w.GetObjectById(107u)!.SetVelocity(new Vector3(-2f, 2f, 0f));
                w.GetObjectById(118u)!.SetOmega(new Vector3(0f, 0f, 1.5f));
            }

            // A remote creature receives position updates (interpolation) now and then, and rests in between.
            if ((tick >= 20 && tick < 100 && tick % 5 == 0) || tick == 180 || tick == 185)
            {
                remote.InterpolateTo(At(100f + (tick % 20), 60f + (tick % 13)), keepHeading: false);
            }

            if (tick == 50)
            {
                w.GetObjectById(130u)!.SetTranslucency(0.8f, 1.0);
                w.GetObjectById(1003u)!.SetTranslucency(0.5f, 1.0); // static: its hook never runs
            }

            if (tick == 60)
            {
                w.RemoveObject(w.GetObjectById(125u)!);
            }

            if (tick == 90)
            {
                Add(w, 125u, At(8f + (125 - 100) % 12 * 15f, 8f + (125 - 100) / 12 * 15f), spheres: 0);
            }

            if (tick == 150)
            {
                w.ObjectMaintenanceActive = false;
            }

            if (tick == 170)
            {
                w.ObjectMaintenanceActive = true;
            }

            double dt = tick == 80 ? 0.45 : tick == 120 ? 2.5 : 1.0 / 30.0 + (tick % 7) * 0.004;
            t += dt;
            w.Tick(t);
            afterTick(tick, w);
        }
    }
}
