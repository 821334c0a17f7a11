using System;

namespace AcDream.Core.Physics.Debug;

/// <summary>Which collision shapes <see cref="PhysicsDebugDraw"/> hands to its sink (library addition; no retail symbol).</summary>
[Flags]
public enum DebugDrawFlags : uint
{
    /// <summary>Nothing.</summary>
    None = 0,

    /// <summary>The spheres of objects that collide through their spheres (no physics BSP, no cylinder spheres):
    /// <see cref="ShapeKind.ObjectSphere"/>.</summary>
    ObjectSpheres = 0x1,

    /// <summary>The cylinder spheres of objects that collide through them (no physics BSP):
    /// <see cref="ShapeKind.ObjectCylSphere"/>.</summary>
    ObjectCylSpheres = 0x2,

    /// <summary>The physics-BSP polygons of objects with <c>HasPhysicsBsp</c>: <see cref="ShapeKind.ObjectPolygon"/>.</summary>
    ObjectPolygons = 0x4,

    /// <summary>The physics-BSP polygons of buildings' shells: <see cref="ShapeKind.BuildingPolygon"/>.</summary>
    BuildingPolygons = 0x8,

    /// <summary>The physics-BSP polygons of indoor cells (walls, floors, ceilings): <see cref="ShapeKind.EnvCellPolygon"/>.</summary>
    EnvCellPolygons = 0x10,

    /// <summary>The two terrain triangles of each land cell: <see cref="ShapeKind.TerrainTriangle"/>.</summary>
    TerrainTriangles = 0x20,

    /// <summary>The four sides of each land cell, on the terrain: <see cref="ShapeKind.LandCellBoundary"/>.</summary>
    LandCellBoundaries = 0x40,

    /// <summary>The portal polygons of indoor cells: <see cref="ShapeKind.EnvCellPortal"/>.</summary>
    EnvCellPortals = 0x80,

    /// <summary>Each object's contact plane, while it is in contact: <see cref="ShapeKind.ContactPlane"/>.</summary>
    ContactPlanes = 0x100,

    /// <summary>Each object's last update's motion: its spheres where the update began and ended and the segment between
    /// the two origins (<see cref="ShapeKind.SweepStart"/>, <see cref="ShapeKind.SweepEnd"/>,
    /// <see cref="ShapeKind.SweepPath"/>).</summary>
    LastSweeps = 0x200,

    /// <summary>Every object shape (spheres, cylinder spheres, polygons).</summary>
    Objects = ObjectSpheres | ObjectCylSpheres | ObjectPolygons,

    /// <summary>Everything.</summary>
    All = 0x3FF,
}
