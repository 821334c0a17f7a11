using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision;

/// <summary>
/// The moving spheres of one sweep and every position the sweep keeps: where it began, where it is (the last valid
/// place), where it is testing (the check position), the backup for a step down, and the walkable polygon bookkeeping.
/// Retail: <c>SPHEREPATH</c> (acclient.h:32625, PORTAL/cphysics/CSpherePath.c). Owned by a pooled <see cref="Transition"/>:
/// every array is allocated once, in the constructor.
/// </summary>
/// <remarks>
/// Coordinates: <see cref="LocalSphere"/> is object-local (scaled); <see cref="GlobalSphere"/> and
/// <see cref="GlobalCurrCenter"/> are local to the landblock of <see cref="CheckPos"/> and <see cref="CurrPos"/>
/// respectively (retail's "global" means landblock-local). Positions are copied by value where retail kept a pointer
/// (<see cref="BeginPos"/>, <see cref="EndPos"/>); <see cref="HasBeginPos"/> stands for a non-null begin pointer.
/// </remarks>
internal sealed partial class SpherePath
{
    /// <summary>Most spheres a path carries. Retail: <c>init_sphere</c> clamps to 2 (acclient.c:313646).</summary>
    public const int MaxSpheres = 2;

    /// <summary>Compute every cache the plain retail way (see <see cref="Transition.ReferencePaths"/>).</summary>
    public bool ReferencePaths;

    /// <summary>Creates an empty path with its sphere arrays allocated.</summary>
    public SpherePath()
    {
        Init();
    }

    /// <summary>Number of spheres in use (0..2). Retail: <c>num_sphere</c>.</summary>
    public int NumSphere { get; private set; }

    /// <summary>The object's spheres, scaled, in object-local coordinates. Retail: <c>local_sphere</c>.</summary>
    public Sphere[] LocalSphere { get; } = new Sphere[MaxSpheres];

    /// <summary>The lowest point of the first local sphere. Retail: <c>local_low_point</c>.</summary>
    public Vector3 LocalLowPoint;

    /// <summary>The spheres placed at <see cref="CheckPos"/>, landblock-local. Retail: <c>global_sphere</c>.</summary>
    public Sphere[] GlobalSphere { get; } = new Sphere[MaxSpheres];

    /// <summary>The lowest point of the first sphere at <see cref="CheckPos"/>. Retail: <c>global_low_point</c>.</summary>
    public Vector3 GlobalLowPoint;

    /// <summary>The spheres expressed in a walkable polygon's local space. Retail: <c>localspace_sphere</c>.</summary>
    public Sphere[] LocalSpaceSphere { get; } = new Sphere[MaxSpheres];

    /// <summary>Lowest point of the first local-space sphere. Retail: <c>localspace_low_point</c>.</summary>
    public Vector3 LocalSpaceLowPoint;

    /// <summary>Sphere centres at <see cref="CurrPos"/> in the walkable's local space. Retail: <c>localspace_curr_center</c>.</summary>
    public Vector3[] LocalSpaceCurrCenter { get; } = new Vector3[MaxSpheres];

    /// <summary>Sphere centres at <see cref="CurrPos"/>, landblock-local. Retail: <c>global_curr_center</c>.</summary>
    public Vector3[] GlobalCurrCenter { get; } = new Vector3[MaxSpheres];

    /// <summary>The position whose local space <see cref="LocalSpaceSphere"/> is in. Retail: <c>localspace_pos</c>.</summary>
    public Position LocalSpacePos;

    /// <summary>The world up axis in that local space. Retail: <c>localspace_z</c>.</summary>
    public Vector3 LocalSpaceZ;

    /// <summary>The cell the sweep began in. Retail: <c>begin_cell</c>.</summary>
    public ObjCell? BeginCell;

    /// <summary>True for a sweep (retail's non-null <c>begin_pos</c>); false for a placement.</summary>
    public bool HasBeginPos;

    /// <summary>Where the sweep began (valid when <see cref="HasBeginPos"/>). Retail: <c>*begin_pos</c>.</summary>
    public Position BeginPos;

    /// <summary>Where the sweep is going. Retail: <c>*end_pos</c>.</summary>
    public Position EndPos;

    /// <summary>The cell of the last valid position. Retail: <c>curr_cell</c>.</summary>
    public ObjCell? CurrCell;

    /// <summary>The last valid position. Retail: <c>curr_pos</c>.</summary>
    public Position CurrPos;

    /// <summary>This step's movement after <c>adjust_offset</c>. Retail: <c>global_offset</c>.</summary>
    public Vector3 GlobalOffset;

    /// <summary>A step up is in progress. Retail: <c>step_up</c>.</summary>
    public bool StepUp;

    /// <summary>The normal of the surface being stepped up. Retail: <c>step_up_normal</c>.</summary>
    public Vector3 StepUpNormal;

    /// <summary>A BSP asked for a step-up check (set by <see cref="SetCollide"/>). Retail: <c>collide</c>.</summary>
    public bool Collide;

    /// <summary>The cell of the position being tested. Retail: <c>check_cell</c>.</summary>
    public ObjCell? CheckCell;

    /// <summary>The position being tested. Retail: <c>check_pos</c>.</summary>
    public Position CheckPos;

    /// <summary>The kind of insertion. Retail: <c>insert_type</c>.</summary>
    public InsertType InsertType;

    /// <summary>A step down is in progress. Retail: <c>step_down</c>.</summary>
    public bool StepDown;

    /// <summary>Saved <see cref="InsertType"/> while a nested insert runs. Retail: <c>backup</c>.</summary>
    public InsertType Backup;

    /// <summary>Saved <see cref="CheckCell"/>. Retail: <c>backup_cell</c>.</summary>
    public ObjCell? BackupCell;

    /// <summary>Saved <see cref="CheckPos"/>. Retail: <c>backup_check_pos</c>.</summary>
    public Position BackupCheckPos;

    /// <summary>Retail: <c>obstruction_ethereal</c> (object collisions).</summary>
    public bool ObstructionEthereal;

    /// <summary>The cell list reached an interior (env) cell. Retail: <c>hits_interior_cell</c>.</summary>
    public bool HitsInteriorCell;

    /// <summary>Retail: <c>bldg_check</c> (buildings).</summary>
    public bool BldgCheck;

    /// <summary>The smallest normal Z a walkable surface needs during this step. Retail: <c>walkable_allowance</c>.</summary>
    public float WalkableAllowance;

    /// <summary>How much of the step down is left (1 = none used). Retail: <c>walk_interp</c>.</summary>
    public float WalkInterp;

    /// <summary>The height of the step down in progress, in metres. Retail: <c>step_down_amt</c>.</summary>
    public float StepDownAmt;

    /// <summary>The sphere tested against <see cref="Walkable"/>. Retail: <c>walkable_check_pos</c>.</summary>
    public Sphere WalkableCheckPos;

    /// <summary>The walkable polygon found by a BSP (null on terrain). Retail: <c>walkable</c>.</summary>
    public Polygon? Walkable;

    /// <summary>A walkable check (probe step down) is in progress. Retail: <c>check_walkable</c>.</summary>
    public bool CheckWalkable;

    /// <summary>The up axis in the walkable polygon's space. Retail: <c>walkable_up</c>.</summary>
    public Vector3 WalkableUp;

    /// <summary>The position whose space the walkable polygon is in. Retail: <c>walkable_pos</c>.</summary>
    public Position WalkablePos;

    /// <summary>The scale of the walkable polygon's object. Retail: <c>walkable_scale</c>.</summary>
    public float WalkableScale;

    /// <summary>The cell array matches the check position. Retail: <c>cell_array_valid</c>.</summary>
    public bool CellArrayValid;

    /// <summary>A BSP's negative-side hit asks for a step up rather than a slide. Retail: <c>neg_step_up</c>.</summary>
    public bool NegStepUp;

    /// <summary>The normal of that negative-side hit. Retail: <c>neg_collision_normal</c>.</summary>
    public Vector3 NegCollisionNormal;

    /// <summary>A BSP reported a negative-side polygon hit. Retail: <c>neg_poly_hit</c>.</summary>
    public bool NegPolyHit;

    /// <summary>A placement that does not fit may search nearby. Retail: <c>placement_allows_sliding</c>.</summary>
    public bool PlacementAllowsSliding;

    /// <summary>Resets the flags and references (not the sphere data). Retail: <c>SPHEREPATH::init</c>.</summary>
    // retail: SPHEREPATH::init (acclient.c:313430)
    public void Init()
    {
        NumSphere = 0;
        BeginCell = null;
        HasBeginPos = false;
        CurrCell = null;
        CheckCell = null;
        InsertType = InsertType.Transition;
        StepDown = false;
        StepUp = false;
        Collide = false;
        HitsInteriorCell = false;
        BldgCheck = false;
        ObstructionEthereal = false;
        BackupCell = null;
        WalkableAllowance = 0f;
        Walkable = null;
        CheckWalkable = false;
        CellArrayValid = false;
        NegStepUp = false;
        NegPolyHit = false;
        PlacementAllowsSliding = true;
    }

    /// <summary>
    /// Loads up to two of the object's spheres, scaled by <paramref name="scale"/>, and the low point of the first.
    /// </summary>
    /// <exception cref="ArgumentException">No sphere is supplied.</exception>
    // retail: SPHEREPATH::init_sphere (acclient.c:313646)
    public void InitSphere(ReadOnlySpan<Sphere> spheres, float scale)
    {
        if (spheres.Length == 0)
        {
            throw new ArgumentException("A sphere path needs at least one sphere.", nameof(spheres));
        }

        NumSphere = spheres.Length <= MaxSpheres ? spheres.Length : MaxSpheres;
        for (int i = 0; i < NumSphere; i++)
        {
            Vector3 c = spheres[i].Center;
            LocalSphere[i] = new Sphere(new Vector3(scale * c.X, scale * c.Y, scale * c.Z), scale * spheres[i].Radius);
        }

        Sphere s0 = LocalSphere[0];
        LocalLowPoint = new Vector3(s0.Center.X, s0.Center.Y, (float)((double)s0.Center.Z - s0.Radius));
    }

    /// <summary>
    /// Starts a path: a sweep from <paramref name="beginPos"/> to <paramref name="endPos"/> when a begin position is given,
    /// otherwise a placement at <paramref name="endPos"/>.
    /// </summary>
    // retail: SPHEREPATH::init_path (acclient.c:314042)
    public void InitPath(ObjCell? beginCell, bool hasBeginPos, in Position beginPos, in Position endPos)
    {
        BeginCell = beginCell;
        HasBeginPos = hasBeginPos;
        BeginPos = beginPos;
        EndPos = endPos;
        CurrPos = hasBeginPos ? beginPos : endPos;
        CurrCell = beginCell;
        CacheGlobalCurrCenter(hasBeginPos ? beginPos.Frame : endPos.Frame);
        InsertType = hasBeginPos ? InsertType.Transition : InsertType.Placement;
    }

    /// <summary>
    /// Records a negative-side polygon hit from a BSP: the sphere touched a polygon it is moving away from (or the second
    /// sphere touched one). The transition then steps up (<paramref name="stepUp"/>) or slides along the reversed normal.
    /// </summary>
    // retail: SPHEREPATH::set_neg_poly_hit (acclient.c:360742)
    public void SetNegPolyHit(bool stepUp, Vector3 collisionNormal)
    {
        NegStepUp = stepUp;
        NegPolyHit = true;
        NegCollisionNormal = new Vector3(-collisionNormal.X, -collisionNormal.Y, -collisionNormal.Z);
    }
}
