using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Tests.Support;

/// <summary>Builders for object-collision scenes: flat ground at z = 20 in landblock 0x8080 (and optionally 0x8180), walkers,
/// obstacles with spheres or cylinder spheres.</summary>
internal static class ObjectScene
{
    /// <summary>Ground height of the flat scenes, metres.</summary>
    public const float GroundZ = 20f;

    /// <summary>A flat world (every vertex at index 20 of the one-metre table: the plane z = 20), one or two landblocks.</summary>
    public static PhysicsWorld Flat(out RetailSweep sweep, bool twoBlocks = false)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        if (twoBlocks)
        {
            SweepScene.AddBlock(terrain, SweepScene.BlockX + 1, SweepScene.BlockY, (_, _) => 20);
        }

        return SweepScene.Physics(terrain, out sweep);
    }

    /// <summary>Cell id of the outdoor cell under (x, y) of landblock 0x8080 (x, y in 0..192).</summary>
    public static uint Cell(float x, float y) => SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, (int)(x / 24f), (int)(y / 24f));

    /// <summary>A position in landblock 0x8080 at (x, y, z) facing <paramref name="heading"/> degrees.</summary>
    public static Position At(float x, float y, float z = GroundZ, float heading = 0f) =>
        new(Cell(x, y), Frame.FromHeading(new Vector3(x, y, z), heading));

    /// <summary>A creature walker (one sphere of radius <paramref name="radius"/> on its origin) with a creature weenie.</summary>
    public static PhysicsObj Creature(PhysicsWorld world, uint id, in Position p, float radius = 0.5f, PhysicsState? state = null,
        IWeenieObject? weenie = null)
    {
        SimplePartArray parts = Walkers.OneSphere(radius);
        parts.Height = 2f * radius;
        return Walkers.Create(world, id, p, parts, state, weenie ?? WeenieTraits.Creature);
    }

    /// <summary>
    /// An object that does not move by itself (no gravity, no movement manager): with the given spheres or cylinder
    /// spheres, state <see cref="PhysicsState.ReportCollisions"/> plus <paramref name="extra"/>.
    /// </summary>
    public static PhysicsObj Obstacle(PhysicsWorld world, uint id, in Position p, Sphere[]? spheres = null, CylSphere[]? cyl = null,
        PhysicsState extra = PhysicsState.None, IWeenieObject? weenie = null)
    {
        PhysicsObj obj = world.CreateObject(id);
        obj.Weenie = weenie;
        var parts = new SimplePartArray(1, 0);
        if (spheres is not null)
        {
            parts.SetSpheres(spheres);
        }

        if (cyl is not null)
        {
            parts.SetCylSpheres(cyl);
            if (spheres is null)
            {
                // Retail setups with cylinder spheres also carry spheres; the sweep of the obstacle itself needs one.
                parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, cyl[0].Radius), cyl[0].Radius) });
            }
        }

        obj.PartArray = parts;
        obj.SetState(PhysicsState.ReportCollisions | extra);
        if (!obj.EnterWorld(p))
        {
            throw new InvalidOperationException("The obstacle could not enter the world.");
        }

        return obj;
    }

    /// <summary>True when <paramref name="cell"/> lists a shadow of <paramref name="obj"/>.</summary>
    public static bool CellLists(ObjCell cell, PhysicsObj obj)
    {
        foreach (ShadowObj s in cell.ShadowObjects)
        {
            if (s.PhysObj == obj)
            {
                return true;
            }
        }

        return false;
    }
}

/// <summary>Records every object collision report.</summary>
internal sealed class RecordingListener : IObjectCollisionListener
{
    public List<(uint Reporter, ObjCollisionProfile Profile)> Objects { get; } = new();

    public List<(uint Reporter, AtkCollisionProfile Profile)> Attacks { get; } = new();

    public List<(uint Reporter, uint Other)> Ends { get; } = new();

    public void OnObjectCollision(PhysicsObj obj, in ObjCollisionProfile profile) => Objects.Add((obj.Id, profile));

    public void OnAttackCollision(PhysicsObj obj, in AtkCollisionProfile profile) => Attacks.Add((obj.Id, profile));

    public void OnObjectCollisionEnd(PhysicsObj obj, uint otherId) => Ends.Add((obj.Id, otherId));
}
