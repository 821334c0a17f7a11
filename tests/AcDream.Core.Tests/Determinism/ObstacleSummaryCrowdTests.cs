using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// A dense crowd whose objects keep changing every input of their obstacle summaries between ticks (scale, spheres,
/// cylinder spheres, a new part array, the physics-BSP bit, a parent, teleports), run with the summaries' check on
/// (<see cref="ObstacleSummary.Verify"/>: every summary a sweep reads is compared with its object) in two worlds, one
/// rejecting obstacles from the summaries and one on the plain retail paths (<c>RetailSweep.ReferencePaths</c>): every
/// object has the same bits after every tick, and every summary of every cell equals a fresh computation.
/// </summary>
[Trait("Category", "Determinism")]
public class ObstacleSummaryCrowdTests
{
    private const int Count = 150;
    private const int Ticks = 160;

    [Fact]
    public void MutatingCrowd_SummariesStayExact_AndTheSweepMatchesTheReferencePaths()
    {
        Scene fast = Build(reference: false);
        Scene slow = Build(reference: true);
        var rngFast = new Random(17);
        var rngSlow = new Random(17);
        int mutations = 0, parented = 0;
        for (int t = 0; t < Ticks; t++)
        {
            mutations += Mutate(fast, rngFast, t);
            Mutate(slow, rngSlow, t);
            fast.World.Tick(fast.World.CurrentTime + SweepScene.Dt);
            slow.World.Tick(slow.World.CurrentTime + SweepScene.Dt);
            for (int i = 0; i < Count; i++)
            {
                PhysicsObj a = fast.Objects[i], b = slow.Objects[i];
                Assert.True(a.Position.ObjCellId == b.Position.ObjCellId && a.Position.Frame.Origin == b.Position.Frame.Origin
                    && a.Position.Frame.Qw == b.Position.Frame.Qw && a.Position.Frame.Qx == b.Position.Frame.Qx
                    && a.Position.Frame.Qy == b.Position.Frame.Qy && a.Position.Frame.Qz == b.Position.Frame.Qz && a.Velocity == b.Velocity && a.TransientState == b.TransientState,
                    $"tick {t}, object {i}: {a.Position} {a.Velocity} {a.TransientState} vs {b.Position} {b.Velocity} {b.TransientState}");
                AssertFresh(a, t);
                parented += a.Parent is null ? 0 : 1;
            }
        }

        Assert.True(mutations > 500, $"{mutations} mutations");
        Assert.True(parented > 100, $"{parented} parented object ticks");
    }

    private sealed record Scene(PhysicsWorld World, PhysicsObj[] Objects);

    // 150 walkers (radius 0.4) on a flat 48 m × 48 m square of landblock 0x8080 (about 37 per 24 m cell), walking 1 to 3 m/s.
    private static Scene Build(bool reference)
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep, twoBlocks: true);
        sweep.ReferencePaths = reference;
        var rng = new Random(5);
        var objects = new List<PhysicsObj>();
        for (uint id = 1; objects.Count < Count; id++)
        {
            Position p = ObjectScene.At(150f + (float)rng.NextDouble() * 40f, 60f + (float)rng.NextDouble() * 48f,
                ObjectScene.GroundZ, (float)(rng.NextDouble() * 360.0));
            PhysicsObj o;
            try
            {
                o = ObjectScene.Creature(world, id, p, 0.4f);
            }
            catch (InvalidOperationException)
            {
                continue;
            }

            SweepScene.SetWalk(o, new Vector3(0f, 1f + (float)rng.NextDouble() * 2f, 0f));
            ((SimplePartArray)o.PartArray!).SequenceOmega = new Vector3(0f, 0f, (float)(rng.NextDouble() - 0.5));
            objects.Add(o);
        }

        world.ObjectMaintenanceActive = false;
        return new Scene(world, objects.ToArray());
    }

    // Between ticks, a few objects change an input of their summaries; the same draws in both worlds.
    private static int Mutate(Scene s, Random rng, int tick)
    {
        int n = 0;
        for (int k = 0; k < 4; k++)
        {
            int i = rng.Next(Count);
            PhysicsObj o = s.Objects[i];
            int kind = rng.Next(8);
            var parts = o.PartArray as SimplePartArray;
            switch (kind)
            {
                case 0:
                    o.SetScaleStatic(0.6f + (float)rng.NextDouble());
                    break;
                case 1 when parts is not null:
                    float r = 0.3f + (float)rng.NextDouble() * 0.4f;
                    parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, r), r), new Sphere(new Vector3(0f, 0.1f, r + 0.9f), r) });
                    break;
                case 2 when parts is not null:
                    parts.SetCylSpheres(rng.Next(2) == 0 ? Array.Empty<CylSphere>() : new[] { new CylSphere(Vector3.Zero, 0.4f, 1.6f) });
                    break;
                case 3:
                    // A new part array (walking on), or back to the one-sphere walker.
                    SimplePartArray fresh = Support.Shared.Walkers.OneSphere(0.3f + (float)rng.NextDouble() * 0.3f);
                    fresh.SequenceVelocity = new Vector3(0f, 1.5f, 0f);
                    o.PartArray = fresh;
                    break;
                case 4:
                    o.SetState(o.State ^ PhysicsState.HasPhysicsBsp);
                    break;
                case 5:
                    PhysicsObj other = s.Objects[(i + 1 + rng.Next(Count - 1)) % Count];
                    if (o.Parent is not null)
                    {
                        o.UnsetParent();
                    }
                    else if (other.Parent is null && o.Children is not { Count: > 0 })
                    {
                        o.SetParent(other, 0, Frame.FromHeading(new Vector3(0f, 0.6f, 1f), 0f));
                    }

                    break;
                case 6 when o.Parent is null:
                    // StorePosition: moved without a sweep, its shadows left where they were.
                    Vector3 at = o.Position.Frame.Origin;
                    o.StorePosition(new Position(o.Position.ObjCellId, Frame.FromHeading(at + new Vector3(0.3f, -0.2f, 0f), 45f)));
                    break;
                case 7 when o.Parent is null:
                    o.SetPositionSimple(ObjectScene.At(150f + (float)rng.NextDouble() * 40f, 60f + (float)rng.NextDouble() * 48f), true);
                    break;
                default:
                    continue;
            }

            n++;
        }

        return n;
    }

    private static void AssertFresh(PhysicsObj o, int tick)
    {
        foreach (ShadowObj s in o.ShadowObjects)
        {
            if (s.Cell is { } cell)
            {
                Assert.Same(s, cell.ShadowObjects[s.Slot]);
                Assert.True(cell.HoldsObstacleSummary(s.Slot, o.ComputeObstacleSummary()),
                    $"tick {tick}, object 0x{o.Id:X8}, cell 0x{cell.Id:X8}: stale, fresh {o.ComputeObstacleSummary()}");
            }
        }
    }
}
