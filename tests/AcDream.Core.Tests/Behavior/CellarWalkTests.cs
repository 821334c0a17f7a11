using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Geometry;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// A human walker (EDGE_SLIDE) in the real Holtburg cellar of landblock 0xA9B4 (../shared/data/geometry, on the real
/// terrain): its cell id always contains it, it stays in contact, never sinks into a floor nor passes a wall, and each
/// height change it meets is climbed or refused as retail's rules say. Cell-local coordinates below are the first cellar's
/// (origin (130.5, 11.5, 94), turned 180°: world = (130.5 - x, 11.5 - y, 94 + z)).
/// </summary>
public class CellarWalkTests
{
    private const uint Outdoor = 0;
    private const uint Doorway = CellarScene.Block | 0x0145;   // the door cell, outdoor portal at x = -5.8
    private const uint Room = CellarScene.Block | 0x0143;      // ground-floor room, floor z 0
    private const uint SideDoor = CellarScene.Block | 0x0144;  // doorway to 0x013F (not in the dumps)
    private const uint Hatch = CellarScene.Block | 0x0146;     // the 0.2 m slab under the floor hatch
    private const uint Cellar = CellarScene.Block | 0x0147;    // cellar, floor z -3.05
    private const uint Lower = CellarScene.Block | 0x0148;     // lower cellar, ramps n.z 0.96 from -3.05 to -4
    private const uint Alcove = CellarScene.Block | 0x0149;    // alcove off the lower cellar, floor z -4

    /// <summary>The scene the walks run in (today's path; a derived class runs every walk through retail bytes).</summary>
    private protected virtual CellarScene Scene() => CellarScene.Load(GeometryTestData.Dir!, TerrainTestData.Dir);

    private static Frame CellarFrame(CellarScene s) => s.Env[Doorway].Cell.Pos.Frame;

    [GeometryDataFact]
    public void InThroughTheDoor_IntoTheSideDoorway_AndBackOut()
    {
        // Outside (x = -3, on the terrain, z 94) → through 0x0145's door → the room 0x0143 → the doorway 0x0144 (its far side
        // leads to 0x013F, not dumped) → back through the room and out. All floors are z 0 (94 m), like the terrain here.
        CellarScene s = Scene();
        Frame f = CellarFrame(s);
        Vector3 start = f.LocalToGlobal(new Vector3(-3f, 6.35f, 0f));
        var visited = Walk(s, SyntheticTerrain.OnGround(s.Cells.Terrain, Holtburg.CentreCell(start.X, start.Y), start.X, start.Y, 90f),
            [new(-8f, 6.35f), new(-8f, 1f), new(-6.0f, 1.03f), new(-8f, 1f), new(-8f, 6.35f), new(-3f, 6.35f)], 400, out PhysicsObj obj,
            cell => cell is Doorway or Room or SideDoor ? (94f, 94f) : null);
        Assert.Equal(new[] { Outdoor, Doorway, Room, SideDoor, Room, Doorway, Outdoor }, visited.ToArray());
        Assert.False(CellarScene.IsIndoor(obj.CellId));
    }

    [GeometryDataFact]
    public void WindowSillOneMetreUp_IsRefused()
    {
        // 0x0142 (y -2.0..-1.6) is a window from the room: its floor is z 1.0, 1.0 m above the room's. Retail's step up
        // reaches 1.5 × 0.6 = 0.9 m (and only where the sphere touches the tread), so the walker stays in the room, at the
        // wall below the sill (y = -1.6 + r = -1.12, world 12.62), on the floor.
        CellarScene s = Scene();
        Vector3 start = CellarFrame(s).LocalToGlobal(new Vector3(-3f, 6.35f, 0f));
        var visited = Walk(s, SyntheticTerrain.OnGround(s.Cells.Terrain, Holtburg.CentreCell(start.X, start.Y), start.X, start.Y, 90f),
            [new(-8f, 6.35f), new(-8.9f, 0f), new(-8.9f, -4f)], 300, out PhysicsObj obj, cell => cell is Doorway or Room ? (94f, 94f) : null,
            reachesTheEnd: false);
        Assert.Equal(Room, obj.CellId);
        Assert.Equal(new[] { Outdoor, Doorway, Room }, visited.ToArray());
        Assert.Equal(94f, obj.Position.Frame.Origin.Z, 2);
        Assert.True(obj.Position.Frame.Origin.Y < 11.5f + 1.6f - HumanWalker.Radius + 0.01f);
    }

    [GeometryDataFact]
    public void DoorSillEightyFiveCentimetresUp_IsRefused_ThoughWithinTheReach()
    {
        // The door of 0x014F in the shell's wall y = -8 (world 19.5) has its floor at z 0.85, 0.85 m above the terrain (94)
        // in front of it; the steps up to it are not in the dumps. 0.85 is within the reach 1.5 × 0.6 = 0.9, but the step up
        // needs the foot sphere to touch the tread: the tread is 0.85 - 0.48 = 0.37 above the centre, so it is touched
        // within sqrt((0.48 - 0.0002)² - 0.37²) = 0.305 m of its edge, while at the riser hit the centre is at least
        // 0.48 - 0.075 = 0.405 m away (1.5 m/s, 0.075 m per tick). Refused: the walker stays outdoors, in front of the wall
        // (its centre within 0.48..0.555 m of it), on the terrain.
        CellarScene s = Scene();
        Vector3 start = CellarFrame(s).LocalToGlobal(new Vector3(-8.9f, -10f, 0f));
        var visited = Walk(s, SyntheticTerrain.OnGround(s.Cells.Terrain, Holtburg.CentreCell(start.X, start.Y), start.X, start.Y, 180f),
            [new(-8.9f, -7.7f), new(-8.9f, -5f)], 200, out PhysicsObj obj, _ => null, reachesTheEnd: false);
        Assert.Equal(new[] { Outdoor }, visited.ToArray());
        Assert.InRange(obj.Position.Frame.Origin.Y, 19.5f + HumanWalker.Radius, 19.5f + HumanWalker.Radius + 0.075f + 0.001f);
        Assert.Equal(94f, obj.Position.Frame.Origin.Z, 2);
    }

    [GeometryDataFact]
    public void FloorHatchToTheCellar_IsAPrecipice_AndHoldsTheWalker()
    {
        // The hatch 0x0146 (x -11.6..-10) opens onto the cellar floor 3.05 m below; the dumps hold no stair object. With
        // EDGE_SLIDE, a step whose half sphere leaves the floor probes min(1.5, ...) → 0.75 m down (two spheres,
        // acclient.c:312474): nothing there, so precipice_slide holds the walker at the hatch's edge (x = -10 local,
        // world 140.5) — it never drops into 0x0146.
        CellarScene s = Scene();
        Vector3 start = CellarFrame(s).LocalToGlobal(new Vector3(-3f, 6.35f, 0f));
        var visited = Walk(s, SyntheticTerrain.OnGround(s.Cells.Terrain, Holtburg.CentreCell(start.X, start.Y), start.X, start.Y, 90f),
            [new(-8f, 6.35f), new(-10.8f, 5.2f)], 250, out PhysicsObj obj, cell => cell is Doorway or Room ? (94f, 94f) : null,
            reachesTheEnd: false);
        Assert.DoesNotContain(Hatch, visited);
        Assert.Equal(Room, obj.CellId);
        Assert.Equal(94f, obj.Position.Frame.Origin.Z, 2);
        Assert.InRange(obj.Position.Frame.Origin.X, 140.5f - 0.01f, 140.5f + HumanWalker.Radius / 2f + 0.01f);
    }

    [GeometryDataFact]
    public void LowerCellars_DownTheRamps_IntoTheAlcove_AndBackUp()
    {
        // From the cellar 0x0147 (floor -3.05) through the sloped portal into 0x0148, down its ramps (n.z 0.96, walkable:
        // floor_z is 0.664) to the floor at -4, into the alcove 0x0149 and back up the ramps into 0x0147.
        CellarScene s = Scene();
        Frame f = CellarFrame(s);
        var p = new Position(Cellar, Frame.FromHeading(f.LocalToGlobal(new Vector3(-8f, 6.25f, -3.05f)), 90f));
        var visited = Walk(s, p, [new(-4.62f, 6.25f), new(0f, 6f), new(2.8f, 6f), new(0f, 6f), new(-8f, 6.25f)], 500, out PhysicsObj obj,
            cell => cell is Cellar or Lower ? (90f, 94f - 3.05f) : cell is Alcove ? (90f, 90f) : null);
        Assert.Equal(new[] { Cellar, Lower, Alcove, Lower, Cellar }, visited.ToArray());
        Assert.Equal(94f - 3.05f, obj.Position.Frame.Origin.Z, 2);
    }

    [GeometryDataFact]
    public void SecondCellar_ThroughItsRooms_AndOutThroughTheFlapDoorway()
    {
        // The second cellar (cells 0x0170..0x0175, origin (161.929, 7.503, 94), turned 180°): its building shell is not in
        // the dumps, so the walk starts inside, in the hall 0x0171 (floor z 0). Through the doorway 0x0173 into the room
        // 0x0172 and back, then south through the flap doorway 0x0170 and its outdoor portal onto the terrain (z 94 there).
        const uint hall = CellarScene.Block | 0x0171, door = CellarScene.Block | 0x0173, room = CellarScene.Block | 0x0172,
            flap = CellarScene.Block | 0x0170;
        CellarScene s = Scene();
        Frame f = s.Env[hall].Cell.Pos.Frame;
        var p = new Position(hall, Frame.FromHeading(f.LocalToGlobal(new Vector3(6.5f, -5f, 0f)), 90f));
        var visited = Walk(s, p, [new(4.6f, -0.9f), new(1f, -0.9f), new(4.6f, -0.9f), new(6.5f, -5f), new(6.5f, -10f)], 400, out PhysicsObj obj,
            cell => cell is hall or door or room or flap ? (94f, 94f) : null, frameOf: hall);
        Assert.Equal(new[] { hall, door, room, door, hall, flap, Outdoor }, visited.ToArray());
        Assert.Equal(94f, obj.Position.Frame.Origin.Z, 2);
    }

    // Walks the human through cell-local waypoints (xy in the frame of cell frameOf, by default the first cellar's) at 1.5 m/s, 20 ticks a second, checking every
    // tick; returns the sequence of cells it was in (outdoor cells as 0).
    private static List<uint> Walk(CellarScene s, in Position start, Vector2[] route, int maxTicks, out PhysicsObj obj,
        Func<uint, (float Lo, float Hi)?> floorOf, bool reachesTheEnd = true, uint frameOf = Doorway)
    {
        var world = new PhysicsWorld(0.0) { Sweep = new RetailSweep(s.Cells) };
        obj = HumanWalker.Create(world, start);
        Frame f = s.Env[frameOf].Cell.Pos.Frame;
        var visited = new List<uint>();
        int w = 0;
        Vector3 prev = Feet(obj) + new Vector3(0f, 0f, HumanWalker.Radius);
        for (int tick = 0; tick < maxTicks && w < route.Length; tick++)
        {
            Vector3 target = f.LocalToGlobal(new Vector3(route[w].X, route[w].Y, 0f));
            Vector3 o = obj.Position.Frame.Origin;
            var to = new Vector2(target.X - o.X, target.Y - o.Y);
            if (to.Length() < 0.2f)
            {
                w++;
                continue;
            }

            Vector2 dir = Vector2.Normalize(to) * 1.5f;
            SweepScene.SetWalk(obj, obj.Position.Frame.GlobalToLocalVec(new Vector3(dir.X, dir.Y, 0f)));
            world.Tick(world.CurrentTime + SweepScene.Dt);

            uint id = obj.CellId;
            uint key = CellarScene.IsIndoor(id) ? id : Outdoor;
            if (visited.Count == 0 || visited[^1] != key)
            {
                visited.Add(key);
            }

            Vector3 feet = Feet(obj);
            Vector3 c0 = feet + new Vector3(0f, 0f, HumanWalker.Radius);
            Vector3 c1 = feet + new Vector3(0f, 0f, HumanWalker.HeadCentre);
            string at = $"tick {tick}, cell 0x{id:X8}, feet {feet}";
            Assert.True((obj.TransientState & TransientState.Contact) != 0, $"out of contact at {at}");
            if (CellarScene.IsIndoor(id))
            {
                Assert.True(s.Env[id].Cell.PointInCell(c0), $"the cell does not contain the walker at {at}");
            }
            else
            {
                Assert.Equal(Holtburg.CentreCell(c0.X, c0.Y), id);
            }

            if (floorOf(id) is (float lo, float hi))
            {
                Assert.True(feet.Z > lo - 0.01f && feet.Z < hi + 0.01f, $"feet not on the floor ({lo}..{hi}) at {at}");
            }

            foreach ((Vector3[] poly, uint _) in s.WorldPolygons)
            {
                Assert.True(PolygonDistance.To(c0, poly) >= HumanWalker.Radius - 0.01f, $"foot sphere inside a polygon at {at}");
                Assert.True(PolygonDistance.To(c1, poly) >= HumanWalker.Radius - 0.01f, $"head sphere inside a polygon at {at}");
                Assert.False(PolygonDistance.Crosses(prev, c0, poly), $"passed through a polygon at {at}");
            }

            prev = c0;
        }

        if (reachesTheEnd)
        {
            Assert.Equal(route.Length, w);
        }
        return visited;
    }

    private static Vector3 Feet(PhysicsObj obj) => obj.Position.Frame.Origin;
}
