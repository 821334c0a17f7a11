using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// A cell of the world as the sweep sees it: something that can be asked for collisions with a transition, can list
/// the further cells a sphere reaches through it, and can tell whether a point lies in it. Retail: <c>CObjCell</c>
/// (acclient.h:30915, PORTAL/ccell/CObjCell.c) and its virtual table. Kinds: <see cref="LandCell"/> (outdoor terrain, with
/// its building) and <see cref="EnvCell"/> (indoor cells). Each cell also lists the shadows of the objects that overlap it.
/// </summary>
public abstract partial class ObjCell
{
    /// <summary>The cell id (0xXXYYCCCC). Retail: <c>m_DID.id</c>.</summary>
    public abstract uint Id { get; }

    /// <summary>True when <paramref name="point"/>, local to this cell's landblock, lies in the cell.</summary>
    // retail: CObjCell::point_in_cell (virtual; CLandCell::point_in_cell acclient.c:354880)
    public abstract bool PointInCell(Vector3 point);

    /// <summary>
    /// Everything in the cell that the transition's check spheres may hit: the environment (terrain, walls), then
    /// buildings, then objects. Returns the first result that is not OK.
    /// </summary>
    // retail: CObjCell::find_collisions (virtual; CLandCell::find_collisions acclient.c:354886)
    internal abstract TransitionState FindCollisions(Transition transition);

    /// <summary>The cell's own geometry against the check spheres (terrain for a land cell).</summary>
    // retail: CObjCell::find_env_collisions (virtual; CLandCell::find_env_collisions acclient.c:354991)
    internal abstract TransitionState FindEnvCollisions(Transition transition);

    /// <summary>
    /// Adds to <paramref name="cellArray"/> the cells the spheres reach through this one (neighbouring outdoor cells,
    /// building and portal cells).
    /// </summary>
    /// <param name="cells">Where cells are looked up.</param>
    /// <param name="p">The position the sphere centres are local to (its landblock).</param>
    /// <param name="spheres">The spheres, in <paramref name="p"/>'s landblock.</param>
    /// <param name="cellArray">The list being built.</param>
    /// <param name="path">The sphere path, when the list is built for a sweep.</param>
    // retail: CObjCell::find_transit_cells (virtual; CLandCell::find_transit_cells acclient.c:355422)
    internal abstract void FindTransitCells(ICellSource cells, in Position p, ReadOnlySpan<Sphere> spheres, CellArray cellArray, SpherePath? path);

    /// <summary>
    /// Whether the moving object may enter the cell at all: never without an object; otherwise yes (retail asks the
    /// weenie about restricted cells, e.g. housing; there is no weenie in the core).
    /// </summary>
    // retail: CObjCell::check_entry_restrictions (acclient.c:347102)
    internal virtual TransitionState CheckEntryRestrictions(Transition transition) =>
        transition.ObjectInfo.Object is null ? TransitionState.Collided : TransitionState.Ok;

    /// <summary>The objects whose shadows lie in the cell against the check spheres (ObjCell.Shadows.cs).</summary>
    // retail: CObjCell::find_obj_collisions (acclient.c:347141)
    internal virtual TransitionState FindObjCollisions(Transition transition) => FindShadowObjCollisions(transition);
}

/// <summary>
/// Where a transition finds cells by id. Retail reached them through globals (<c>CObjCell::GetVisible</c>,
/// <c>CLandCell::Get</c> → <c>LScape::get_landcell</c>); the port passes the world explicitly.
/// </summary>
public interface ICellSource
{
    /// <summary>The loaded cell with id <paramref name="cellId"/>, or null (not loaded, or not a cell).</summary>
    // retail: CObjCell::GetVisible (acclient.c:346416)
    ObjCell? GetVisible(uint cellId);
}
