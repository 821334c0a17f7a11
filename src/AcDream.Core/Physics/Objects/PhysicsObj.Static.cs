// PhysicsObj — static objects: add_obj_to_cell, calc_cross_cells_static, find_bbox_cell_list.
using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects;

// A static object (a landblock's or an indoor cell's, scenery) put straight into a cell, without a sweep, and shadowed in
// every cell its parts reach.
public sealed partial class PhysicsObj
{
    /// <summary>
    /// Puts the object in <paramref name="cell"/> at <paramref name="frame"/> (landblock-local) without a sweep, and lists its
    /// shadows in every cell it reaches (<see cref="CalcCrossCellsStatic"/>).
    /// </summary>
    // retail: CPhysicsObj::add_obj_to_cell (acclient.c:322896)
    internal void AddObjToCell(ObjCell cell, in Frame frame, RetailSweep sweep)
    {
        Touch();
        EnterCell(cell.Id);
        _position.Frame = frame;
        SyncObstacleSummary();
        if ((_state & PhysicsState.ParticleEmitter) == 0)
        {
            PartArray?.SetFrame(_position.Frame);
        }

        UpdateChildrenInternal();
        CalcCrossCellsStatic(sweep);
    }

    /// <summary>
    /// Re-shadows a static object where it stands: in the cells its cylinder spheres reach (an object without a physics BSP
    /// that has them), else in the cells its parts' bounding boxes reach (<see cref="FindBboxCellList"/>).
    /// </summary>
    // retail: CPhysicsObj::calc_cross_cells_static (acclient.c:322404)
    internal void CalcCrossCellsStatic(RetailSweep sweep)
    {
        CellArray ca = sweep.CrossCells;
        ca.Clear();
        ca.DoNotLoadCells = true;
        IPartCollision? parts = PartArray as IPartCollision;
        ReadOnlySpan<CylSphere> cyl = parts is null ? default : parts.CylSpheres;
        if ((_state & PhysicsState.HasPhysicsBsp) == 0 && cyl.Length != 0)
        {
            Position p = Position;
            int n = cyl.Length <= 10 ? cyl.Length : 10;
            Span<Sphere> spheres = stackalloc Sphere[10];
            for (int i = 0; i < n; i++)
            {
                spheres[i] = new Sphere(p.LocalToGlobal(p, cyl[i].LowPt), cyl[i].Radius);
            }

            CellList.FindCellList(sweep.Cells, p, spheres[..n], ca, false, null);
        }
        else
        {
            FindBboxCellList(sweep, ca);
        }

        RemoveShadowsFromCells();
        AddShadowsToCells(ca, sweep.Cells.GetVisible(CellId));
    }

    /// <summary>
    /// The object's own cell, then, for every cell found so far (the list grows as it is walked), the cells that cell finds
    /// for the parts: an outdoor cell adds the block of outdoor cells the parts' bounding boxes cover and the indoor cells
    /// behind its building's doors; an indoor cell, its neighbours through its portals.
    /// </summary>
    // retail: CPhysicsObj::find_bbox_cell_list (acclient.c:318275)
    internal void FindBboxCellList(RetailSweep sweep, CellArray ca)
    {
        ca.NumCells = 0;
        ca.AddedOutside = false;
        ca.AddCell(CellId, sweep.Cells.GetVisible(CellId));
        if (CellId == 0 || PartArray is null)
        {
            return;
        }

        ReadOnlySpan<PartBox> boxes = default;
        PlacedPartBox[] placed = Array.Empty<PlacedPartBox>();
        if (PartArray is SimplePartArray simple)
        {
            boxes = simple.PartBoxes;
            placed = simple.PlacedBoxes;
        }

        int numParts = boxes.Length;
        Position p = Position;
        for (int i = 0; i < numParts; i++)
        {
            PartBox b = boxes[i];
            placed[i] = new PlacedPartBox(new Position(p.ObjCellId, ScaledPartFrame(b.LocalFrame)), b.Min, b.Max, b.Always2D, b.PartSphere);
        }

        ReadOnlySpan<PlacedPartBox> parts = placed.AsSpan(0, numParts);
        for (int i = 0; i < ca.NumCells; i++)
        {
            // retail: CPartArray::calc_cross_cells_static (acclient.c:325457) -> the cell's find_transit_cells(parts)
            ObjCell? cell = ca.CellAt(i);
            if (cell is LandCell land)
            {
                land.FindTransitCellsForParts(sweep.Cells, parts, ca);
            }
            else if (cell is EnvCell env)
            {
                env.FindTransitCellsForParts(sweep.Cells, parts, ca);
            }
        }
    }

    // A part's frame in the object's landblock: the object's frame combined with the part's frame, its origin scaled.
    // retail: CPartArray::UpdateParts (acclient.c:326600), one part
    private Frame ScaledPartFrame(in Frame local)
    {
        Frame scaled = local;
        if (Scale != 1f)
        {
            Vector3 o = local.Origin;
            scaled.Origin = new Vector3(o.X * Scale, o.Y * Scale, o.Z * Scale);
        }

        return Frame.Combined(_position.Frame, scaled);
    }

    /// <summary>
    /// True when the object lies wholly inside its landblock in x and y: with a physics BSP, its sorting sphere; with cylinder
    /// spheres, each of them (its low point); with spheres, the sorting sphere; otherwise its origin. Scale is not applied
    /// (scenery asks before it is scaled).
    /// </summary>
    // retail: CPhysicsObj::obj_within_block (acclient.c:318306)
    internal bool ObjWithinBlock()
    {
        const float BlockLength = LandDefs.BlockLength;
        IPartArray? parts = PartArray;
        IPartCollision? pc = parts as IPartCollision;
        if ((_state & PhysicsState.HasPhysicsBsp) != 0)
        {
            Sphere s = pc?.SortingSphere ?? Sphere.Dummy;
            Vector3 c = _position.Frame.LocalToGlobal(s.Center);
            float r = s.Radius;
            if (c.X >= r && c.Y >= r)
            {
                float edge = BlockLength - r;
                return c.X < edge && c.Y < edge;
            }

            return false;
        }

        ReadOnlySpan<CylSphere> cyl = pc is null ? default : pc.CylSpheres;
        if (cyl.Length != 0)
        {
            ref readonly Frame f = ref _position.Frame;
            for (int i = 0; i < cyl.Length; i++)
            {
                Vector3 l = cyl[i].LowPt;
                double x = (double)f.M21 * l.Y + (double)l.Z * f.M31 + (double)f.M11 * l.X + f.Origin.X;
                float y = (float)((double)f.M22 * l.Y + (double)f.M12 * l.X + (double)f.M32 * l.Z + f.Origin.Y);
                float r = cyl[i].Radius;
                if (x < r || y < r)
                {
                    return false;
                }

                float edge = BlockLength - r;
                if (x >= edge || y >= edge)
                {
                    return false;
                }
            }

            return true;
        }

        if (parts is not null && parts.NumSpheres != 0)
        {
            Sphere s = pc?.SortingSphere ?? Sphere.Dummy;
            return LandDefs.WithinBlock(_position.Frame.LocalToGlobal(s.Center), s.Radius);
        }

        return LandDefs.WithinBlock(_position.Frame.Origin, 0f);
    }

    /// <summary>True for an object made from a data id whose parts have boxes (<see cref="CalcCrossCellsStatic"/> lists it).</summary>
    internal bool HasPartBoxes => PartArray is SimplePartArray { PartBoxes.Length: > 0 };
}
