using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.WorldData;

/// <summary>Where a world object came from.</summary>
public enum WorldObjectKind
{
    /// <summary>A building of the landblock info (retail <c>CLandBlock::init_buildings</c>).</summary>
    Building,

    /// <summary>A static object of the landblock info (retail <c>CLandBlock::init_static_objs</c>).</summary>
    LandBlockStatic,

    /// <summary>A static object of an indoor cell (retail <c>CEnvCell::init_static_objects</c>).</summary>
    EnvCellStatic,

    /// <summary>Procedural scenery (retail <c>CLandBlock::get_land_scenes</c>).</summary>
    Scenery,
}

/// <summary>
/// One object the <see cref="WorldLoader"/> built into the world, for a renderer to draw: the physics object (or, for a
/// building, the <see cref="BuildingObj"/>), the data id it was made from, its kind, its cell, its landblock-local frame and
/// its scale.
/// </summary>
/// <param name="Kind">Where it came from.</param>
/// <param name="DataId">The Setup (0x02…) or GfxObj (0x01…) id it was made from: the model to draw.</param>
/// <param name="Object">The static physics object (null for a building).</param>
/// <param name="Building">The building (null for any other kind).</param>
/// <param name="CellId">The cell it stands in: a land cell, or an indoor cell for <see cref="WorldObjectKind.EnvCellStatic"/>.
/// A building hangs on the one land cell under its origin, whatever its footprint.</param>
/// <param name="Frame">Its frame, local to its landblock (an indoor static's too, as stored).</param>
/// <param name="Scale">Its scale (1 but for scenery).</param>
public sealed record WorldObject(WorldObjectKind Kind, uint DataId, PhysicsObj? Object, BuildingObj? Building, uint CellId, Frame Frame,
    float Scale);
