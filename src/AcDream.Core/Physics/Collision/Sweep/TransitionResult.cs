using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Sweep;

/// <summary>
/// What a successful sweep hands back to the object: the parts of retail's <c>CTransition</c> (sphere_path.curr_pos,
/// curr_cell, collision_info) that <c>CPhysicsObj::SetPositionInternal(CTransition*)</c> (acclient.c:322503) commits.
/// </summary>
public struct TransitionResult
{
    /// <summary>Where the sweep ended (retail <c>sphere_path.curr_pos</c>).</summary>
    public Position CurrentPosition;

    /// <summary>Cell the sweep ended in (retail <c>sphere_path.curr_cell</c>); 0 means no cell (the object goes to the lost cell).</summary>
    public uint CurrentCellId;

    /// <summary>True when the sweep ended on a contact plane (retail <c>collision_info.contact_plane_valid</c>).</summary>
    public bool ContactPlaneValid;

    /// <summary>Contact plane normal (retail <c>collision_info.contact_plane.N</c>); copied even when not valid.</summary>
    public Vector3 ContactPlaneNormal;

    /// <summary>Contact plane distance (retail <c>collision_info.contact_plane.d</c>).</summary>
    public float ContactPlaneD;

    /// <summary>Cell of the contact plane (retail <c>collision_info.contact_plane_cell_id</c>).</summary>
    public uint ContactPlaneCellId;

    /// <summary>True when the contact plane is water (retail <c>collision_info.contact_plane_is_water</c>).</summary>
    public bool ContactPlaneIsWater;

    /// <summary>True when the sweep slid along a surface (retail <c>collision_info.sliding_normal_valid</c>).</summary>
    public bool SlidingNormalValid;

    /// <summary>The sliding normal (retail <c>collision_info.sliding_normal</c>).</summary>
    public Vector3 SlidingNormal;

    /// <summary>A result that ends at <paramref name="position"/> in its cell, in free space (no contact, no sliding).</summary>
    public static TransitionResult FreeSpace(in Position position) => new()
    {
        CurrentPosition = position,
        CurrentCellId = position.ObjCellId,
    };
}
