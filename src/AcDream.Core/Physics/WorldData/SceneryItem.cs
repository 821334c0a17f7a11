using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.WorldData;

/// <summary>
/// One scenery object to make, as the scenery placement hands it to the door (retail <c>get_land_scenes</c> up to
/// <c>makeObject</c>): its data id, its land cell, its landblock-local frame (z on the terrain) and the scale applied after its
/// shadows are listed.
/// </summary>
/// <remarks>The seam for <c>Scenery.SceneryGenerator.Generate</c>'s <c>ScenePlacement</c>s (see
/// <see cref="WorldLoader.ScenerySource"/>).</remarks>
internal readonly record struct SceneryItem(uint ObjectId, uint LandCellId, Frame Frame, float Scale);
