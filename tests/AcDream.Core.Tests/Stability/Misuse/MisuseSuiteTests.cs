using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using AcDream.Core.Physics.Objects;
using Xunit;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// The misuse suite: every public mutator of every library type the scene reaches (<see cref="MutatorCatalog"/>), called with
/// every class of bad value its parameter types allow (<see cref="BadValues"/>), the other arguments good. For each call:
/// a refusal (ArgumentException) leaves every public member exactly as it was (<see cref="PublicState"/>); any other exception
/// fails; then 30 ticks run without an exception and leave no NaN or infinity anywhere in the public state.
/// </summary>
public class MisuseSuiteTests
{
    private const int TicksAfter = 30;

    public static TheoryData<string> Members()
    {
        var data = new TheoryData<string>();
        foreach (string n in MutatorCatalog.Discover(new MisuseScene()).Select(x => MutatorCatalog.Name(x.Method) + " on " + x.Path).Distinct()
                     .Where(n => !MutatorCatalog.Excluded.ContainsKey(n[..n.IndexOf(" on ", StringComparison.Ordinal)]))
                     .Order(StringComparer.Ordinal))
        {
            data.Add(n);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Members))]
    public void BadValues_AreRefusedWithStateUnchanged_OrAccepted_AndTheWorldTicksOn(string member)
    {
        (MethodInfo method, string path) = MutatorCatalog.Discover(new MisuseScene())
            .First(x => MutatorCatalog.Name(x.Method) + " on " + x.Path == member);
        ParameterInfo[] ps = method.GetParameters();
        var failures = new List<string>();
        int cases = 0;
        // A span parameter cannot be passed through reflection: such a member goes on the exclusion list with its own test.
        Assert.False(ps.Any(p => MutatorCatalog.ParamType(p).IsByRefLike),
            $"{member} takes a span: call it directly in a test and add it to MutatorCatalog.Excluded with that test's name");

        for (int i = 0; i < ps.Length; i++)
        {
            var probe = new MisuseScene();
            Assert.True(BadValues.TryGood(MutatorCatalog.ParamType(ps[i]), probe, out object? good),
                $"{member}: no good value for a {MutatorCatalog.ParamType(ps[i]).Name} (add one to BadValues.TryGood)");
            foreach ((string label, object? _) in BadValues.For(MutatorCatalog.ParamType(ps[i]), good))
            {
                cases++;
                RunCase(member, method, path, ps, i, label, failures);
            }
        }

        if (ps.Length == 0)
        {
            // No value input: called once in the scene, to check that the call itself never breaks a later tick.
            cases++;
            RunCase(member, method, path, ps, -1, "no arguments", failures);
        }

        Assert.True(failures.Count == 0, $"{member}, {failures.Count} of {cases} cases:\n" + string.Join("\n", failures.Take(25)));
    }

    private static void RunCase(string member, MethodInfo method, string path, ParameterInfo[] ps, int badIndex, string label,
        List<string> failures)
    {
        var s = new MisuseScene();
        object? target = MutatorCatalog.Resolve(s, path);
        var args = new object?[ps.Length];
        for (int k = 0; k < ps.Length; k++)
        {
            BadValues.TryGood(MutatorCatalog.ParamType(ps[k]), s, out args[k]);
            if (path == "static" && args[k] is PhysicsObj)
            {
                // A static entry's object is the scene's creature (retail's movement manager).
                args[k] = s.Creature;
            }
        }

        if (badIndex >= 0)
        {
            args[badIndex] = BadValues.For(MutatorCatalog.ParamType(ps[badIndex]), args[badIndex]).First(b => b.Label == label).Value;
        }

        // A MovementEvent is addressed to the object it is handed to (unless the bad value is one for another object).
        BadValues.Address(args, target as PhysicsObj);

        string name = badIndex >= 0 ? $"{ps[badIndex].Name} = {label}" : label;
        PublicState before = PublicState.Capture(s);
        try
        {
            method.Invoke(target, args);
        }
        catch (TargetInvocationException e) when (e.InnerException is ArgumentException)
        {
            List<string> diff = PublicState.Diff(before, PublicState.Capture(s));
            if (diff.Count > 0)
            {
                failures.Add($"  {name}: refused but changed {diff.Count} members: {string.Join("; ", diff.Take(4))}");
                return;
            }
        }
        catch (TargetInvocationException e)
        {
            failures.Add($"  {name}: threw {e.InnerException!.GetType().Name}: {e.InnerException.Message}");
            return;
        }

        try
        {
            s.Tick(TicksAfter);
        }
        catch (Exception e)
        {
            failures.Add($"  {name}: a later Tick threw {e.GetType().Name}: {e.Message}");
            return;
        }

        PublicState after = PublicState.Capture(s);
        if (after.NonFinite.Count > 0)
        {
            failures.Add($"  {name}: after {TicksAfter} ticks non-finite: {string.Join("; ", after.NonFinite.Take(4))}");
        }
    }

    [Fact]
    public void Catalog_FindsTheMutatorsOfEveryReachedType_AndEveryExclusionNamesAMember()
    {
        var s = new MisuseScene();
        Assert.True(s.Resting.IsDormant, "the scene's resting object must be dormant for the no-wake cases");
        HashSet<string> names = MutatorCatalog.Discover(s).Select(x => MutatorCatalog.Name(x.Method)).ToHashSet();
        // A few members that must be reached (world, object, part array, managers, terrain):
        string[] expected =
        [
            "PhysicsWorld.Tick(Double)", "PhysicsObj.SetFrame(Frame)", "PhysicsObj.SetScaleStatic(Single)",
            "SimplePartArray.set_SequenceVelocity(Vector3)", "PositionManager.ConstrainTo(Position, Single, Single)",
            "InterpolationManager.InterpolateTo(Position, Boolean)", "ConstraintManager.ConstrainTo(Position, Single, Single)",
            "StickyManager.StickTo(UInt32, Single, Single)", "TerrainWorld.RemoveLandBlock(UInt32, ICollection`1)",
            // The motion surface (issue #34): the creature's movement manager, interpreter, states and move-to, and the
            // static MovementEvent entry.
            "PhysicsObj.HandleMovementEvent(MovementEventMessage)", "MotionInterp.set_MyRunRate(Single)",
            "MotionInterp.DoMotion(MotionCommand, MovementParameters)", "MovementManager.MoveToInterpretedState(InterpretedMotionState)",
            "InterpretedMotionState.AddAction(MotionCommand, Single, UInt32, Boolean)", "ActionList.Add(ActionNode)",
            "RawMotionState.set_ForwardSpeed(Single)", "MovementManager.MoveToPosition(Position, MovementParameters)",
            "MovementEvent.ApplyInterpretedMotion(PhysicsObj, InterpretedMotionState, UInt32, Boolean)",
        ];
        foreach (string e in expected)
        {
            Assert.Contains(e, names);
        }

        foreach (string x in MutatorCatalog.Excluded.Keys)
        {
            Assert.True(names.Contains(x), $"stale exclusion: {x}");
        }
    }
}
