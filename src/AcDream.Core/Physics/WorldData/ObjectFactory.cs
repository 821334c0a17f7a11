using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Physics.WorldData;

/// <summary>
/// Makes physics objects from a data id, as retail's <c>CPhysicsObj::makeObject</c> does: a GfxObj id (0x01…) becomes a
/// one-part simple setup, a Setup id (0x02…) the setup's parts, each part colliding with its GfxObj's physics BSP (the first
/// level of its degrade table when it names one). The entries are read from the client's <see cref="IRetailDataSource"/>
/// once and shared by every object made from the same id.
/// </summary>
/// <remarks>A client creates a creature or an item from its Setup id with <see cref="MakeObject(PhysicsWorld, uint, uint, bool)"/> (dynamic); the
/// <see cref="WorldLoader"/> makes the world's static objects and buildings through the same factory. Not thread-safe.</remarks>
public sealed class ObjectFactory
{
    private readonly IRetailDataSource _source;
    private readonly Dictionary<uint, ObjectModel?> _models = new();
    private readonly Dictionary<uint, GfxObjEntry?> _gfxObjs = new();
    private readonly HashSet<uint> _missing = new();
    private readonly Dictionary<uint, uint[]> _modelMissing = new();
    private readonly List<uint> _missingOrder = new();

    /// <summary>Creates a factory reading <paramref name="source"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="source"/> is null.</exception>
    public ObjectFactory(IRetailDataSource source)
    {
        ArgumentNullException.ThrowIfNull(source);
        _source = source;
    }

    /// <summary>The entry ids the factory needed and the source did not hold (a Setup, or a part's GfxObj), in no order.</summary>
    public IReadOnlyCollection<uint> MissingIds => _missing;

    /// <summary>
    /// Makes an object of <paramref name="world"/> from <paramref name="dataId"/>: its part array (spheres, cylinder
    /// spheres, sizes and step heights of the setup; parts with a physics BSP, at the setup's placement frame 0x65, else
    /// key 0, with the setup's default scales) and its state (STATIC unless <paramref name="isDynamic"/>,
    /// <see cref="PhysicsState.HasPhysicsBsp"/> when a part has a physics BSP). It is in no cell until placed
    /// (<see cref="PhysicsObj.EnterWorld"/>).
    /// </summary>
    /// <param name="world">The world that owns the object.</param>
    /// <param name="dataId">A Setup (0x02xxxxxx) or GfxObj (0x01xxxxxx) id; an id whose high byte is 0 is retail's
    /// anim object (<c>makeAnimObject</c>): Setup <c>0x02000000 | dataId</c>, ethereal, ignoring collisions, translucency 0.25.</param>
    /// <param name="objectId">The object's id (0 for none). Retail: <c>object_iid</c>.</param>
    /// <param name="isDynamic">False for a static object (the STATIC bit). Retail: <c>bDynamic</c>.</param>
    /// <returns>The object, or null, adding nothing to the world, when retail's <c>makeObject</c> fails: another kind of id,
    /// or the Setup or a part's GfxObj missing from the source (listed in <see cref="MissingIds"/>).</returns>
    /// <exception cref="ArgumentNullException"><paramref name="world"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="objectId"/> is in use in the world (see
    /// <see cref="PhysicsWorld.CreateObject"/>); nothing is added.</exception>
    /// <exception cref="RetailDataFormatException">An entry's bytes are bad (or hold another id than the one asked for);
    /// nothing is added.</exception>
    // retail: CPhysicsObj::makeObject (acclient.c:320828)
    public PhysicsObj? MakeObject(PhysicsWorld world, uint dataId, uint objectId = 0, bool isDynamic = true)
    {
        ArgumentNullException.ThrowIfNull(world);
        if (objectId != 0 && world.GetObjectById(objectId) is not null)
        {
            throw new ArgumentException($"An object with id 0x{objectId:X8} is already in this world.", nameof(objectId));
        }

        ObjectModel? model = InitPartArrayModel(dataId, out bool animObject);
        return model is null ? null : Instantiate(world, model, objectId, isDynamic, animObject);
    }

    /// <summary>
    /// Makes the object of a server's CreateObject from its physics description: a dynamic object from
    /// <see cref="PhysicsDesc.SetupId"/> with the message's object id (<see cref="MakeObject(PhysicsWorld, uint, uint, bool)"/>).
    /// Its signature is <see cref="PhysicsObjectFactory"/>: <c>handler.ObjectFactory = loader.Objects.MakeObject;</c>. The
    /// handler then applies the rest of the description; a motion player (from <see cref="PhysicsDesc.MotionTableId"/>) and
    /// a weenie are the client's to add, in its own factory that calls this one.
    /// </summary>
    /// <returns>The object, or null (the handler answers <c>NotApplicable</c>) when the Setup or a part's GfxObj is missing
    /// from the source.</returns>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    // retail seam: SmartBox::HandleCreateObject (acclient.c:145880) -> CObjectMaint's create slot -> CPhysicsObj::makeObject
    public PhysicsObj? MakeObject(PhysicsWorld world, uint objectId, PhysicsDesc desc)
    {
        ArgumentNullException.ThrowIfNull(desc);
        return MakeObject(world, desc.SetupId, objectId, isDynamic: true);
    }

    /// <summary>The model of <paramref name="dataId"/>, or null when retail's <c>InitPartArrayObject</c> fails.</summary>
    // retail: CPhysicsObj::InitPartArrayObject (acclient.c:319645), the part array half
    internal ObjectModel? InitPartArrayModel(uint dataId, out bool animObject)
    {
        animObject = false;
        if (dataId == 0)
        {
            return null;
        }

        switch (dataId >> 24)
        {
            case 0x01:
                return CreateMesh(dataId);
            case 0x02:
                return CreateSetup(dataId);
            case 0x00:
                // retail: CPhysicsObj::makeAnimObject (acclient.c:315620) with that setup
                animObject = true;
                return CreateSetup(dataId | 0x02000000u);
            default:
                return null;
        }
    }

    /// <summary>
    /// A new object of <paramref name="world"/> holding <paramref name="model"/>'s part array.
    /// </summary>
    // retail: CPhysicsObj::InitObjectBegin (acclient.c:317272), InitPartArrayObject's object half, InitObjectEnd
    // (acclient.c:317292)
    internal PhysicsObj Instantiate(PhysicsWorld world, ObjectModel model, uint objectId, bool isDynamic, bool animObject = false)
    {
        var parts = new SimplePartArray(model.Setup, model.NumParts);
        if (model.SortingSphere.Radius > 0f)
        {
            parts.SortingSphere = model.SortingSphere;
        }

        int n = 0;
        foreach (GfxObjPhysics? g in model.PartPhysics)
        {
            n += g is null ? 0 : 1;
        }

        if (n != 0)
        {
            var gfx = new GfxObjPhysics[n];
            var frames = new Frame[n];
            var scales = new Vector3[n];
            for (int i = 0, k = 0; i < model.NumParts; i++)
            {
                if (model.PartPhysics[i] is GfxObjPhysics g)
                {
                    gfx[k] = g;
                    frames[k] = model.PartFrames[i];
                    scales[k++] = model.DefaultScales[i];
                }
            }

            parts.SetPhysicsParts(gfx, frames, scales);
        }

        parts.SetPartBoxes(model.Boxes);
        PhysicsObj obj = world.CreateObject(objectId);
        PhysicsState state = obj.State;
        state = isDynamic ? state & ~PhysicsState.Static : state | PhysicsState.Static;
        obj.PartArray = parts;
        // retail: CPhysicsObj::CacheHasPhysicsBSP (acclient.c:316513)
        state = model.HasPhysicsBsp ? state | PhysicsState.HasPhysicsBsp : state & ~PhysicsState.HasPhysicsBsp;
        if (animObject)
        {
            state |= PhysicsState.Ethereal | PhysicsState.IgnoreCollisions;
        }

        state = InitDefaults(world, obj, model, state);
        obj.SetState(state);
        if (animObject)
        {
            obj.SetTranslucency(0.25f, 0.0);
        }

        parts.SetFrame(obj.Position.Frame);
        return obj;
    }

    /// <summary>The state bits a static object's setup defaults add: a default animation or script puts it on the world's
    /// static-animating list. (Scripts, motion, sound and physics-script tables belong to the client's seams.)</summary>
    // retail: CPhysicsObj::InitDefaults (acclient.c:320853), reached from CPartArray::InitDefaults (acclient.c:326157)
    private static PhysicsState InitDefaults(PhysicsWorld world, PhysicsObj obj, ObjectModel model, PhysicsState state)
    {
        if ((state & PhysicsState.Static) != 0)
        {
            if (model.DefaultAnimId != 0)
            {
                state |= PhysicsState.HasDefaultAnim;
            }

            if (model.DefaultScriptId != 0)
            {
                state |= PhysicsState.HasDefaultScript;
            }

            if ((state & (PhysicsState.HasDefaultAnim | PhysicsState.HasDefaultScript)) != 0)
            {
                world.AddStaticAnimatingObject(obj);
            }
        }

        return state;
    }

    // retail: CPartArray::CreateSetup (acclient.c:326946) -> SetSetupID (acclient.c:326778) -> InitParts, SetPlacementFrame(0x65)
    private ObjectModel? CreateSetup(uint setupId)
    {
        if (_models.TryGetValue(setupId, out ObjectModel? cached))
        {
            return cached;
        }

        int before = _missingOrder.Count;
        ObjectModel? model = null;
        if (TryGetEntry(setupId, out ReadOnlyMemory<byte> bytes))
        {
            SetupEntry setup = SetupEntry.UnPack(bytes.Span);
            Expect("CSetup", setup.Id, setupId);
            SetupPhysics shape = setup.ToSetupPhysics();
            model = InitParts(setupId, setup.Parts, setup.DefaultScales, setup.PlacementFrames, shape, setup.SortingSphere,
                setup.DefaultAnimationId, setup.DefaultScriptId, setup.DefaultMotionTableId);
        }

        return Cache(setupId, model, before);
    }

    // retail: CPartArray::CreateMesh (acclient.c:326983) -> SetMeshID (acclient.c:326634) -> CSetup::makeSimpleSetup
    private ObjectModel? CreateMesh(uint gfxObjId)
    {
        if (_models.TryGetValue(gfxObjId, out ObjectModel? cached))
        {
            return cached;
        }

        int before = _missingOrder.Count;
        return Cache(gfxObjId, MakeSimpleSetup(gfxObjId), before);
    }

    // Keeps a model (or its failure, with the entries found missing while building it) for every later object of the id.
    private ObjectModel? Cache(uint dataId, ObjectModel? model, int missingBefore)
    {
        _models[dataId] = model;
        if (model is null)
        {
            _modelMissing[dataId] = _missingOrder.GetRange(missingBefore, _missingOrder.Count - missingBefore).ToArray();
        }

        return model;
    }

    /// <summary>The entries found missing when the object of <paramref name="dataId"/> failed to be made (empty when it was
    /// made, or failed for another reason).</summary>
    internal uint[] MissingFor(uint dataId) =>
        _modelMissing.TryGetValue(dataId, out uint[]? ids) ? ids : (_modelMissing.TryGetValue(dataId | 0x02000000u, out ids) ? ids : []);

    /// <summary>One part, the GfxObj itself, at placement key 0 (the identity); the sorting sphere is the GfxObj's physics
    /// sphere, else its drawing sphere (the drawing tree's root sphere), else none.</summary>
    // retail: CSetup::makeSimpleSetup (acclient.c:334455)
    private ObjectModel? MakeSimpleSetup(uint gfxObjId)
    {
        GfxObjEntry? root = GetGfxObj(gfxObjId);
        Sphere sorting = root?.PhysicsSphere ?? root?.DrawingSphere ?? default;
        var placement = new Dictionary<uint, Frame[]> { [0] = [Frame.Identity] };
        var shape = new SetupPhysics(ReadOnlySpan<Sphere>.Empty, ReadOnlySpan<CylSphere>.Empty, 0f, 0f, 0f, 0f);
        return InitParts(gfxObjId, [gfxObjId], ReadOnlySpan<Vector3>.Empty, placement, shape, sorting, 0, 0, 0);
    }

    /// <summary>Every part through <c>makePhysicsPart</c>: one part that cannot be made fails the whole setup. Default scales
    /// are copied onto the parts; the placement frame is 0x65, else key 0, else none (the parts stay at the object's frame).</summary>
    // retail: CPartArray::InitParts (acclient.c:325273) with CPartArray::SetPlacementFrame (acclient.c:326817)
    private ObjectModel? InitParts(uint dataId, ReadOnlySpan<uint> partIds, ReadOnlySpan<Vector3> defaultScales,
        IReadOnlyDictionary<uint, Frame[]> placements, SetupPhysics shape, Sphere sorting, uint anim, uint script, uint mtable)
    {
        int numParts = partIds.Length;
        var physics = new GfxObjPhysics?[numParts];
        var frames = new Frame[numParts];
        var scales = new Vector3[numParts];
        var boxes = new PartBox[numParts];
        if (!placements.TryGetValue(0x65, out Frame[]? placement))
        {
            placements.TryGetValue(0, out placement);
        }

        for (int i = 0; i < numParts; i++)
        {
            if (!MakePhysicsPart(partIds[i], out GfxObjEntry? gfx, out bool always2D))
            {
                return null;
            }

            physics[i] = gfx.Physics;
            // non-retail: a part the placement frame does not cover stays at the object's frame (retail leaves it unplaced)
            frames[i] = placement is not null && i < placement.Length ? placement[i] : Frame.Identity;
            scales[i] = defaultScales.IsEmpty ? Vector3.One : defaultScales[i];
            // non-retail: a part frame or default scale outside the library's domains fails the model here, before any object
            // is made (a part array would refuse it half-way)
            if (!InputLimits.IsChildFrameInDomain(frames[i]))
            {
                throw new RetailDataFormatException("CSetup", 0, $"0x{dataId:X8}: part {i}'s placement frame is outside the library's domain");
            }

            if (!InputLimits.IsScaleInDomain(scales[i].X) || !InputLimits.IsScaleInDomain(scales[i].Y) || !InputLimits.IsScaleInDomain(scales[i].Z))
            {
                throw new RetailDataFormatException("CSetup", 0, $"0x{dataId:X8}: part {i}'s default scale is outside [0.01, 100]");
            }
            (Vector3 min, Vector3 max) = BoundingBox(gfx.Vertices);
            // retail: gfxobj[0]->physics_sphere, else drawing_sphere (CEnvCell::find_transit_cells(parts), acclient.c:348406)
            Sphere? partSphere = gfx.PhysicsSphere ?? gfx.DrawingSphere;
            boxes[i] = new PartBox(frames[i], min, max, always2D, partSphere);
        }

        return new ObjectModel(dataId, shape, sorting, physics, frames, scales, boxes, anim, script, mtable);
    }

    /// <summary>A part's GfxObj array: the degrade table the GfxObj names, when the source holds it, gives <c>gfxobj[0]</c>
    /// (its first level); otherwise the GfxObj itself. False when the GfxObj or that first level is missing.</summary>
    // retail: CPhysicsPart::makePhysicsPart (acclient.c:315550) -> CPhysicsPart::SetPart (acclient.c:315524) ->
    // CPhysicsPart::LoadGfxObjArray (acclient.c:314891)
    private bool MakePhysicsPart(uint gfxObjId, [System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out GfxObjEntry? gfx0, out bool always2D)
    {
        always2D = false;
        gfx0 = null;
        if (gfxObjId == 0)
        {
            return false;
        }

        GfxObjEntry? root = GetGfxObj(gfxObjId);
        if (root is null)
        {
            return false;
        }

        GfxObjDegradeInfoEntry? degrades = null;
        if (root.DegradeId != 0 && TryGetEntry(root.DegradeId, out ReadOnlyMemory<byte> bytes, reportMissing: false))
        {
            degrades = GfxObjDegradeInfoEntry.UnPack(bytes.Span);
            Expect("GfxObjDegradeInfo", degrades.Id, root.DegradeId);
        }

        if (degrades is null)
        {
            gfx0 = root;
            return true;
        }

        if (degrades.Degrades.IsEmpty)
        {
            return false;
        }

        // retail: CPhysicsPart::Always2D (acclient.c:314641)
        always2D = degrades.Degrades[0].DegradeMode != 1;
        gfx0 = degrades.Degrades[0].GfxObjId == 0 ? null : GetGfxObj(degrades.Degrades[0].GfxObjId);
        return gfx0 is not null;
    }

    private GfxObjEntry? GetGfxObj(uint id)
    {
        if (_gfxObjs.TryGetValue(id, out GfxObjEntry? cached))
        {
            return cached;
        }

        GfxObjEntry? gfx = null;
        if (TryGetEntry(id, out ReadOnlyMemory<byte> bytes))
        {
            gfx = GfxObjEntry.UnPack(bytes.Span);
            Expect("CGfxObj", gfx.Id, id);
        }

        _gfxObjs[id] = gfx;
        return gfx;
    }

    // The GfxObj's bounding box over its vertices (zero without vertices).
    // retail: CGfxObj::init_end (acclient.c:356199)
    private static (Vector3 Min, Vector3 Max) BoundingBox(ReadOnlySpan<Vector3> vertices)
    {
        if (vertices.IsEmpty)
        {
            return (Vector3.Zero, Vector3.Zero);
        }

        Vector3 min = vertices[0], max = vertices[0];
        for (int i = 1; i < vertices.Length; i++)
        {
            min = Vector3.Min(min, vertices[i]);
            max = Vector3.Max(max, vertices[i]);
        }

        return (min, max);
    }

    private bool TryGetEntry(uint id, out ReadOnlyMemory<byte> bytes, bool reportMissing = true)
    {
        if (_source.TryGetEntry(id, out bytes))
        {
            return true;
        }

        if (reportMissing && _missing.Add(id))
        {
            _missingOrder.Add(id);
        }
        else if (reportMissing)
        {
            _missingOrder.Add(id);
        }

        return false;
    }

    // An entry whose own id is not the id it was asked for is not that entry.
    private static void Expect(string structure, uint got, uint asked)
    {
        if (got != asked)
        {
            throw new RetailDataFormatException(structure, 0, $"the entry asked for as 0x{asked:X8} holds 0x{got:X8}");
        }
    }
}
