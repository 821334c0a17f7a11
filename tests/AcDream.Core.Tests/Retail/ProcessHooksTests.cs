using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>process_hooks (acclient.c:318640), FPHook::Execute (acclient.c:329694) and process_fp_hook (acclient.c:320571).</summary>
public class ProcessHooksTests
{
    private const double Q = 0.0625; // 1/16 s steps: exact in binary

    private sealed class CountingHook : PhysicsObjHook
    {
        private readonly int[] _log;
        private readonly int _name;
        private readonly int _doneAfter;

        public CountingHook(int[] log, int name, int doneAfter)
        {
            _log = log;
            _name = name;
            _doneAfter = doneAfter;
        }

        public int Runs { get; private set; }

        public PhysicsObjHook? ToAddDuringExecute { get; set; }

        public override bool Execute(PhysicsObj obj)
        {
            Runs++;
            _log[++_log[0]] = _name;
            if (ToAddDuringExecute is not null)
            {
                obj.AddHook(ToAddDuringExecute);
                ToAddDuringExecute = null;
            }

            return Runs >= _doneAfter;
        }
    }

    private sealed class CountingAnimHook : IAnimHook
    {
        public int Runs { get; private set; }

        public void Execute(PhysicsObj obj) => Runs++;
    }

    private sealed class ScriptRecorder : IScriptPlayer
    {
        public int Plays { get; private set; }

        public uint LastScript { get; private set; }

        public void PlayScript(PhysicsObj obj, uint scriptId)
        {
            Plays++;
            LastScript = scriptId;
        }
    }

    private static PhysicsObj Create(out PhysicsWorld world)
    {
        world = new PhysicsWorld(0.0);
        return TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), spheres: 0);
    }

    private static void TickTo(PhysicsWorld world, int step) => Assert.True(world.Tick(step * Q));

    [Fact]
    public void TranslucencyFade_ReachesEndExactlyAtInterpolationTime_ThenIsRemoved()
    {
        PhysicsObj obj = Create(out PhysicsWorld world);
        int pooled = world.FreeHookCount;
        obj.SetTranslucency2(0f, 1f, 0.5); // created at physics time 0, over 0.5 s
        Assert.Equal(pooled - 1, world.FreeHookCount);

        for (int k = 1; k <= 7; k++)
        {
            TickTo(world, k);
            // After step k the physics clock is k/16: fraction (k/16)/0.5 = k/8, value = (1 - 0) * k/8 + 0.
            Assert.Equal(k / 8f, obj.Translucency);
            Assert.NotNull(obj.Hooks);
        }

        TickTo(world, 8); // elapsed 0.5 is not < 0.5: fraction 1, value 1, done
        Assert.Equal(1f, obj.Translucency);
        Assert.Null(obj.Hooks);
        Assert.Equal(pooled, world.FreeHookCount); // the hook went back to the pool
        Assert.Equal(1f, ((SimplePartArray)obj.PartArray!).Translucency);
    }

    [Fact]
    public void Hooks_RunNewestFirst_AndAFinishedHookDoesNotRunAgain()
    {
        PhysicsObj obj = Create(out PhysicsWorld world);
        int[] log = new int[16];
        var older = new CountingHook(log, 1, doneAfter: 3);
        var newer = new CountingHook(log, 2, doneAfter: 1);
        obj.AddHook(older);
        obj.AddHook(newer); // pushed at the head

        TickTo(world, 1);
        Assert.Equal(2, log[0]);
        Assert.Equal(2, log[1]); // newest first
        Assert.Equal(1, log[2]);
        Assert.Same(older, obj.Hooks); // newer reported done and was unlinked

        TickTo(world, 2);
        TickTo(world, 3);
        TickTo(world, 4);
        Assert.Equal(1, newer.Runs);
        Assert.Equal(3, older.Runs); // removed once it reported done on its third run
        Assert.Null(obj.Hooks);
    }

    [Fact]
    public void HookAddedDuringExecute_WaitsForTheNextStep()
    {
        PhysicsObj obj = Create(out PhysicsWorld world);
        int[] log = new int[16];
        var late = new CountingHook(log, 9, doneAfter: 100);
        var first = new CountingHook(log, 1, doneAfter: 100) { ToAddDuringExecute = late };
        obj.AddHook(first);

        TickTo(world, 1);
        Assert.Equal(0, late.Runs); // next was read before Execute; the new head is not visited this pass
        TickTo(world, 2);
        Assert.Equal(1, late.Runs);
        Assert.Same(late, obj.Hooks);
    }

    [Fact]
    public void AnimHooks_RunOnceThenTheBagIsEmptied()
    {
        PhysicsObj obj = Create(out PhysicsWorld world);
        var a = new CountingAnimHook();
        var b = new CountingAnimHook();
        obj.AddAnimHook(a);
        obj.AddAnimHook(b);
        Assert.Equal(2, obj.PendingAnimHookCount);
        TickTo(world, 1);
        TickTo(world, 2);
        Assert.Equal(1, a.Runs);
        Assert.Equal(1, b.Runs);
        Assert.Equal(0, obj.PendingAnimHookCount);
    }

    [Fact]
    public void ScaleHook_StartsFromCurrentScale()
    {
        PhysicsObj obj = Create(out PhysicsWorld world);
        obj.SetScale(3f, 0.5); // FPHook(0, start = m_scale = 1, end = 3)
        TickTo(world, 4); // fraction 0.25/0.5 = 0.5 -> (3 - 1) * 0.5 + 1 = 2
        Assert.Equal(2f, obj.Scale);
        Assert.Equal(2f, ((SimplePartArray)obj.PartArray!).Scale);
        obj.SetScale(5f, 0.0); // delta < EPSILON: immediate
        Assert.Equal(5f, obj.Scale);
    }

    [Fact]
    public void SetTranslucency_FadesFromZero_AndNeverBelowOriginal()
    {
        PhysicsObj obj = Create(out PhysicsWorld world);
        obj.TranslucencyOriginal = 0.3f;
        obj.SetTranslucency(1f, 0.5); // retail starts this fade at 0.0, not at the current value
        TickTo(world, 1); // fraction 1/8 -> value 0.125, clamped up to translucencyOriginal 0.3
        Assert.Equal(0.3f, obj.Translucency);
        TickTo(world, 6); // fraction 6/8 -> 0.75
        Assert.Equal(0.75f, obj.Translucency);
    }

    [Fact]
    public void PartAndLightingHooks_ReachTheirPartsThroughTheSeam()
    {
        PhysicsObj obj = Create(out PhysicsWorld world);
        var parts = (SimplePartArray)obj.PartArray!;
        obj.SetPartTranslucency(1, 0f, 1f, 0.5);
        obj.SetLuminosity(0f, 0.5f, 0.5);
        obj.SetDiffusion(1f, 0f, 0.5);
        obj.SetPartLuminosity(0, 0f, 1f, 0.5);
        obj.SetPartDiffusion(1, 0f, 1f, 0.5);
        TickTo(world, 4); // fraction 0.5 for all
        Assert.Equal(0.5f, parts.GetPartTranslucency(1));
        Assert.Equal(0f, parts.GetPartTranslucency(0));
        Assert.Equal(0.25f, parts.Luminosity);
        Assert.Equal(0.5f, parts.Diffusion);
        // Newest first: PartDiffusion(1) = 0.5, PartLuminosity(0) = 0.5, then the older whole-object hooks overwrite every
        // part: Diffusion = 0.5, Luminosity = 0.25.
        Assert.Equal(0.25f, parts.GetPartLuminosity(0));
        Assert.Equal(0.5f, parts.GetPartDiffusion(1));
        TickTo(world, 8);
        Assert.Null(obj.Hooks);
        Assert.Equal(0.5f, parts.Luminosity);
        Assert.Equal(0f, parts.Diffusion);
    }

    [Fact]
    public void CallPes_PlaysTheScriptOnceWhenTheRandomDelayHasPassed()
    {
        PhysicsObj obj = Create(out PhysicsWorld world);
        var player = new ScriptRecorder();
        world.ScriptPlayer = player;
        obj.CallPes(0x3300001Au, 0.5); // delay drawn in [0, 0.5]; value goes 0 -> 1 over that delay
        for (int k = 1; k <= 9; k++)
        {
            TickTo(world, k); // by 9/16 s > 0.5 s the value has reached 1
        }

        Assert.Equal(1, player.Plays);
        Assert.Equal(0x3300001Au, player.LastScript);
        Assert.Null(obj.Hooks);

        obj.CallPes(7u, 0.0); // delta < EPSILON: played at once while in a cell
        Assert.Equal(2, player.Plays);
    }

    [Fact]
    public void HooksRunForHiddenObjectsToo_ButNotForInactiveOnes()
    {
        PhysicsObj obj = Create(out PhysicsWorld world);
        obj.SetState(obj.State | PhysicsState.Hidden);
        obj.SetTranslucency2(0f, 1f, 0.5);
        TickTo(world, 4);
        Assert.Equal(0.5f, obj.Translucency); // process_hooks is outside the HIDDEN test in UpdatePositionInternal

        obj.SetActive(false);
        TickTo(world, 6);
        Assert.Equal(0.5f, obj.Translucency); // the inactive branch runs only particles and scripts
    }
}
