using AcDream.Core.Physics.Collision.Primitives;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects;

// The object's side of the collision sweep: its sweep flags and its collision response.
public sealed partial class PhysicsObj
{
    /// <summary>The object is in an ongoing collision with the environment (reported once until it ends). Retail:
    /// <c>colliding_with_environment</c>.</summary>
    public bool CollidingWithEnvironment { get; internal set; }

    /// <summary>
    /// The object's contact as seen by a sweep: false when it moves away from its contact plane faster than EPSILON.
    /// </summary>
    // retail: CPhysicsObj::check_contact (acclient.c:316535)
    internal bool CheckContact(bool contact)
    {
        if ((_transientState & TransientState.Contact) != 0)
        {
            Vector3 n = ContactPlaneNormal;
            if ((double)_velocity.Z * n.Z + (double)_velocity.Y * n.Y + (double)_velocity.X * n.X > PhysicsGlobals.Epsilon)
            {
                return false;
            }
        }

        return contact;
    }

    /// <summary>
    /// Seeds a transition with the object's contact state (unless <paramref name="adminMove"/>) and returns its sweep flags:
    /// EDGE_SLIDE from <see cref="PhysicsState.EdgeSlide"/>, CONTACT / ON_WALKABLE while in contact and not lifting off,
    /// PATH_CLIPPED for a missile.
    /// </summary>
    /// <remarks>FREE_ROTATE comes from the part array's <c>AllowsFreeHeading</c>, which the core's part array does not model
    /// (always false).</remarks>
    // retail: CPhysicsObj::get_object_info (acclient.c:319073)
    internal ObjectInfoState GetObjectInfo(Transition transition, bool adminMove)
    {
        System.ArgumentNullException.ThrowIfNull(transition);
        ObjectInfoState state = ObjectInfoState.None;
        if ((_state & PhysicsState.EdgeSlide) != 0)
        {
            state = ObjectInfoState.EdgeSlide;
        }

        if (!adminMove)
        {
            if ((_transientState & TransientState.Contact) != 0)
            {
                bool isWater = (_transientState & TransientState.WaterContact) != 0;
                var plane = new CollisionPlane(ContactPlaneNormal, ContactPlaneD);
                if (CheckContact(true))
                {
                    transition.InitContactPlane(ContactPlaneCellId, plane, isWater);
                    state |= ObjectInfoState.Contact;
                    if ((_transientState & TransientState.OnWalkable) != 0)
                    {
                        state |= ObjectInfoState.OnWalkable;
                    }
                }
                else
                {
                    transition.InitLastKnownContactPlane(ContactPlaneCellId, plane, isWater);
                }
            }

            if ((_transientState & TransientState.Sliding) != 0)
            {
                transition.InitSlidingNormal(SlidingNormal);
            }
        }

        if ((_state & PhysicsState.Missile) != 0)
        {
            state |= ObjectInfoState.PathClipped;
        }

        return state;
    }
}
