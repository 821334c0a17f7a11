using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Physics.Collision;

// The moving object's object-collision rules.
internal sealed partial class ObjectInfo
{
    // retail: OBJECTINFO::init (acclient.c:314117), the weenie part: IS_IMPENETRABLE, IS_PLAYER, IS_PK, IS_PKLITE.
    private void AddWeenieState(IWeenieObject? weenie)
    {
        if (weenie is null)
        {
            return;
        }

        if (weenie.IsImpenetrable)
        {
            State |= ObjectInfoState.IsImpenetrable;
        }

        if (weenie.IsPlayer)
        {
            State |= ObjectInfoState.IsPlayer;
        }

        if (weenie.IsPK)
        {
            State |= ObjectInfoState.IsPK;
        }

        if (weenie.IsPKLite)
        {
            State |= ObjectInfoState.IsPKLite;
        }
    }

    /// <summary>
    /// True when the moving missile does not collide with <paramref name="other"/>: missiles never hit missiles; a
    /// missile (other than at its target) passes ethereal game objects and, when it has a target, other creatures.
    /// </summary>
    // retail: OBJECTINFO::missile_ignore (acclient.c:314069)
    public bool MissileIgnore(PhysicsObj other)
    {
        System.ArgumentNullException.ThrowIfNull(other);
        if ((other.State & PhysicsState.Missile) != 0)
        {
            return true;
        }

        if (Object is null || (Object.State & PhysicsState.Missile) == 0 || other.Id == TargetId)
        {
            return false;
        }

        IWeenieObject? weenie = other.Weenie;
        if (weenie is null)
        {
            return false;
        }

        return (other.State & PhysicsState.Ethereal) != 0 || (TargetId != 0 && weenie.IsCreature);
    }
}
