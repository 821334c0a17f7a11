// PhysicsObj — targets and detection: set_target, clear_target, receive_target_update, add_voyeur, receive_detection_update.
using System;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Objects;

// The object's side of target tracking (TargetManager) and of detection (DetectionManager): the calls those managers make on
// objects, and their part of leaving the world.
public sealed partial class PhysicsObj
{
    /// <summary>Starts tracking object <paramref name="objectId"/> (creating the target manager).</summary>
    // retail: CPhysicsObj::set_target (acclient.c:315991)
    internal void SetTarget(uint contextId, uint objectId, float radius, double quantum)
    {
        Touch();
        RareTargetManager().SetTarget(contextId, objectId, radius, quantum);
    }

    /// <summary>Stops tracking the target.</summary>
    // retail: CPhysicsObj::clear_target (acclient.c:316011)
    internal void ClearTarget() => TargetManager?.ClearTarget();

    /// <summary>Sets the tracked target's report look-ahead, seconds.</summary>
    // retail: CPhysicsObj::set_target_quantum (acclient.c:316021)
    internal void SetTargetQuantum(double newQuantum) => TargetManager?.SetTargetQuantum(newQuantum);

    /// <summary>The tracked target's report look-ahead, seconds (0 without a target).</summary>
    // retail: CPhysicsObj::get_target_quantum (acclient.c:316031)
    internal double TargetQuantum => TargetManager is { HasTarget: true } tm ? tm.TargetInfo.Quantum : 0.0;

    /// <summary>A report of the tracked target, from the target's manager.</summary>
    // retail: CPhysicsObj::receive_target_update (acclient.c:316046)
    internal void ReceiveTargetUpdate(in TargetInfo info)
    {
        Touch();
        TargetManager?.ReceiveUpdate(info);
    }

    /// <summary>Registers object <paramref name="objectId"/> as tracking this one (creating the target manager).</summary>
    // retail: CPhysicsObj::add_voyeur (acclient.c:316056)
    internal void AddVoyeur(uint objectId, float radius, float quantum)
    {
        Touch();
        RareTargetManager().AddVoyeur(objectId, radius, quantum);
    }

    /// <summary>Unregisters a voyeur.</summary>
    /// <returns>True when it was registered.</returns>
    // retail: CPhysicsObj::remove_voyeur (acclient.c:316076)
    internal bool RemoveVoyeur(uint objectId) => TargetManager is not null && TargetManager.RemoveVoyeur(objectId);

    private TargetManager RareTargetManager()
    {
        RareComponents rare = Rare(true)!;
        return rare.TargetManager ??= new TargetManager(this);
    }

    /// <summary>Passes a report (context 0 only) to the movement manager (its move-to) and the position manager (its stick).
    /// The engine's <see cref="HandleUpdateTarget"/>.</summary>
    internal void HandleUpdateTargetInternal(in TargetInfo info)
    {
        Touch();
        if (info.ContextId != 0)
        {
            return;
        }

        Movement?.HandleUpdateTarget(info);
        PositionManager?.HandleUpdateTarget(info);
    }

    /// <summary>The object leaves the world for good: its target tracking stops, its voyeurs are told
    /// (<see cref="TargetStatus.ExitWorld"/>), so a move-to onto it cancels and a stick to it ends, and its voyeur table is
    /// emptied.</summary>
    // retail part: the target manager's lines of CPhysicsObj::exit_world (acclient.c line 322204)
    internal void NotifyTargetExitWorld()
    {
        TargetManager? tm = TargetManager;
        if (tm is not null)
        {
            tm.ClearTarget();
            tm.NotifyVoyeurOfEvent(TargetStatus.ExitWorld);
            // The object is gone for good (retail deletes it: ~TargetManager destroys the voyeur table).
            tm.DestroyVoyeurs();
        }
    }

    /// <summary>A cell's detection report for this object's global detection: the detection manager counts it, and the object
    /// wakes (not static: active, its update time now when it was not active).</summary>
    // retail: CPhysicsObj::receive_detection_update (acclient.c:317646)
    internal void ReceiveDetectionUpdate(in DetectionInfo info)
    {
        if (DetectionManager is Managers.DetectionManager dm)
        {
            dm.ReceiveDetectionUpdate(info);
            ActivateIfNotStatic();
        }
    }

    /// <summary>The object leaves the world for good: exit_world destroys detection cylinder 0, then retail deletes the object
    /// and its detection manager (every cylinder dropped, no report).</summary>
    // retail part: the detection manager's lines of CPhysicsObj::exit_world (acclient.c line 322204) and ~CPhysicsObj
    internal void NotifyDetectionExitWorld()
    {
        if (DetectionManager is Managers.DetectionManager dm)
        {
            dm.DestroyDetectionCylsphere(0);
            dm.Destroy();
        }
    }
}
