// PhysicsObj — motion interpreter calls: MakeMovementManager, DoInterpretedMotion, StopCompletely_Internal, MotionDone.
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Physics.Objects;

// The object's side of the motion interpreter: the calls CMotionInterp makes on its physics object, forwarded to the part
// array's motion table, and the movement manager's creation.
public sealed partial class PhysicsObj
{
    /// <summary>
    /// Creates the movement manager if absent (the world's <see cref="World.PhysicsWorld.MovementManagerFactory"/>, else
    /// the retail <see cref="Motion.MovementManager"/>), entering its default state when <paramref name="initMotion"/>, and
    /// activates a non-static object.
    /// </summary>
    /// <returns>The movement manager.</returns>
    /// <exception cref="System.InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::MakeMovementManager (acclient.c:317453)
    public IMovementManager MakeMovementManager(bool initMotion)
    {
        ThrowIfRemoved();
        Touch();
        if (Movement is null)
        {
            IMovementManager? custom = World.MovementManagerFactory?.Create(this);
            if (custom is not null)
            {
                Movement = custom;
            }
            else
            {
                var mm = Motion.MovementManager.Create(this, Weenie as IMotionWeenie);
                Movement = mm;
                if (initMotion)
                {
                    mm.EnterDefaultState();
                }
            }

            ActivateIfNotStatic();
        }

        return Movement;
    }

    // retail: CPhysicsObj::DoInterpretedMotion (acclient.c:315752)
    internal MotionError DoInterpretedMotion(MotionCommand motion, in MovementParameters p)
    {
        if (PartArray is null)
        {
            return MotionError.GeneralMovementFailure;
        }

        // retail: CPartArray::DoInterpretedMotion (acclient.c:326017): 7 without a motion-table manager
        IMotionPlayer? table = PartArray.MotionPlayer;
        return table is null ? MotionError.NoMotionTable : table.DoInterpretedMotion(motion, p);
    }

    // retail: CPhysicsObj::StopInterpretedMotion (acclient.c:315765)
    internal MotionError StopInterpretedMotion(MotionCommand motion, in MovementParameters p)
    {
        if (PartArray is null)
        {
            return MotionError.GeneralMovementFailure;
        }

        IMotionPlayer? table = PartArray.MotionPlayer;
        return table is null ? MotionError.NoMotionTable : table.StopInterpretedMotion(motion, p);
    }

    // retail: CPhysicsObj::StopCompletely_Internal (acclient.c:315787)
    internal void StopCompletelyInternal() => PartArray?.MotionPlayer?.StopCompletely();

    // retail: CPhysicsObj::InitializeMotionTables (acclient.c:315742)
    internal void InitializeMotionTables() => PartArray?.MotionPlayer?.InitializeMotionTables();

    // retail: CPhysicsObj::RemoveLinkAnimations (acclient.c:317144)
    internal void RemoveLinkAnimations() => PartArray?.HandleEnterWorld();

    /// <summary>Reports every motion the part array's motion table has finished to the movement manager.</summary>
    // retail: CPhysicsObj::CheckForCompletedMotions (acclient.c:317154) -> MotionTableManager::CheckForCompletedMotions
    internal void CheckForCompletedMotions()
    {
        IMotionPlayer? table = PartArray?.MotionPlayer;
        if (table is null)
        {
            return;
        }

        table.CheckForCompletedMotions();
        ReportCompletedMotions(table);
    }

    /// <summary>Hands every motion <paramref name="table"/> has reported done to the movement manager, oldest first (retail's
    /// manager calls <c>CPhysicsObj::MotionDone</c> for each as it finds it).</summary>
    // retail: CPhysicsObj::MotionDone (acclient.c:317096), once per motion the manager reports
    internal void ReportCompletedMotions(IMotionPlayer table)
    {
        while (table.TryTakeCompletedMotion(out MotionCommand motion, out bool success))
        {
            Movement?.MotionDone(motion, success);
        }
    }
}
