namespace AcDream.Core.Physics.Motion;

public sealed partial class MotionInterp
{
    /// <summary>Runs a movement request of types 1–5 (do or stop a raw or interpreted command, stop completely), then takes
    /// the motions the part array's motion table finished. Engine entry from <see cref="MovementManager"/>.</summary>
    /// <returns>The command's result; <see cref="MotionError.None"/> for a stop-completely;
    /// <see cref="MotionError.GeneralMovementFailure"/> (0x47) for another type.</returns>
    // retail: CMotionInterp::PerformMovement (acclient.c:344669)
    internal MotionError PerformMovement(in MovementStruct mvs)
    {
        MotionError r;
        switch (mvs.Type)
        {
            case MovementType.RawCommand:
                r = DoMotion(mvs.Motion, mvs.Params);
                break;
            case MovementType.InterpretedCommand:
                r = DoInterpretedMotion(mvs.Motion, mvs.Params);
                break;
            case MovementType.StopRawCommand:
                r = StopMotion(mvs.Motion, mvs.Params);
                break;
            case MovementType.StopInterpretedCommand:
                r = StopInterpretedMotion(mvs.Motion, mvs.Params);
                break;
            case MovementType.StopCompletely:
                StopCompletely();
                r = MotionError.None;
                break;
            default:
                return MotionError.GeneralMovementFailure;
        }

        _physicsObj?.CheckForCompletedMotions();
        return r;
    }
}
