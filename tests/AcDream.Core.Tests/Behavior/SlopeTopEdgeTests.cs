using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// A walker leaving the top end of a stair-steep slope (normal z 0.669, just above floor_z 0.664) catches the top edge.
/// Retail's answer, from the decompilation: the falling sphere hits the slope's polygon (moving into it), set_collide asks
/// for a landing, and find_walkable cannot land it on the slope's plane, because beyond the slope's end the centre is only
/// about 0.08 m from that plane, so the lift a 0.0245 m fall step would need is t = (0.08 - 0.5) / (0.669 · -0.0245) ≈ 26
/// steps, far past adjust_sphere_to_plane's walk_interp floor of -0.5 (acclient.c:359533): the step is Collided. With no
/// movement while falling, validate_transition counts stationary frames and at the third sets a flat contact plane under the
/// sphere (frames_stationary_fall, acclient.c:312193): the walker stands for a tick, walks (the slide along the slope's edge
/// takes the step's x off), falls a tick, and the cycle repeats. So on such an edge retail neither slides off nor falls:
/// it is given contact, every six ticks.
/// </summary>
public class SlopeTopEdgeTests
{
    [Fact]
    public void WalkingOffTheTopEndOfASlope_CatchesTheEdge_AndIsGivenContactByTheStationaryFallRule()
    {
        // Slope: normal (-0.7433, 0, 0.669), rising 2.5 m along +x over L = 2.5 / (0.7433 / 0.669) = 2.25 m, 2 m wide
        // (y -1..1), from x = 105: top edge x = 107.25, z = 22.5. One sphere r 0.5, step heights 0.6, no EDGE_SLIDE, heading
        // 88 at 2 m/s (0.1 m per tick: 0.0035 m along y).
        const float nz = 0.669f, h = 2.5f, r = 0.5f;
        float L = h / (MathF.Sqrt(1f - nz * nz) / nz);
        var polys = new List<Polygon>
        {
            BspScene.Quad(new(0f, -1f, 0f), new(L, -1f, h), new(L, 1f, h), new(0f, 1f, 0f)),
            BspScene.Quad(new(L, -1f, 0f), new(L, 1f, 0f), new(L, 1f, h), new(L, -1f, h)),
            new(2, new Vector3[] { new(0f, -1f, 0f), new(L, -1f, 0f), new(L, -1f, h) }, new ushort[] { 0, 1, 2 }),
            new(3, new Vector3[] { new(0f, 1f, 0f), new(L, 1f, h), new(L, 1f, 0f) }, new ushort[] { 0, 1, 2 }),
        };
        WorldCells cells = BspScene.FlatWorld();
        var origin = new Vector3(105f, 100f, BspScene.Ground);
        BspScene.AddBuilding(cells, origin, polys);
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(102f, 100f), Frame.FromHeading(new Vector3(102f, 100f, BspScene.Ground), 88f)),
            r, 0.6f, 0.6f, state: (PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.EdgeSlide);
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));

        int outOfContactWithoutDescent = 0, longest = 0, contactTicks = 0;
        float lastZ = obj.Position.Frame.Origin.Z;
        SweepScene.Run(world, 200, tick =>
        {
            Vector3 o = obj.Position.Frame.Origin;
            Vector3 c = o + new Vector3(0f, 0f, r);
            bool contact = (obj.TransientState & TransientState.Contact) != 0;
            if (tick >= 100)
            {
                outOfContactWithoutDescent = !contact && !(o.Z < lastZ - 1e-4f) ? outOfContactWithoutDescent + 1 : 0;
                longest = Math.Max(longest, outOfContactWithoutDescent);
                if (contact)
                {
                    contactTicks++;
                    // The contact plane is the stationary-fall plane (flat, through the sphere's bottom), not the slope's.
                    Assert.Equal(new Vector3(0f, 0f, 1f), obj.ContactPlaneNormal);
                }
            }

            foreach (Polygon p in polys)
            {
                var local = new Sphere(c - origin, r - 0.001f);
                Assert.False(p.HitsSphere(local), $"tick {tick}: the sphere sinks into the slope at {o}");
            }

            lastZ = o.Z;
        });

        // Held on the top edge: beyond its end (x > 107.25) but within r of it, at the edge's height (the feet above
        // 22.5 - r), never fallen to the ground.
        Vector3 end = obj.Position.Frame.Origin;
        Assert.InRange(end.X, origin.X + L, origin.X + L + r);
        Assert.True(end.Z > BspScene.Ground + h - r, $"fell: {end}");
        // The cycle: walk tick, blocked gravity tick, three stationary frames, contact (retail's frames_stationary_fall = 3):
        // never more than 5 ticks out of contact without descending, contact once per six ticks (100 ticks → 16 or 17).
        Assert.Equal(5, longest);
        Assert.InRange(contactTicks, 16, 17);
    }
}
