using System.Numerics;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.WorldData;

/// <summary>
/// An object's shape as retail builds it from a data id before any object holds it: the setup (a Setup entry, or the
/// one-part simple setup of a GfxObj) with each part's first-level GfxObj loaded and the placement frame chosen. Shared by
/// every object made from the same id (retail shares the <c>CSetup</c> and <c>CGfxObj</c>s through its data cache).
/// </summary>
internal sealed class ObjectModel
{
    public ObjectModel(uint dataId, SetupPhysics setup, Sphere sortingSphere, GfxObjPhysics?[] partPhysics, Frame[] partFrames,
        Vector3[] defaultScales, PartBox[] boxes, uint defaultAnimId, uint defaultScriptId, uint defaultMotionTableId)
    {
        DataId = dataId;
        Setup = setup;
        SortingSphere = sortingSphere;
        PartPhysics = partPhysics;
        PartFrames = partFrames;
        DefaultScales = defaultScales;
        Boxes = boxes;
        DefaultAnimId = defaultAnimId;
        DefaultScriptId = defaultScriptId;
        DefaultMotionTableId = defaultMotionTableId;
        foreach (GfxObjPhysics? p in partPhysics)
        {
            HasPhysicsBsp |= p is not null;
        }
    }

    /// <summary>The id the object was made from (a Setup 0x02…, or a GfxObj 0x01…).</summary>
    public uint DataId { get; }

    /// <summary>The setup's spheres, cylinder spheres, sizes and step heights.</summary>
    public SetupPhysics Setup { get; }

    /// <summary>Retail <c>CSetup::sorting_sphere</c>.</summary>
    public Sphere SortingSphere { get; }

    /// <summary>Each part's <c>gfxobj[0]</c> physics (null: no physics BSP).</summary>
    public GfxObjPhysics?[] PartPhysics { get; }

    /// <summary>Each part's frame relative to the object (the placement frame chosen by <c>SetPlacementFrame(0x65)</c>).</summary>
    public Frame[] PartFrames { get; }

    /// <summary>Each part's default scale (1 without the setup's default scales).</summary>
    public Vector3[] DefaultScales { get; }

    /// <summary>Each part's frame and bounding box, for the static cell list.</summary>
    public PartBox[] Boxes { get; }

    /// <summary>Retail <c>default_anim_id</c>, <c>default_script_id</c> and <c>default_mtable_id</c> (0 for a simple setup).</summary>
    public uint DefaultAnimId { get; }

    /// <inheritdoc cref="DefaultAnimId"/>
    public uint DefaultScriptId { get; }

    /// <inheritdoc cref="DefaultAnimId"/>
    public uint DefaultMotionTableId { get; }

    /// <summary>Some part's GfxObj has a physics BSP (retail <c>CPartArray::CacheHasPhysicsBSP</c>).</summary>
    public bool HasPhysicsBsp { get; }

    /// <summary>The number of parts. Retail: <c>num_parts</c>.</summary>
    public int NumParts => PartPhysics.Length;
}
