using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Primitives;

/// <summary>
/// Which surfaces an object may stand or land on, by the z of the surface's unit normal (the cosine of its slope).
/// </summary>
/// <remarks>Walking uses <see cref="PhysicsGlobals.FloorZ"/> (0.66417414, a slope of about 48.4°); landing from a fall
/// accepts anything up to <see cref="PhysicsGlobals.LandingZ"/> (0.0871557, about 85°).</remarks>
public static class Walkability
{
    /// <summary>True when a surface with this normal is floor an object can walk on: <c>normal.z &gt;= floor_z</c>.</summary>
    // retail: CPhysicsObj::is_valid_walkable (acclient.c:316499)
    public static bool IsWalkable(Vector3 normal) => normal.Z >= PhysicsGlobals.FloorZ;

    /// <summary>True when a falling object can land on a surface with this normal: <c>normal.z &gt;= z_for_landing</c>
    /// (the test <c>step_down</c> applies with the landing allowance).</summary>
    // retail: CTransition::step_down (acclient.c:312628) with z_for_landing (acclient_data.h:1429)
    public static bool IsLandable(Vector3 normal) => normal.Z >= PhysicsGlobals.LandingZ;

    /// <summary>
    /// The walkable allowance the sweep uses: <see cref="PhysicsGlobals.FloorZ"/> for an object already on walkable
    /// ground, <see cref="PhysicsGlobals.LandingZ"/> otherwise.
    /// </summary>
    // retail: CTransition::step_up (acclient.c:312793) and transitional_insert (acclient.c:312833) choose z this way
    public static float WalkableAllowance(bool onWalkable) => onWalkable ? PhysicsGlobals.FloorZ : PhysicsGlobals.LandingZ;

    /// <summary>True when the terrain triangle is walkable floor (<see cref="IsWalkable(Vector3)"/> of its plane normal).</summary>
    public static bool IsWalkable(Polygon polygon)
    {
        System.ArgumentNullException.ThrowIfNull(polygon);
        return IsWalkable(polygon.Plane.N);
    }
}
