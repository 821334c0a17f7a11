using System;
using AcDream.Core.Physics.Collision.Sweep;

namespace AcDream.Core.Physics.World;

// The scratch result of a swept step, one per world rather than one per object (a step's result is dead once committed). A
// stack, so that a step run from a callback inside another object's step (a collision listener calling UpdateObject) gets a
// result of its own: the outer step's is never overwritten.
public sealed partial class PhysicsWorld
{
    private TransitionResult[] _stepScratch = new TransitionResult[4];
    private int _stepScratchDepth;

    /// <summary>The scratch result for a swept step about to start; pair with <see cref="LeaveStepScratch"/>.</summary>
    internal ref TransitionResult EnterStepScratch()
    {
        if (_stepScratchDepth == _stepScratch.Length)
        {
            // Only for steps nested deeper than ever before (the outer steps keep their results in the old array).
            Array.Resize(ref _stepScratch, _stepScratch.Length * 2);
        }

        return ref _stepScratch[_stepScratchDepth++];
    }

    /// <summary>Number of swept steps in progress (0 between ticks).</summary>
    internal int StepScratchDepth => _stepScratchDepth;

    /// <summary>Ends the step that took the innermost scratch result.</summary>
    internal void LeaveStepScratch() => _stepScratchDepth--;
}
