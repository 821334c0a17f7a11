using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Collision;

/// <summary>
/// One collision sweep: moves an object's spheres from a begin position towards an end position through the cells of
/// the world, stepping up and down, sliding along walls and edges, and leaves the last valid position in
/// <see cref="SpherePath"/>.<see cref="SpherePath.CurrPos"/> with the contact state in <see cref="CollisionInfo"/>.
/// Retail: <c>CTransition</c> (acclient.h:52329, PORTAL/cphysics/CTransition.c).
/// </summary>
/// <remarks>
/// Transitions are not created per sweep: a <see cref="TransitionPool"/> owns ten of them and hands them out by nesting
/// level, as retail's <c>makeTransition</c> does. Every array a sweep touches is allocated with the transition, so a
/// sweep allocates nothing. The file is split by concern: path (stepping and offset adjustment), insert (cell tests and
/// validation), step (step up and down), edge slide, placement.
/// </remarks>
internal sealed partial class Transition
{
    /// <summary>
    /// Step-down (and step-up) height, in metres, of an object that is not on walkable ground (and the landing allowance
    /// <see cref="PhysicsGlobals.LandingZ"/> goes with it). Retail: the literal 0.039999999 in <c>transitional_insert</c>
    /// (acclient.c:312833) and <c>step_up</c> (acclient.c:312793). Float bits 0x3D23D70A.
    /// </summary>
    public const float NotWalkingStepHeight = 0.039999999f;

    /// <summary>
    /// Consecutive no-progress frames after which a falling object is stood on a made-up flat plane. Retail: the third
    /// increment of <c>frames_stationary_fall</c> in <c>validate_transition</c> (acclient.c:312193).
    /// </summary>
    public const int StationaryFallFrames = 3;

    /// <summary>How far, in metres, a sliding placement searches around the requested spot. Retail: 4.0 in
    /// <c>find_placement_pos</c> (acclient.c:313014).</summary>
    public const float PlacementSearchDistance = 4.0f;

    /// <summary>Search distance, in metres, for a sphere smaller than <see cref="PlacementSmallRadius"/>. Retail: 2.0
    /// (acclient.c:313014).</summary>
    public const float PlacementSmallSearchDistance = 2.0f;

    /// <summary>Spheres below this radius, in metres, search half as many rings. Retail: 0.125 (acclient.c:313014).</summary>
    public const float PlacementSmallRadius = 0.125f;

    /// <summary>Smallest radius, in metres, used to space the placement rings. Retail: 0.47999999 (acclient.c:313014),
    /// float bits 0x3EF5C28F.</summary>
    public const float PlacementMinRadius = 0.47999999f;

    /// <summary>Retail's value of pi in the placement ring count: 3.1415999 (acclient.c:313014), float bits 0x40490FF9.</summary>
    public const float PlacementPi = 3.1415999f;

    /// <summary>Creates a transition whose cell lookups go to <paramref name="cells"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="cells"/> is null.</exception>
    public Transition(ICellSource cells)
    {
        ArgumentNullException.ThrowIfNull(cells);
        Cells = cells;
        Init();
    }

    /// <summary>Where cells are found by id (retail's <c>CObjCell::GetVisible</c> / <c>LScape::get_landcell</c>).</summary>
    public ICellSource Cells { get; }

    /// <summary>The object being moved. Retail: <c>object_info</c>.</summary>
    public ObjectInfo ObjectInfo { get; } = new();

    /// <summary>The spheres and positions of the sweep. Retail: <c>sphere_path</c>.</summary>
    public SpherePath SpherePath { get; } = new();

    /// <summary>What the sweep touched. Retail: <c>collision_info</c>.</summary>
    public CollisionInfo CollisionInfo { get; } = new();

    /// <summary>The cells the check position overlaps. Retail: <c>cell_array</c>.</summary>
    public CellArray CellArray { get; } = new();

    /// <summary>
    /// Run the sweep the plain retail way, without the exact shortcuts of the port (obstacles out of reach skipped, the
    /// outdoor cells of spheres inside one landblock's cells found directly, the check spheres taken from the current
    /// centres when they are equal). Off by default; the tests turn it on in one of two worlds to show that
    /// both give the same bits.
    /// </summary>
    internal bool ReferencePaths
    {
        get => CellArray.ReferencePaths;
        set
        {
            CellArray.ReferencePaths = value;
            SpherePath.ReferencePaths = value;
        }
    }

    /// <summary>Retail: <c>new_cell_ptr</c> (declared; unused by the outdoor sweep).</summary>
    public ObjCell? NewCellPtr { get; set; }

    /// <summary>Resets the transition for a new sweep.</summary>
    // retail: CTransition::init (acclient.c:311595)
    public void Init()
    {
        ObjectInfo.Clear();
        SpherePath.Init();
        CollisionInfo.Init();
        CellArray.Clear();
    }

    /// <summary>Loads the moving object's properties and its sweep state bits.</summary>
    // retail: CTransition::init_object (folded into OBJECTINFO::init, acclient.c:314117)
    public void InitObject(PhysicsObj obj, ObjectInfoState state)
    {
        ArgumentNullException.ThrowIfNull(obj);
        ObjectInfo.Init(obj, state);
    }

    /// <summary>Loads up to two spheres, scaled.</summary>
    // retail: CTransition::init_sphere (acclient.c:311619)
    public void InitSphere(ReadOnlySpan<Sphere> spheres, float scale) => SpherePath.InitSphere(spheres, scale);

    /// <summary>Starts a sweep from <paramref name="beginPos"/> in <paramref name="beginCell"/> to <paramref name="endPos"/>.</summary>
    // retail: CTransition::init_path (acclient.c:311625)
    public void InitPath(ObjCell? beginCell, in Position beginPos, in Position endPos) =>
        SpherePath.InitPath(beginCell, true, beginPos, endPos);

    /// <summary>Starts a placement at <paramref name="pos"/> in <paramref name="cell"/> (retail's null begin position).</summary>
    // retail: CTransition::init_path (acclient.c:311625) with begin_pos == 0
    public void InitPlacementPath(ObjCell? cell, in Position pos) => SpherePath.InitPath(cell, false, pos, pos);

    /// <summary>Seeds the current and last known contact planes from the object's contact state.</summary>
    // retail: CTransition::init_contact_plane (acclient.c:315598)
    public void InitContactPlane(uint cellId, in CollisionPlane plane, bool isWater)
    {
        CollisionInfo ci = CollisionInfo;
        ci.LastKnownContactPlaneValid = true;
        ci.LastKnownContactPlane = plane;
        ci.LastKnownContactPlaneIsWater = isWater;
        ci.LastKnownContactPlaneCellId = cellId;
        ci.ContactPlaneValid = true;
        ci.ContactPlane = plane;
        ci.ContactPlaneIsWater = isWater;
        ci.ContactPlaneCellId = cellId;
    }

    /// <summary>
    /// Seeds only the last known contact plane (the object is leaving it). Retail quirk kept: the cell id is written to
    /// the CURRENT contact plane's cell id, not the last known one.
    /// </summary>
    // retail: CTransition::init_last_known_contact_plane (acclient.c:315611)
    public void InitLastKnownContactPlane(uint cellId, in CollisionPlane plane, bool isWater)
    {
        CollisionInfo ci = CollisionInfo;
        ci.LastKnownContactPlaneValid = true;
        ci.LastKnownContactPlane = plane;
        ci.LastKnownContactPlaneIsWater = isWater;
        ci.ContactPlaneCellId = cellId;
    }

    /// <summary>Seeds the sliding normal (horizontal part, normalised; zero when too small).</summary>
    // retail: CTransition::init_sliding_normal (acclient.c:317252)
    public void InitSlidingNormal(Vector3 normal)
    {
        CollisionInfo ci = CollisionInfo;
        ci.SlidingNormalValid = true;
        ci.SlidingNormal = new Vector3(normal.X, normal.Y, 0f);
        if (VectorMath.NormalizeCheckSmall(ref ci.SlidingNormal))
        {
            ci.SlidingNormal = Vector3.Zero;
        }
    }

    /// <summary>Runs the sweep (or the placement). Returns true when a valid position was found.</summary>
    // retail: CTransition::find_valid_position (acclient.c:313418)
    public bool FindValidPosition() =>
        SpherePath.InsertType != InsertType.Transition ? FindPlacementPosition() : FindTransitionalPosition();

    /// <summary>
    /// Rebuilds the cell array around the check position; with <paramref name="findCell"/> also returns the cell that
    /// contains the first sphere's centre (retail passes a null out-pointer to skip that search).
    /// </summary>
    // retail: CTransition::build_cell_array (acclient.c:311674)
    public ObjCell? BuildCellArray(bool findCell)
    {
        SpherePath.CellArrayValid = true;
        SpherePath.HitsInteriorCell = false;
        return CellList.FindCellList(Cells, CellArray, SpherePath, findCell);
    }
}
