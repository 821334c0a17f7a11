using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.World;

public sealed partial class PhysicsWorld
{
    private FPHook? _freeHooks;
    private System.Random _random = new(0);

    /// <summary>Reseeds the world's random source (used by CallPES delays). Deterministic: seed 0 by default.</summary>
    public void SeedRandom(int seed) => _random = new System.Random(seed);

    // retail: Random::RollDice(lower, upper) for CallPES; our generator is System.Random, not retail's.
    internal float RollDice(float lower, float upper) => (float)(lower + (_random.NextDouble() * ((double)upper - lower)));

    /// <summary>Number of pooled hooks ready for reuse.</summary>
    public int FreeHookCount { get; private set; }

    /// <summary>Takes a hook from the pool (allocating only when the pool is empty) and initialises it.</summary>
    internal FPHook RentFPHook(PhysicsHookType type, double timeCreated, double delta, float startValue, float endValue, uint userData)
    {
        FPHook? h = _freeHooks;
        if (h is null)
        {
            h = new FPHook();
        }
        else
        {
            _freeHooks = h.PoolNext;
            h.PoolNext = null;
            h.InPool = false;
            FreeHookCount--;
        }

        h.Init(type, timeCreated, delta, startValue, endValue, userData);
        return h;
    }

    /// <summary>Returns a finished hook to the pool; a hook the pool already holds is ignored (a second return would make the
    /// free list point at itself and hand one hook to several objects).</summary>
    internal void ReturnFPHook(FPHook hook)
    {
        if (hook.InPool)
        {
            return;
        }

        hook.InPool = true;
        hook.PoolNext = _freeHooks;
        _freeHooks = hook;
        FreeHookCount++;
    }
}
