using AcDream.Core.Physics.Managers;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
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
