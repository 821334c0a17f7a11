using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

/// <summary>
/// A hook that interpolates one float linearly from <see cref="StartValue"/> to <see cref="EndValue"/> over
/// <see cref="PhysicsObjHook.InterpolationTime"/> seconds of physics clock and applies it through
/// <see cref="PhysicsObj.ProcessFPHook"/> (retail <c>FPHook</c>, CPhysicsObjHooks.c). Done when the fraction reaches 1.
/// </summary>
/// <remarks>Instances come from a world's pool (<see cref="PhysicsWorld.RentFPHook"/>) and go back to it when done.</remarks>
public sealed class FPHook : PhysicsObjHook
{
    internal FPHook()
    {
    }

    /// <summary>Value at the start of the interpolation.</summary>
    public float StartValue { get; private set; }

    /// <summary>Value at the end of the interpolation.</summary>
    public float EndValue { get; private set; }

    internal FPHook? PoolNext { get; set; }

    /// <summary>True while the hook sits in its world's free list.</summary>
    internal bool InPool { get; set; }

    // retail: FPHook::FPHook (acclient.c:329679)
    internal void Init(PhysicsHookType type, double timeCreated, double delta, float startValue, float endValue, uint userData)
    {
        HookType = type;
        TimeCreated = timeCreated;
        InterpolationTime = delta;
        Prev = null;
        Next = null;
        Owner = null;
        UserData = userData;
        StartValue = startValue;
        EndValue = endValue;
    }

    /// <inheritdoc />
    // retail: FPHook::Execute (acclient.c:329694)
    public override bool Execute(PhysicsObj obj)
    {
        double elapsed = obj.World.PhysicsTime - TimeCreated;
        float frac;
        if (elapsed > 0.0)
        {
            frac = elapsed < InterpolationTime ? (float)(elapsed / InterpolationTime) : 1.0f;
        }
        else
        {
            frac = 0.0f;
        }

        float value = (float)(((double)EndValue - StartValue) * frac + StartValue);
        obj.ProcessFPHook(HookType, value, UserData);
        return frac == 1.0f;
    }

    /// <inheritdoc />
    protected internal override void OnRemoved(PhysicsWorld world) => world.ReturnFPHook(this);
}
