using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Core.Physics.Objects;

// The setup check: what keeps the object from walking (not retail; a client's diagnostic).
public sealed partial class PhysicsObj
{
    /// <summary>Largest step height that counts as "no Setup" (retail's 0.01 f default, acclient.c:325399).</summary>
    private const float NoSetupStepHeight = 0.0099999998f;

    /// <summary>
    /// What keeps this object from walking, stepping and colliding as a retail creature would: <see cref="ObjectSetupIssues.None"/>
    /// for a creature built from a Setup (<see cref="SimplePartArray(SetupPhysics, int)"/>) with a motion table, with a movement manager, entered
    /// into a world over terrain. Cheap; not part of the tick. Read it once the object is in place — after
    /// <see cref="EnterWorld"/> and, for the player, after setting <see cref="World.PhysicsWorld.Player"/> (which gives it its movement
    /// manager); before them it reports <see cref="ObjectSetupIssues.NotInCell"/> and
    /// <see cref="ObjectSetupIssues.NoMovementManager"/> even for a correctly built object. An issue is otherwise silent (the
    /// object does not move, moves at half speed, or takes one step and stops).
    /// </summary>
    public ObjectSetupIssues SetupIssues
    {
        get
        {
            ObjectSetupIssues issues = ObjectSetupIssues.None;
            IPartArray? parts = PartArray;
            if (parts is null)
            {
                issues |= ObjectSetupIssues.NoPartArray;
            }
            else
            {
                if (parts.NumSpheres == 0)
                {
                    issues |= ObjectSetupIssues.NoCollisionSpheres;
                }

                if (parts.MotionPlayer is null && Movement is null or Motion.MovementManager)
                {
                    issues |= ObjectSetupIssues.NoMotionTable;
                }

                if (parts.StepUpHeight <= NoSetupStepHeight || parts.StepDownHeight <= NoSetupStepHeight)
                {
                    issues |= ObjectSetupIssues.NoSetupStepHeights;
                }
            }

            if (Movement is null)
            {
                issues |= ObjectSetupIssues.NoMovementManager;
            }

            if (World.IsFreeSpace)
            {
                issues |= ObjectSetupIssues.FreeSpaceSweep;
            }

            if (CellId == 0)
            {
                issues |= ObjectSetupIssues.NotInCell;
            }

            return issues;
        }
    }
}
