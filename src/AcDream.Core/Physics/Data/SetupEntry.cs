using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>A holding location or connection point of a Setup (retail <c>LocationType</c>): its key, the part it hangs on and
/// its frame in that part.</summary>
/// <param name="Key">The location's key (retail hash key).</param>
/// <param name="PartId">The part index. Retail: <c>part_id</c>.</param>
/// <param name="Frame">The frame in the part. Retail: <c>frame</c>.</param>
public readonly record struct LocationInfo(uint Key, uint PartId, Frame Frame);

/// <summary>A light of a Setup (retail <c>LIGHTINFO</c>), read and kept for completeness.</summary>
/// <param name="Type">Retail <c>type</c>.</param>
/// <param name="Offset">Retail <c>offset</c>.</param>
/// <param name="Color">The colour as stored (0xAARRGGBB word).</param>
/// <param name="Intensity">Retail <c>intensity</c>.</param>
/// <param name="Falloff">Retail <c>falloff</c>.</param>
/// <param name="ConeAngle">Retail <c>cone_angle</c>.</param>
public readonly record struct LightInfo(uint Type, Frame Offset, uint Color, float Intensity, float Falloff, float ConeAngle);

/// <summary>
/// A Setup (data-file entry 0x02xxxxxx: how an object is put together) as retail's <c>CSetup::UnPack</c> reads it: the parts
/// (GfxObj ids), parent indices and default scales, holding locations and connection points, the placement frames (one
/// frame per part for each placement), the cylinder spheres and spheres, height, radius, step-up and step-down heights, the
/// sorting and selection spheres, the lights, and the default animation, script, motion table, sound table and physics script
/// table ids. <see cref="ToSetupPhysics"/> gives the collision half the part arrays take.
/// </summary>
/// <remarks>All fields are plain data, so an animated part array can take the parts, placement frames and default ids as
/// they are.</remarks>
public sealed class SetupEntry
{
    /// <summary>Retail flag 1: parent indices follow the parts.</summary>
    public const uint HasParentFlag = 1;

    /// <summary>Retail flag 2: default scales follow.</summary>
    public const uint HasDefaultScaleFlag = 2;

    /// <summary>Retail flag 4: the object may turn freely (<c>allow_free_heading</c>).</summary>
    public const uint AllowFreeHeadingFlag = 4;

    /// <summary>Retail flag 8: the parts carry physics BSPs (<c>has_physics_bsp</c>).</summary>
    public const uint HasPhysicsBspFlag = 8;

    private readonly uint[] _parts;
    private readonly uint[] _parentIndices;
    private readonly Vector3[] _defaultScales;
    private readonly LocationInfo[] _holdingLocations;
    private readonly LocationInfo[] _connectionPoints;
    private readonly Dictionary<uint, Frame[]> _placementFrames;
    private readonly Dictionary<uint, AnimFrame> _placementAnimFrames;
    private readonly CylSphere[] _cylSpheres;
    private readonly Sphere[] _spheres;
    private readonly LightInfo[] _lights;
    private readonly int _shapesOffset;

    private SetupEntry(uint id, uint flags, uint[] parts, uint[] parentIndices, Vector3[] defaultScales, LocationInfo[] holding,
        LocationInfo[] connection, Dictionary<uint, Frame[]> placement, Dictionary<uint, AnimFrame> placementAnim, CylSphere[] cylSpheres, Sphere[] spheres, float height,
        float radius, float stepUp, float stepDown, Sphere sorting, Sphere selection, LightInfo[] lights, uint[] ids, int shapesOffset)
    {
        Id = id;
        Flags = flags;
        _parts = parts;
        _parentIndices = parentIndices;
        _defaultScales = defaultScales;
        _holdingLocations = holding;
        _connectionPoints = connection;
        _placementFrames = placement;
        _placementAnimFrames = placementAnim;
        _cylSpheres = cylSpheres;
        _spheres = spheres;
        Height = height;
        Radius = radius;
        StepUpHeight = stepUp;
        StepDownHeight = stepDown;
        SortingSphere = sorting;
        SelectionSphere = selection;
        _lights = lights;
        DefaultAnimationId = ids[0];
        DefaultScriptId = ids[1];
        DefaultMotionTableId = ids[2];
        DefaultSoundTableId = ids[3];
        DefaultPhysicsScriptTableId = ids[4];
        _shapesOffset = shapesOffset;
    }

    /// <summary>The entry id (0x02xxxxxx).</summary>
    public uint Id { get; }

    /// <summary>The stored flags (<see cref="HasParentFlag"/>, <see cref="HasDefaultScaleFlag"/>,
    /// <see cref="AllowFreeHeadingFlag"/>, <see cref="HasPhysicsBspFlag"/>).</summary>
    public uint Flags { get; }

    /// <summary>Retail <c>allow_free_heading</c>: flag 4.</summary>
    public bool AllowFreeHeading => (Flags & AllowFreeHeadingFlag) != 0;

    /// <summary>Retail <c>has_physics_bsp</c>: flag 8.</summary>
    public bool HasPhysicsBsp => (Flags & HasPhysicsBspFlag) != 0;

    /// <summary>The parts' GfxObj ids, one per part. Retail: <c>parts</c>.</summary>
    public ReadOnlySpan<uint> Parts => _parts;

    /// <summary>Each part's parent index (empty without flag 1). Retail: <c>parent_index</c>.</summary>
    public ReadOnlySpan<uint> ParentIndices => _parentIndices;

    /// <summary>Each part's default scale (empty without flag 2). Retail: <c>default_scale</c>.</summary>
    public ReadOnlySpan<Vector3> DefaultScales => _defaultScales;

    /// <summary>The holding locations. Retail: <c>holding_locations</c>.</summary>
    public ReadOnlySpan<LocationInfo> HoldingLocations => _holdingLocations;

    /// <summary>The connection points. Retail: <c>connection_points</c>.</summary>
    public ReadOnlySpan<LocationInfo> ConnectionPoints => _connectionPoints;

    /// <summary>The placement frames: for each placement key, one frame per part. Retail: <c>placement_frames</c>.</summary>
    public IReadOnlyDictionary<uint, Frame[]> PlacementFrames => _placementFrames;

    /// <summary>The placement frames as retail holds them: for each placement key an <see cref="AnimFrame"/> (the part frames
    /// as read, unnormalised, and the frame's animation hooks), what <see cref="Objects.Parts.AnimatedPartArray"/> takes as
    /// its placement frames. Retail: <c>placement_frames</c> (<c>AnimFrame</c>).</summary>
    public IReadOnlyDictionary<uint, AnimFrame> PlacementAnimFrames => _placementAnimFrames;

    /// <summary>The cylinder spheres, object-local. Retail: <c>cylsphere</c>.</summary>
    public ReadOnlySpan<CylSphere> CylSpheres => _cylSpheres;

    /// <summary>The collision spheres, object-local. Retail: <c>sphere</c>.</summary>
    public ReadOnlySpan<Sphere> Spheres => _spheres;

    /// <summary>Retail <c>height</c>.</summary>
    public float Height { get; }

    /// <summary>Retail <c>radius</c>.</summary>
    public float Radius { get; }

    /// <summary>Retail <c>step_up_height</c>.</summary>
    public float StepUpHeight { get; }

    /// <summary>Retail <c>step_down_height</c>.</summary>
    public float StepDownHeight { get; }

    /// <summary>Retail <c>sorting_sphere</c>.</summary>
    public Sphere SortingSphere { get; }

    /// <summary>Retail <c>selection_sphere</c>.</summary>
    public Sphere SelectionSphere { get; }

    /// <summary>The lights. Retail: <c>lights</c>.</summary>
    public ReadOnlySpan<LightInfo> Lights => _lights;

    /// <summary>Retail <c>default_anim_id</c>.</summary>
    public uint DefaultAnimationId { get; }

    /// <summary>Retail <c>default_script_id</c>.</summary>
    public uint DefaultScriptId { get; }

    /// <summary>Retail <c>default_mtable_id</c>.</summary>
    public uint DefaultMotionTableId { get; }

    /// <summary>Retail <c>default_stable_id</c>.</summary>
    public uint DefaultSoundTableId { get; }

    /// <summary>Retail <c>default_phstable_id</c>.</summary>
    public uint DefaultPhysicsScriptTableId { get; }

    /// <summary>The holding location with key <paramref name="locationId"/>, or null. Retail
    /// <c>CSetup::GetHoldingLocation</c> (a hash lookup: of two entries with one key, the later read is found).</summary>
    // retail: CSetup::GetHoldingLocation (acclient.c:336113)
    public LocationInfo? GetHoldingLocation(uint locationId)
    {
        for (int i = _holdingLocations.Length - 1; i >= 0; i--)
        {
            if (_holdingLocations[i].Key == locationId)
            {
                return _holdingLocations[i];
            }
        }

        return null;
    }

    /// <summary>
    /// The collision half for <see cref="SimplePartArray(SetupPhysics, int)"/>: the spheres, cylinder spheres, radius, height
    /// and step heights as stored.
    /// </summary>
    /// <exception cref="RetailDataFormatException">A value is outside the library's domain (see <see cref="SetupPhysics"/>:
    /// a sphere or cylinder without a positive radius, a shape reaching beyond 192 m, a step height above 192 m); the
    /// offset is where the cylinder spheres start.</exception>
    public SetupPhysics ToSetupPhysics()
    {
        try
        {
            return new SetupPhysics(_spheres, _cylSpheres, Radius, Height, StepUpHeight, StepDownHeight);
        }
        catch (ArgumentException e)
        {
            throw new RetailDataFormatException("CSetup", _shapesOffset, "the shapes are outside the library's domain: " + e.Message);
        }
    }

    /// <summary>Unpacks one Setup entry's bytes (after the data-file container). Retail <c>CSetup::UnPack</c>.</summary>
    /// <exception cref="RetailDataFormatException">The bytes are not a Setup (truncated, inconsistent, a frame not valid, or a
    /// placement frame's animation hook not valid).</exception>
    // retail: CSetup::UnPack (acclient.c:335520)
    public static SetupEntry UnPack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "CSetup");
        uint id = r.ReadUInt32("id");
        uint flags = r.ReadUInt32("flags");
        int numPartsAt = r.Offset;
        int numParts = r.ReadCount("part count", 4);
        var parts = new uint[numParts];
        for (int i = 0; i < numParts; i++)
        {
            parts[i] = r.ReadUInt32("part id");
        }

        uint[] parents = [];
        if ((flags & HasParentFlag) != 0)
        {
            r.CheckCount((uint)numParts, "parent index count", 4, numPartsAt);
            parents = new uint[numParts];
            for (int i = 0; i < numParts; i++)
            {
                parents[i] = r.ReadUInt32("parent index");
            }
        }

        Vector3[] scales = [];
        if ((flags & HasDefaultScaleFlag) != 0)
        {
            r.CheckCount((uint)numParts, "default scale count", 12, numPartsAt);
            scales = new Vector3[numParts];
            for (int i = 0; i < numParts; i++)
            {
                scales[i] = r.ReadFiniteVector3("default scale");
            }
        }

        LocationInfo[] holding = ReadLocations(ref r, "holding location");
        LocationInfo[] connection = ReadLocations(ref r, "connection point");
        int numPlacements = r.ReadCount("placement frame count", 8);
        var placement = new Dictionary<uint, Frame[]>(numPlacements);
        var placementAnim = new Dictionary<uint, AnimFrame>(numPlacements);
        for (int i = 0; i < numPlacements; i++)
        {
            uint key = r.ReadUInt32("placement key");
            string structure = r.Structure;
            r.Structure = "AnimFrame (CSetup placement)";
            AnimFrame frame = AnimFrame.UnPack(ref r, numParts, numPartsAt);
            r.Structure = structure;
            ReadOnlySpan<AFrame> partFrames = frame.Frames;
            var frames = new Frame[partFrames.Length];
            for (int k = 0; k < partFrames.Length; k++)
            {
                frames[k] = partFrames[k].ToFrame();
            }

            // Retail's hash keeps both; a lookup finds the later one (it is linked in front of its bucket).
            placement[key] = frames;
            placementAnim[key] = frame;
        }

        int shapesAt = r.Offset;
        int numCyl = r.ReadCount("cylinder sphere count", 20);
        var cyl = new CylSphere[numCyl];
        for (int i = 0; i < numCyl; i++)
        {
            cyl[i] = CylSphere.UnPack(ref r, "cylinder sphere");
        }

        int numSpheres = r.ReadCount("sphere count", 16);
        var spheres = new Sphere[numSpheres];
        for (int i = 0; i < numSpheres; i++)
        {
            spheres[i] = Sphere.UnPack(ref r, "sphere");
        }

        float height = r.ReadFiniteSingle("height");
        float radius = r.ReadFiniteSingle("radius");
        float stepUp = r.ReadFiniteSingle("step up height");
        float stepDown = r.ReadFiniteSingle("step down height");
        Sphere sorting = Sphere.UnPack(ref r, "sorting sphere");
        Sphere selection = Sphere.UnPack(ref r, "selection sphere");
        int numLights = r.ReadCount("light count", 48);
        var lights = new LightInfo[numLights];
        for (int i = 0; i < numLights; i++)
        {
            uint type = r.ReadUInt32("light type");
            Frame offset = r.ReadFrame("light frame");
            uint color = r.ReadUInt32("light colour");
            lights[i] = new LightInfo(type, offset, color, r.ReadSingle("light intensity"), r.ReadSingle("light falloff"), r.ReadSingle("light cone angle"));
        }

        var ids = new uint[5];
        for (int i = 0; i < ids.Length; i++)
        {
            ids[i] = r.ReadUInt32("default id");
        }

        r.Align4();
        return new SetupEntry(id, flags, parts, parents, scales, holding, connection, placement, placementAnim, cyl, spheres, height, radius, stepUp,
            stepDown, sorting, selection, lights, ids, shapesAt);
    }

    // A location hash: the count, then each key, part id and frame (Frame::UnPack: origin, quaternion w x y z, valid).
    private static LocationInfo[] ReadLocations(ref RetailDataReader r, string what)
    {
        int n = r.ReadCount(what + " count", 36);
        var list = new LocationInfo[n];
        for (int i = 0; i < n; i++)
        {
            uint key = r.ReadUInt32(what + " key");
            uint part = r.ReadUInt32(what + " part");
            list[i] = new LocationInfo(key, part, r.ReadFrame(what + " frame"));
        }

        return list;
    }
}
