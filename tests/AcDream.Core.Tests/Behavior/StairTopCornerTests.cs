using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Geometry;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Issue #25 item 10, the top corner of a real stair flight (../shared/data/geometry/outdoor-stairs, placed as its README
/// says: the foot wedge 0x01000ACA at (x0, y0, ground), eight 0x01000AC5 slabs at (x0, y0 + 0.5 (k + 1), ground + 0.4 (k + 1)),
/// yaw +90°; a ramp of N.z 0.781 up to ground + 3.8 m at y0 + 4.25, then a 3.8 m drop). A one-sphere walker without
/// EDGE_SLIDE (r 0.48 centred 0.48 up, step-up 0.6, step-down 1.5, 4 m/s) climbing diagonally (from x0 ± 0.6 at ∓10°)
/// leaves the ramp past its top corner and is held there, descending a few centimetres at a time, before it falls.
/// </summary>
/// <remarks>
/// Retail's path, traced (the port runs the same functions): past the ramp's end the walker keeps the ramp's plane
/// (validate_transition restores the last known contact plane within r + EPSILON, acclient.c:312193) and then loses it:
/// transitional_insert's step down is cut to r/2 = 0.24 for a single sphere whose step-down exceeds 2r (312974), the ground
/// 3.8 m below is not found, and without EDGE_SLIDE nothing holds it on the tread: it falls. The falling sphere touches the
/// top slab's upper corner (the ramp polygon's vertex, 0.43 m from the centre): BSPTREE::find_collisions (361295) for an
/// object out of contact calls set_collide with the ramp's normal; transitional_insert's collide branch (312833) asks for a
/// landing (check_walkable with z_for_landing), but the walkable search (find_walkable / adjust_sphere_to_plane) needs the
/// centre's projection on the polygon, which at the corner it is not, so there is no contact plane: restore_check_pos,
/// COLLIDED, and handle_all_collisions (321807) bounces the velocity off the ramp's normal. The sphere cannot land on the
/// corner and cannot pass it. validate_transition's stationary-fall rule (312193: a gravity object that ends a step where
/// it began counts frames_stationary_fall 1, 2, 3; at 3 it sets a horizontal contact plane under the sphere) then gives it
/// ground for one tick; the root motion moves it a few centimetres, it loses that plane, falls 0.037 m onto the corner
/// again, and the cycle repeats until the sphere is clear of the corner. That is retail's answer to a sphere resting on a
/// vertex (landable nowhere, solid everywhere): kept, not changed.
/// </remarks>
public class StairTopCornerTests
{
    private const float X0 = 100f;
    private const float Y0 = 100f;
    private const float G = ObjectScene.GroundZ;

    private static Polygon[] Polygons(string geometryDir, string file)
    {
        DumpPolygon[] dump = CellDump.ReadGfxObjPolygons(Path.Combine(geometryDir, "outdoor-stairs", file));
        var polys = new Polygon[dump.Length];
        for (int i = 0; i < dump.Length; i++)
        {
            var ids = new ushort[dump[i].Vertices.Length];
            for (int j = 0; j < ids.Length; j++)
            {
                ids[j] = (ushort)j;
            }

            polys[i] = new Polygon((short)i, dump[i].Vertices, ids);
        }

        return polys;
    }

    // A static piece: one part with the GfxObj's physics BSP (HAS_PHYSICS_BSP), no spheres, a sorting sphere covering it.
    private static void Piece(PhysicsWorld world, uint id, Polygon[] polys, Vector3 at)
    {
        var gfx = new GfxObjPhysics(BspBuilder.Build(polys));
        PhysicsObj obj = world.CreateObject(id);
        var parts = new SimplePartArray(1, 0) { SortingSphere = new Sphere(Vector3.Zero, 1.2f) };
        obj.PartArray = parts;
        obj.SetState(PhysicsState.ReportCollisions | PhysicsState.HasPhysicsBsp);
        var frame = new Frame(at, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2f));   // yaw +90: local +X = north
        Assert.True(obj.EnterWorld(new Position(ObjectScene.Cell(at.X, at.Y), frame)));
        parts.SetPhysicsParts(new[] { gfx }, new[] { Frame.Identity }, new[] { Vector3.One });
    }

    private static List<(float Z, TransientState State)> Climb(float dx, float heading)
    {
        string dir = GeometryTestData.Dir!;
        PhysicsWorld world = ObjectScene.Flat(out _);
        Piece(world, 100, Polygons(dir, "0x01000ACA.gfxobj.json"), new Vector3(X0, Y0, G));
        Polygon[] slab = Polygons(dir, "0x01000AC5.gfxobj.json");
        for (int k = 0; k < 8; k++)
        {
            Piece(world, 101u + (uint)k, slab, new Vector3(X0, Y0 + 0.5f * (k + 1), G + 0.4f * (k + 1)));
        }

        PhysicsObj w = Walkers.Create(world, 1, ObjectScene.At(X0 + dx, Y0 - 1.5f, G, heading), Walkers.OneSphere(0.48f, 0.6f, 1.5f),
            (PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.EdgeSlide);
        SweepScene.SetWalk(w, new Vector3(0f, 4f, 0f));
        var track = new List<(float, TransientState)>();
        SweepScene.Run(world, 160, _ => track.Add((w.Position.Frame.Origin.Z - G, w.TransientState)));
        return track;
    }

    [GeometryDataFact]
    public void PastTheTopCorner_TheWalkerIsHeldOnTheCornerByTheStationaryFallRule_ThenFallsAndLands()
    {
        foreach ((float dx, float heading) in new[] { (0.6f, -10f), (-0.6f, 10f) })
        {
            List<(float Z, TransientState State)> track = Climb(dx, heading);
            // It climbs the ramp (on walkable ground above 3.5 m) and then leaves contact up there.
            int leave = track.FindIndex(s => (s.State & TransientState.Contact) == 0);
            Assert.True(leave > 0, "never left the flight");
            Assert.True((track[leave - 1].State & TransientState.OnWalkable) != 0 && track[leave - 1].Z > 3.5f, $"left at {track[leave - 1]}");
            float z0 = track[leave].Z;

            // Free fall from z0 to 3 m: one tick with no movement (UpdatePhysicsInternal moves only a non-zero velocity), then
            // 0.5 g t^2 >= z0 - 3 (about 1.06 m): t >= 0.465 s, 10 ticks: 11 ticks in all. Held on the corner it takes
            // more than twice that.
            int below3 = track.FindIndex(leave, s => s.Z < 3f);
            Assert.True(below3 - leave > 22, $"{dx}: fell from {z0} to 3 m in {below3 - leave} ticks");
            // The hold is the stationary-fall rule: STATIONARY_FALL set in that time, the position unchanged across it.
            Assert.Contains(track.GetRange(leave, below3 - leave), s => (s.State & TransientState.StationaryFall) != 0);

            // It is not stuck: it lands on the ground.
            (float Z, TransientState State) last = track[^1];
            Assert.Equal(0f, last.Z, 3);
        }
    }
}
