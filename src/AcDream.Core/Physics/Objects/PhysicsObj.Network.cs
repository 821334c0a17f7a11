using System;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
    private UpdateTimeStamps _updateTimes;

    /// <summary>Last accepted 16-bit timestamp of <paramref name="stamp"/> (retail <c>update_times</c>).</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="stamp"/> is not a defined stamp.</exception>
    public ushort GetUpdateTime(PhysicsTimeStamp stamp) => _updateTimes[StampIndex(stamp)];

    private int StampIndex(PhysicsTimeStamp stamp) =>
        (uint)stamp < (uint)UpdateTimeStamps.Count ? (int)stamp : throw new ArgumentOutOfRangeException(nameof(stamp));

    /// <summary>
    /// True when <paramref name="newTime"/> is newer than the stored stamp in 16-bit wrap-around order (a difference above
    /// 0x7FFF means the counter wrapped); a newer stamp is stored.
    /// </summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::newer_event (acclient.c:143014)
    public bool NewerEvent(PhysicsTimeStamp stamp, ushort newTime)
    {
        ThrowIfRemoved();
        ushort old = _updateTimes[StampIndex(stamp)];
        bool newer = Math.Abs(newTime - old) > 0x7FFF ? newTime < old : old < newTime;
        if (newer)
        {
            _updateTimes[(int)stamp] = newTime;
        }

        return newer;
    }

    /// <summary>
    /// Applies a server position: a stale teleport stamp is ignored; a newer teleport (or an object with no cell) teleports;
    /// otherwise, only with contact, an object at least 96 m from the player snaps there and a nearer one interpolates.
    /// </summary>
    /// <returns>True when the position was used.</returns>
    /// <param name="p">The reported position: the position domain of <see cref="StorePosition"/> (unit quaternion; origin
    /// within ±65,536 m, outdoor x, y in [−192, 384]).</param>
    /// <param name="teleportTimestamp">The report's 16-bit teleport timestamp (any value; wrap-around order).</param>
    /// <param name="contact">The report says the object is on the ground.</param>
    /// <exception cref="ArgumentException">The position is outside that domain; state unchanged.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::MoveOrTeleport (acclient.c:323450)
    public bool MoveOrTeleport(in Position p, ushort teleportTimestamp, bool contact)
    {
        ThrowIfRemoved();
        return MoveOrTeleportResult(p, teleportTimestamp, contact) >= ReceivedPositionResult.Interpolating;
    }

    // retail: CPhysicsObj::MoveOrTeleport (acclient.c:323450), answering which branch it took
    private ReceivedPositionResult MoveOrTeleportResult(in Position p, ushort teleportTimestamp, bool contact)
    {
        InputLimits.ThrowIfOutside(p, nameof(p));
        Touch();

        ushort stored = _updateTimes[(int)PhysicsTimeStamp.Teleport];
        bool older = Math.Abs(stored - teleportTimestamp) > 0x7FFF ? stored < teleportTimestamp : teleportTimestamp < stored;
        if (older)
        {
            return ReceivedPositionResult.StaleTeleport;
        }

        if (NewerEvent(PhysicsTimeStamp.Teleport, teleportTimestamp) || CellId == 0)
        {
            bool loaded = World.Sweep.FindsCell(this, p);
            TeleportHook();
            return Placement(loaded, SetPosition(p, SetPositionFlags.Teleport | SetPositionFlags.Slide | SetPositionFlags.SendPositionEvent));
        }

        if (!contact)
        {
            return ReceivedPositionResult.NoContact;
        }

        bool cellLoaded = World.Sweep.FindsCell(this, p);
        if (PlayerDistance >= PhysicsGlobals.PlayerActivityDistance)
        {
            PositionManager?.StopInterpolating();
            return Placement(cellLoaded, SetPositionSimple(p, true));
        }

        // non-retail: fidelity switch PhysicsProfile.RemoteSmoothing; the retail profile runs InterpolateTo(p, IsMovingTo())
        if (FollowRemoteReport(p, out SetPositionError placed))
        {
            return cellLoaded ? ReceivedPositionResult.Interpolating : ReceivedPositionResult.InterpolatingToUnloadedCell;
        }

        return Placement(cellLoaded, placed);
    }

    private static ReceivedPositionResult Placement(bool cellLoaded, SetPositionError e) =>
        !cellLoaded ? ReceivedPositionResult.LeftWorld
        : e == SetPositionError.Ok ? ReceivedPositionResult.Placed
        : ReceivedPositionResult.PlacementFailed;

    /// <summary>Drops every move-to, stickiness, interpolation, constraint and target before a teleport.</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::teleport_hook (acclient.c:322236)
    public void TeleportHook()
    {
        ThrowIfRemoved();
        Touch();
        Movement?.CancelMoveTo(MotionError.ITeleported);
        PositionManager?.StopSticking();
        PositionManager?.StopInterpolating();
        PositionManager?.StopConstraining();
        if (TargetManager is { } tm)
        {
            tm.ClearTarget();
            tm.NotifyVoyeurOfEvent(Managers.TargetStatus.Teleported);
        }
        World.Sweep.ReportCollisionEnd(this, true);
    }
}
