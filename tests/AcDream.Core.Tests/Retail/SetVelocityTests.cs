using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CPhysicsObj::set_velocity</c> (acclient.c:318577) stores the new velocity only when <c>Vector3::operator!=</c>
/// (acclient.c:156312) says it differs: <c>|new.x − old.x| &gt; 0.00019999999 || … y … || … z …</c>, i.e. some axis
/// differs by more than EPSILON (0.0002f, 0x3951B717). A change within EPSILON on every axis keeps the old velocity and
/// does not mark the jump; the object is activated either way.
/// </summary>
public class SetVelocityTests
{
    private static PhysicsObj Create()
    {
        var world = new PhysicsWorld();
        return TickTestContext.CreateObject(world, new Vector3(10f, 10f, 100f));
    }

    [Fact]
    public void ChangeWithinEpsilonOnEveryAxis_KeepsTheOldVelocity_AndDoesNotMarkTheJump()
    {
        PhysicsObj obj = Create();
        obj._velocity = new Vector3(1f, 2f, 3f);
        Assert.False(obj.JumpedThisFrame);
        obj.SetActive(false);

        // 1.0001f = 1.00010001659393310546875: |1.0001f − 1| = 1.0001659e-4 ≤ 2e-4; y and z differ by 1.5e-4 and 0.
        obj.SetVelocity(new Vector3(1.0001f, 2.00015f, 3f));

        Assert.Equal(new Vector3(1f, 2f, 3f), obj.Velocity);
        Assert.False(obj.JumpedThisFrame);
        Assert.True(obj.IsActive); // the activation below the compare runs regardless
    }

    [Fact]
    public void ChangeOfExactlyEpsilon_IsNotADifference_OneFloatStepMoreIs()
    {
        PhysicsObj obj = Create();
        obj._velocity = Vector3.Zero;
        Assert.False(obj.JumpedThisFrame);

        // |0.0002f − 0| = 0.0002f exactly (the difference of a float and 0 is exact): not > EPSILON.
        obj.SetVelocity(new Vector3(0f, 0.0002f, 0f));
        Assert.Equal(Vector3.Zero, obj.Velocity);
        Assert.False(obj.JumpedThisFrame);

        // The next float above EPSILON (0x3951B718) is a difference.
        float above = BitConverter.Int32BitsToSingle(0x3951B718);
        obj.SetVelocity(new Vector3(0f, 0f, -above));
        Assert.Equal(new Vector3(0f, 0f, -above), obj.Velocity);
        Assert.True(obj.JumpedThisFrame);
    }

    [Fact]
    public void OneAxisBeyondEpsilon_StoresAllThreeAxes()
    {
        PhysicsObj obj = Create();
        obj._velocity = new Vector3(1f, 2f, 3f);
        Assert.False(obj.JumpedThisFrame);

        // x within (1e-4), y within (0), z beyond (3.0003f − 3 = 2.9993e-4 > 2e-4): the whole new vector is stored.
        obj.SetVelocity(new Vector3(1.0001f, 2f, 3.0003f));

        Assert.Equal(new Vector3(1.0001f, 2f, 3.0003f), obj.Velocity);
        Assert.True(obj.JumpedThisFrame);
    }
}
