using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Scenery;

/// <summary>
/// One scenery object as <c>CLandBlock::get_land_scenes</c> (acclient.c:352529) places it, up to <c>makeObject</c>: which
/// object, in which land cell, with which block-local frame, and the scale to apply after its shadows are listed.
/// </summary>
/// <param name="ObjectId">The Setup (0x02…) or GfxObj (0x01…) id to make (retail <c>ObjectDesc.obj_id</c>).</param>
/// <param name="LandCellId">The outdoor cell holding the origin (0xXXYY0001–0xXXYY0040).</param>
/// <param name="Frame">The frame local to the landblock, z on the terrain (the frame <c>set_initial_frame</c> and
/// <c>add_obj_to_cell</c> get).</param>
/// <param name="Scale">Retail <c>ObjectDesc::ScaleObj</c>; retail applies it with <c>SetScaleStatic</c> after
/// <c>obj_within_block</c> and <c>add_obj_to_cell</c> ran at scale 1 (acclient.c:352715).</param>
/// <param name="SceneId">The scene (0x12…) the object came from.</param>
/// <param name="ObjectIndex">The object's index in the scene (the hash's <c>k</c>).</param>
/// <param name="VertexX">The terrain vertex column, 0–8, the object was placed from.</param>
/// <param name="VertexY">The terrain vertex row, 0–8.</param>
public readonly record struct ScenePlacement(
    uint ObjectId,
    uint LandCellId,
    Frame Frame,
    float Scale,
    uint SceneId,
    int ObjectIndex,
    int VertexX,
    int VertexY);
