using System.Collections.Generic;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Tests.Support;

/// <summary>A movement manager that records the motions its object reports done (<c>CPhysicsObj::MotionDone</c>).</summary>
internal sealed class MotionDoneRecorder : IMovementManager
{
    public readonly List<(MotionCommand Motion, bool Success)> Done = new();

    public void UseTime()
    {
    }

    public void LeaveGround()
    {
    }

    public void HitGround()
    {
    }

    public bool IsMovingTo() => false;

    public void HandleEnterWorld()
    {
    }

    public IMotionInterpreter? MotionInterpreter => null;

    public void MotionDone(MotionCommand motion, bool success) => Done.Add((motion, success));
}
