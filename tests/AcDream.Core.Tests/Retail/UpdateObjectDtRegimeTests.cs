using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// update_object's time slicing (acclient.c:323080) for both profiles, observed through the world's step observer.
/// Each test places an object at client time <see cref="Start"/>, moves the client clock by dt and calls UpdateObject once.
/// </summary>
public class UpdateObjectDtRegimeTests
{
    private const double Start = 100.0;

    private static (PhysicsObj Obj, StepRecorder Steps) Setup(PhysicsProfile profile)
    {
        PhysicsWorld world = TickTestContext.World(Start, profile);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 50f));
        Assert.Equal(Start, obj.UpdateTime);
        var steps = new StepRecorder();
        world.StepObserver = steps;
        return (obj, steps);
    }

    private static double Run(PhysicsObj obj, double dt)
    {
        double now = Start + dt;
        obj.World.SetCurrentTime(now);
        obj.UpdateObject();
        return now;
    }

    [Fact]
    public void Retail_DtBelowEpsilon_NoStep_UpdateTimeIsNow()
    {
        var (obj, steps) = Setup(PhysicsProfile.Retail);
        double now = Run(obj, 0.0001); // 0.0001 <= EPSILON (0.0002): consumed, nothing simulated
        Assert.Equal(0, steps.Count);
        Assert.Equal(now, obj.UpdateTime);
    }

    [Fact]
    public void Retail_DtOneSixtieth_OneWholeStep_NoMinQuantumTest()
    {
        var (obj, steps) = Setup(PhysicsProfile.Retail);
        double now = Run(obj, 1.0 / 60.0);
        double dt = now - Start; // ~0.016667 > EPSILON and <= 0.2: one step of dt, even though dt < 1/30
        Assert.Equal(1, steps.Count);
        Assert.Equal((float)dt, steps.Quantum(0));
        Assert.Equal(1.0 / 60.0, steps.Quantum(0), 6);
        Assert.Equal(Start + dt, obj.UpdateTime);
    }

    [Fact]
    public void Retail_Dt0Point21_OneMaxQuantumStep_RemainderCarriedToNextCall()
    {
        var (obj, steps) = Setup(PhysicsProfile.Retail);
        Run(obj, 0.21);
        // 0.21 > 0.2: one 0.2 slice; 0.21 - 0.2 = 0.01 is not > 1/30, so it is not simulated and update_time = start + 0.2.
        Assert.Equal(1, steps.Count);
        Assert.Equal(0.2f, steps.Quantum(0));
        Assert.Equal(Start + PhysicsGlobals.MaxQuantum, obj.UpdateTime);

        // The unconsumed 0.01 is still owed: at +0.25 the object sees dt = 0.25 - 0.2 = 0.05 and steps once.
        steps.Clear();
        double now = Run(obj, 0.25);
        Assert.Equal(1, steps.Count);
        Assert.Equal((float)(now - (Start + PhysicsGlobals.MaxQuantum)), steps.Quantum(0));
        Assert.Equal(0.05f, steps.Quantum(0), 5);
    }

    [Fact]
    public void Retail_Dt0Point25_MaxQuantumThenRemainder()
    {
        var (obj, steps) = Setup(PhysicsProfile.Retail);
        double now = Run(obj, 0.25);
        double rest = (now - Start) - PhysicsGlobals.MaxQuantum; // ~0.05 > 1/30: simulated
        Assert.Equal(2, steps.Count);
        Assert.Equal(0.2f, steps.Quantum(0));
        Assert.Equal((float)rest, steps.Quantum(1));
        Assert.Equal(0.05f, steps.Quantum(1), 5);
        Assert.Equal(Start + PhysicsGlobals.MaxQuantum + rest, obj.UpdateTime);
    }

    [Fact]
    public void Retail_Dt0Point45_TwoMaxQuantaThenRemainder()
    {
        var (obj, steps) = Setup(PhysicsProfile.Retail);
        double now = Run(obj, 0.45);
        double rest = (now - Start) - PhysicsGlobals.MaxQuantum - PhysicsGlobals.MaxQuantum; // 0.45 - 0.4 = ~0.05
        Assert.Equal(3, steps.Count);
        Assert.Equal(0.2f, steps.Quantum(0));
        Assert.Equal(0.2f, steps.Quantum(1));
        Assert.Equal((float)rest, steps.Quantum(2));
        Assert.Equal(0.05f, steps.Quantum(2), 5);
        // The physics clock advances slice by slice: start + 0.2, + 0.2, + rest.
        Assert.Equal(Start + 0.2, steps.Time(0));
        Assert.Equal(Start + 0.2 + 0.2, steps.Time(1));
        Assert.Equal(Start + 0.2 + 0.2 + rest, obj.UpdateTime);
    }

    [Fact]
    public void Retail_Dt2Point5_AboveHugeQuantum_NoStep_UpdateTimeIsNow()
    {
        var (obj, steps) = Setup(PhysicsProfile.Retail);
        double now = Run(obj, 2.5);
        Assert.Equal(0, steps.Count);
        Assert.Equal(now, obj.UpdateTime);
    }

    [Fact]
    public void AceCompatible_DtBelowEpsilon_NoStep_TimeAccumulates()
    {
        var (obj, steps) = Setup(PhysicsProfile.AceCompatible);
        Run(obj, 0.0001);
        Assert.Equal(0, steps.Count);
        Assert.Equal(Start, obj.UpdateTime); // ACE returns before touching update_time
    }

    [Fact]
    public void AceCompatible_DtOneSixtieth_NoStep_TimeAccumulatesUntilAThirtieth()
    {
        var (obj, steps) = Setup(PhysicsProfile.AceCompatible);
        Run(obj, 1.0 / 60.0); // 0.0167 < 1/30: early return, time kept
        Assert.Equal(0, steps.Count);
        Assert.Equal(Start, obj.UpdateTime);

        double now = Run(obj, 0.04); // accumulated 0.04 >= 1/30, <= 0.1: one step of 0.04
        Assert.Equal(1, steps.Count);
        Assert.Equal((float)(now - Start), steps.Quantum(0));
        Assert.Equal(Start + (now - Start), obj.UpdateTime);
    }

    [Fact]
    public void AceCompatible_Dt0Point21_TwoTenthSlices_RemainderCarried()
    {
        var (obj, steps) = Setup(PhysicsProfile.AceCompatible);
        Run(obj, 0.21);
        // 0.21 -> 0.1, 0.1, remainder 0.01 (not > 1/30): update_time = start + 0.1 + 0.1.
        Assert.Equal(2, steps.Count);
        Assert.Equal(0.1f, steps.Quantum(0));
        Assert.Equal(0.1f, steps.Quantum(1));
        Assert.Equal(Start + 0.1 + 0.1, obj.UpdateTime);
    }

    [Fact]
    public void AceCompatible_Dt0Point25_TwoTenthSlicesThenRemainder()
    {
        var (obj, steps) = Setup(PhysicsProfile.AceCompatible);
        double now = Run(obj, 0.25);
        double rest = (now - Start) - 0.1 - 0.1; // ~0.05 > 1/30
        Assert.Equal(3, steps.Count);
        Assert.Equal(0.1f, steps.Quantum(0));
        Assert.Equal(0.1f, steps.Quantum(1));
        Assert.Equal((float)rest, steps.Quantum(2));
        Assert.Equal(Start + 0.1 + 0.1 + rest, obj.UpdateTime);
    }

    [Fact]
    public void AceCompatible_Dt0Point45_FourTenthSlicesThenRemainder()
    {
        var (obj, steps) = Setup(PhysicsProfile.AceCompatible);
        double now = Run(obj, 0.45);
        double rest = (now - Start) - 0.1 - 0.1 - 0.1 - 0.1; // ~0.05
        Assert.Equal(5, steps.Count);
        for (int i = 0; i < 4; i++)
        {
            Assert.Equal(0.1f, steps.Quantum(i));
        }

        Assert.Equal((float)rest, steps.Quantum(4));
        Assert.Equal(0.05f, steps.Quantum(4), 5);
    }

    [Fact]
    public void AceCompatible_Dt2Point5_NoStep_UpdateTimeIsNow()
    {
        var (obj, steps) = Setup(PhysicsProfile.AceCompatible);
        double now = Run(obj, 2.5);
        Assert.Equal(0, steps.Count);
        Assert.Equal(now, obj.UpdateTime);
    }

    [Fact]
    public void Retail_NegativeDt_NoStep_UpdateTimeResyncs()
    {
        var (obj, steps) = Setup(PhysicsProfile.Retail);
        double now = Run(obj, -1.0); // dt = -1 <= EPSILON: consumed (update_time = now)
        Assert.Equal(0, steps.Count);
        Assert.Equal(now, obj.UpdateTime);
    }
}
