using AcDream.Core.Physics.Collision.Primitives;
using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Collision;

/// <summary>
/// What a sweep has touched: the contact plane it stands on (and the last one known), the sliding normal it moves along,
/// the normal of the last collision, the objects it hit and the stationary-fall counter. Retail: <c>COLLISIONINFO</c>
/// (acclient.h:52306). Owned by a pooled <see cref="Transition"/>; the object list grows only past its capacity.
/// </summary>
internal sealed class CollisionInfo
{
    private PhysicsObj?[] _collideObject = new PhysicsObj?[InitialObjectCapacity];

    /// <summary>Initial capacity of the collided-object list (retail grows its <c>DArray</c> by 10).</summary>
    public const int InitialObjectCapacity = 16;

    /// <summary>Creates an empty record.</summary>
    public CollisionInfo()
    {
        Init();
    }

    /// <summary>The last known contact plane is set. Retail: <c>last_known_contact_plane_valid</c>.</summary>
    public bool LastKnownContactPlaneValid;

    /// <summary>The plane the object stood on most recently. Retail: <c>last_known_contact_plane</c>.</summary>
    public CollisionPlane LastKnownContactPlane;

    /// <summary>That plane is water. Retail: <c>last_known_contact_plane_is_water</c>.</summary>
    public bool LastKnownContactPlaneIsWater;

    /// <summary>The object stands on <see cref="ContactPlane"/>. Retail: <c>contact_plane_valid</c>.</summary>
    public bool ContactPlaneValid;

    /// <summary>The plane the object stands on, local to <see cref="ContactPlaneCellId"/>'s landblock. Retail: <c>contact_plane</c>.</summary>
    public CollisionPlane ContactPlane;

    /// <summary>The cell whose landblock the contact plane is expressed in. Retail: <c>contact_plane_cell_id</c>.</summary>
    public uint ContactPlaneCellId;

    /// <summary>The cell of the last known contact plane. Retail: <c>last_known_contact_plane_cell_id</c>.</summary>
    public uint LastKnownContactPlaneCellId;

    /// <summary>The contact plane is a water surface. Retail: <c>contact_plane_is_water</c>.</summary>
    public bool ContactPlaneIsWater;

    /// <summary>The object is sliding along <see cref="SlidingNormal"/>. Retail: <c>sliding_normal_valid</c>.</summary>
    public bool SlidingNormalValid;

    /// <summary>The horizontal unit normal of the wall being slid along. Retail: <c>sliding_normal</c>.</summary>
    public Vector3 SlidingNormal;

    /// <summary>A collision normal was recorded. Retail: <c>collision_normal_valid</c>.</summary>
    public bool CollisionNormalValid;

    /// <summary>The unit normal of the last collision (zero when it was too small to normalise). Retail: <c>collision_normal</c>.</summary>
    public Vector3 CollisionNormal;

    /// <summary>Retail: <c>adjust_offset</c> (declared, unused by the sweep).</summary>
    public Vector3 AdjustOffset;

    /// <summary>Number of objects hit. Retail: <c>num_collide_object</c>.</summary>
    public int NumCollideObject;

    /// <summary>The most recent object hit with a state other than OK. Retail: <c>last_collided_object</c>.</summary>
    public PhysicsObj? LastCollidedObject;

    /// <summary>The sweep hit the environment (terrain or a cell's walls). Retail: <c>collided_with_environment</c>.</summary>
    public bool CollidedWithEnvironment;

    /// <summary>Consecutive sweeps that made no progress while falling (0..3). Retail: <c>frames_stationary_fall</c>.</summary>
    public int FramesStationaryFall;

    /// <summary>The objects hit, <see cref="NumCollideObject"/> long.</summary>
    public ReadOnlySpan<PhysicsObj?> CollideObjects => _collideObject.AsSpan(0, NumCollideObject);

    /// <summary>Clears the flags, counters and object list (plane values are left as they were, as in retail).</summary>
    // retail: COLLISIONINFO::init (acclient.c:311566)
    public void Init()
    {
        LastKnownContactPlaneValid = false;
        ContactPlaneValid = false;
        SlidingNormalValid = false;
        CollisionNormalValid = false;
        NumCollideObject = 0;
        LastCollidedObject = null;
        CollidedWithEnvironment = false;
        ContactPlaneCellId = 0;
        FramesStationaryFall = 0;
    }

    /// <summary>Sets the contact plane.</summary>
    // retail: COLLISIONINFO::set_contact_plane (acclient.c:311580)
    public void SetContactPlane(in CollisionPlane plane, bool isWater)
    {
        ContactPlaneValid = true;
        ContactPlane = plane;
        ContactPlaneIsWater = isWater;
    }

    /// <summary>Records a collision normal, normalised; a normal shorter than EPSILON is stored as zero.</summary>
    // retail: COLLISIONINFO::set_collision_normal (acclient.c:311725)
    public void SetCollisionNormal(Vector3 normal)
    {
        CollisionNormalValid = true;
        CollisionNormal = normal;
        if (VectorMath.NormalizeCheckSmall(ref CollisionNormal))
        {
            CollisionNormal = Vector3.Zero;
        }
    }

    /// <summary>Records a sliding normal: the horizontal part of <paramref name="normal"/>, normalised (zero when too small).</summary>
    // retail: COLLISIONINFO::set_sliding_normal (acclient.c:311743)
    public void SetSlidingNormal(Vector3 normal)
    {
        SlidingNormalValid = true;
        SlidingNormal = new Vector3(normal.X, normal.Y, 0f);
        if (VectorMath.NormalizeCheckSmall(ref SlidingNormal))
        {
            SlidingNormal = Vector3.Zero;
        }
    }

    /// <summary>Adds an object to the hit list once; a hit with a state other than OK also becomes the last collided object.</summary>
    // retail: COLLISIONINFO::add_object (acclient.c:718728)
    public void AddObject(PhysicsObj obj, TransitionState state)
    {
        for (int i = 0; i < NumCollideObject; i++)
        {
            if (ReferenceEquals(_collideObject[i], obj))
            {
                return;
            }
        }

        if (NumCollideObject >= _collideObject.Length)
        {
            // Retail grows by 10; we double (an allocation only when a sweep hits more objects than ever before).
            Array.Resize(ref _collideObject, _collideObject.Length * 2);
        }

        _collideObject[NumCollideObject++] = obj;
        if (state != TransitionState.Ok)
        {
            LastCollidedObject = obj;
        }
    }
}
