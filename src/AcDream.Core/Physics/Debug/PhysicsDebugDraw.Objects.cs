using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Debug;

// One object's or one building's shapes.
public sealed partial class PhysicsDebugDraw
{
    /// <summary>
    /// Hands <paramref name="obj"/>'s shapes that <paramref name="flags"/> selects to <paramref name="sink"/>, in the frame of
    /// <paramref name="frameCellId"/>'s landblock (0: global): its part polygons when it has <c>HasPhysicsBsp</c>, else its
    /// cylinder spheres, else its spheres (the shapes <c>CPhysicsObj::FindObjCollisions</c> tests, acclient.c:316158); its
    /// contact plane while in contact; its last update's motion. Nothing for an object in no cell.
    /// </summary>
    /// <param name="sink">The client's sink.</param>
    /// <param name="obj">An object of this view's world.</param>
    /// <param name="flags">The shapes to draw.</param>
    /// <param name="frameCellId">A cell id of the frame's landblock, or 0 (global).</param>
    /// <typeparam name="TSink">The sink, a struct.</typeparam>
    /// <exception cref="ArgumentNullException"><paramref name="obj"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="obj"/> belongs to another world.</exception>
    public void DrawObject<TSink>(ref TSink sink, PhysicsObj obj, DebugDrawFlags flags, uint frameCellId = 0)
        where TSink : struct, IDebugDrawSink
    {
        ArgumentNullException.ThrowIfNull(obj);
        if (obj.World != World)
        {
            throw new ArgumentException("The object belongs to another world.", nameof(obj));
        }

        if (obj.CellId == 0)
        {
            return;
        }

        Position pos = obj.Position;
        Vector3 off = LandDefs.GetBlockOffset(frameCellId, pos.ObjCellId);
        IPartArray? parts = obj.PartArray;
        float scale = obj.Scale;
        if ((obj.State & PhysicsState.HasPhysicsBsp) != 0)
        {
            if ((flags & DebugDrawFlags.ObjectPolygons) != 0 && parts is IPartCollision bspParts)
            {
                for (int i = 0; i < bspParts.NumCollisionParts; i++)
                {
                    if (bspParts.GetCollisionPart(i, out Position partPos) is { } part)
                    {
                        Polygons(ref sink, part.GfxObj.PhysicsBsp, partPos.Frame, part.GfxObjScale.Z,
                                 LandDefs.GetBlockOffset(frameCellId, partPos.ObjCellId), ShapeKind.ObjectPolygon, obj.Id);
                    }
                }
            }
        }
        else if (parts is IPartCollision { CylSpheres.Length: > 0 } cylParts)
        {
            if ((flags & DebugDrawFlags.ObjectCylSpheres) != 0)
            {
                ReadOnlySpan<CylSphere> cyl = cylParts.CylSpheres;
                for (int i = 0; i < cyl.Length; i++)
                {
                    // placed as CCylSphere::intersects_sphere(Position*, float, CTransition*) places it (acclient.c:362243)
                    Vector3 low = new(scale * cyl[i].LowPt.X, scale * cyl[i].LowPt.Y, scale * cyl[i].LowPt.Z);
                    sink.Cylinder(off + pos.Frame.LocalToGlobal(low), scale * cyl[i].Radius, scale * cyl[i].Height,
                                  ShapeKind.ObjectCylSphere, obj.Id);
                }
            }
        }
        else if ((flags & DebugDrawFlags.ObjectSpheres) != 0 && parts is not null)
        {
            Spheres(ref sink, parts.Spheres, pos.Frame, scale, off, ShapeKind.ObjectSphere, obj.Id);
        }

        if ((flags & DebugDrawFlags.ContactPlanes) != 0 && (obj.TransientState & TransientState.Contact) != 0)
        {
            // The plane is in its cell's landblock: the object's origin is moved there and dropped onto it.
            Vector3 n = obj.ContactPlaneNormal;
            Vector3 o = pos.Frame.Origin + LandDefs.GetBlockOffset(obj.ContactPlaneCellId, pos.ObjCellId);
            float dist = n.X * o.X + n.Y * o.Y + n.Z * o.Z + obj.ContactPlaneD;
            Vector3 onPlane = o - dist * n;
            sink.Plane(LandDefs.GetBlockOffset(frameCellId, obj.ContactPlaneCellId) + onPlane, n, ShapeKind.ContactPlane, obj.Id);
        }

        if ((flags & DebugDrawFlags.LastSweeps) != 0 && !obj.IsPlacedSinceLastUpdate && parts is not null)
        {
            Position start = obj.PreviousPose;
            Vector3 startOff = LandDefs.GetBlockOffset(frameCellId, start.ObjCellId);
            Spheres(ref sink, parts.Spheres, start.Frame, scale, startOff, ShapeKind.SweepStart, obj.Id);
            Spheres(ref sink, parts.Spheres, pos.Frame, scale, off, ShapeKind.SweepEnd, obj.Id);
            sink.Segment(startOff + start.Frame.Origin, off + pos.Frame.Origin, ShapeKind.SweepPath, obj.Id);
        }
    }

    /// <summary>Hands <paramref name="building"/>'s shell polygons (its part's physics BSP, placed at the part's position and
    /// scaled by its scale's z, as <c>CBuildingObj::find_building_collisions</c> tests them, acclient.c:719115) to
    /// <paramref name="sink"/> as <see cref="ShapeKind.BuildingPolygon"/>s with the id of the land cell it hangs on (for a building
    /// hung on its cells by hand, <see cref="BuildingObj.CellId"/> 0: the cell of its shell's position), in the frame of
    /// <paramref name="frameCellId"/>'s landblock (0: global). Nothing for a building without a shell.</summary>
    /// <param name="sink">The client's sink.</param>
    /// <param name="building">The building.</param>
    /// <param name="frameCellId">A cell id of the frame's landblock, or 0 (global).</param>
    /// <typeparam name="TSink">The sink, a struct.</typeparam>
    /// <exception cref="ArgumentNullException"><paramref name="building"/> is null.</exception>
    public void DrawBuilding<TSink>(ref TSink sink, BuildingObj building, uint frameCellId = 0)
        where TSink : struct, IDebugDrawSink
    {
        ArgumentNullException.ThrowIfNull(building);
        if (building.Part is not { } part)
        {
            return;
        }

        Polygons(ref sink, part.GfxObj.PhysicsBsp, part.Pos.Frame, part.GfxObjScale.Z,
                 LandDefs.GetBlockOffset(frameCellId, part.Pos.ObjCellId), ShapeKind.BuildingPolygon, BuildingCellId(building));
    }

    // The land cell a building hangs on (CBuildingObj::add_to_cell), or, for one a client hung on its cells by hand (cell id
    // 0), the cell of its shell's position.
    internal static uint BuildingCellId(BuildingObj building) =>
        building.CellId != 0 ? building.CellId : building.Part?.Pos.ObjCellId ?? 0;

    private static void Spheres<TSink>(ref TSink sink, ReadOnlySpan<Sphere> spheres, in Frame frame, float scale, Vector3 off,
        ShapeKind kind, uint id)
        where TSink : struct, IDebugDrawSink
    {
        for (int i = 0; i < spheres.Length; i++)
        {
            // placed as CSphere::intersects_sphere(Position*, float, CTransition*, int) places it (acclient.c:359389)
            Vector3 c = new(scale * spheres[i].Center.X, scale * spheres[i].Center.Y, scale * spheres[i].Center.Z);
            sink.Sphere(off + frame.LocalToGlobal(c), scale * spheres[i].Radius, kind, id);
        }
    }
}
