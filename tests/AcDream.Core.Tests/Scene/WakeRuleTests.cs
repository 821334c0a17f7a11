using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using System.Reflection;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Scene;

/// <summary>
/// The wake rule (<see cref="PhysicsObj.Touch"/>): every public mutator of <see cref="PhysicsObj"/> wakes a dormant object, or
/// is on the documented no-wake list; a new public member in neither list (nor among the queries) fails here by name.
/// </summary>
public class WakeRuleTests
{
    /// <summary>The dormant object, a second object of the same world (dormant too), and the world's clock.</summary>
    public sealed class Fixture
    {
        public required PhysicsWorld World { get; init; }

        public required PhysicsObj Obj { get; init; }

        public required PhysicsObj Other { get; init; }

        public double Time { get; set; }

        /// <summary>Objects the world visited in the last tick before the invocation (those that stay awake).</summary>
        public int VisitsWhileDormant { get; set; }

        public void Tick(int ticks = 1)
        {
            for (int i = 0; i < ticks; i++)
            {
                Time += 0.04;
                World.Tick(Time);
            }
        }
    }

    private sealed class NopAnimHook : IAnimHook
    {
        public void Execute(PhysicsObj obj)
        {
        }
    }

    private sealed class NopHook : PhysicsObjHook
    {
        public override bool Execute(PhysicsObj obj) => true;
    }

    private sealed class NopSeams : IDetectionManager, IParticleManager, IScriptManager
    {
        public void CheckDetection()
        {
        }

        public void UpdateParticles()
        {
        }

        public void UpdateScripts()
        {
        }
    }

    private static Position Near(float dx) => SceneTestContext.At(60f + dx, 50f);

    /// <summary>Public mutators that wake a dormant object, each with an invocation with valid arguments (and, for a few, a
    /// preparation run before the object is put to sleep).</summary>
    private static readonly Dictionary<string, (Action<Fixture>? Prepare, Action<Fixture> Invoke)> Wakes = new()
    {
        ["AddAnimHook(IAnimHook)"] = (null, f => f.Obj.AddAnimHook(new NopAnimHook())),
        ["AddHook(PhysicsObjHook)"] = (null, f => f.Obj.AddHook(new NopHook())),
        ["CalcAcceleration()"] = (null, f => f.Obj.CalcAcceleration()),
        ["CallPes(UInt32, Double)"] = (null, f => f.Obj.CallPes(7u, 0.0)),
        ["ClearTransientStates()"] = (null, f => f.Obj.ClearTransientStates()),
        ["CommitTransition(TransitionResult)"] = (null, f => f.Obj.CommitTransition(TransitionResult.FreeSpace(Near(0.5f)))),
        ["ConstrainTo(Position, Single, Single)"] = (null, f => f.Obj.ConstrainTo(f.Obj.Position, 1f, 2f)),
        ["EnterWorld(Position)"] = (null, f => f.Obj.EnterWorld(Near(0.5f))),
        ["GetOrCreateMotionInterpreter()"] = (null, f => f.Obj.GetOrCreateMotionInterpreter()),
        ["GoToLostCell(Position)"] = (null, f => f.Obj.GoToLostCell(Near(0.5f))),
        ["LeaveWorld()"] = (null, f => f.Obj.LeaveWorld()),
        ["HandleReceivedPosition(Position, UInt16, UInt16, Boolean)"] = (null, f => f.Obj.HandleReceivedPosition(Near(0.5f), 1, 0, true)),
        // A MovementEvent that is applied (newer movement stamp): walk forward.
        ["HandleMovementEvent(MovementEventMessage)"] = (null, f =>
        {
            var m = new MovementEventMessage { ObjectId = f.Obj.Id, MovementTimestamp = 1 };
            m.State.ForwardCommand = MotionCommand.WalkForward;
            f.Obj.HandleMovementEvent(m);
        }),
        ["DoMotion(MotionCommand, MovementParameters)"] = (null,
            f => f.Obj.DoMotion(MotionCommand.WalkForward, new MovementParameters())),
        ["StopMotion(MotionCommand, MovementParameters)"] = (null,
            f => f.Obj.StopMotion(MotionCommand.WalkForward, new MovementParameters())),
        ["HandleUpdateTarget(TargetInfo)"] = (null, f => f.Obj.HandleUpdateTarget(default)),
        ["InterpolateTo(Position, Boolean)"] = (null, f => f.Obj.InterpolateTo(Near(0.5f), false)),
        ["MakePositionManager()"] = (null, f => f.Obj.MakePositionManager()),
        ["MakeMovementManager(Boolean)"] = (null, f => f.Obj.MakeMovementManager(true)),
        ["MoveOrTeleport(Position, UInt16, Boolean)"] = (null, f => f.Obj.MoveOrTeleport(Near(0.5f), 0, true)),
        ["ProcessFPHook(PhysicsHookType, Single, UInt32)"] = (null, f => f.Obj.ProcessFPHook(PhysicsHookType.Translucency, 0.5f, 0u)),
        ["SetAcceleration(Vector3)"] = (null, f => f.Obj.SetAcceleration(new Vector3(0f, 0f, -1f))),
        ["SetActive(Boolean)"] = (null, f => f.Obj.SetActive(true)),
        ["SetDiffusion(Single, Single, Double)"] = (null, f => f.Obj.SetDiffusion(0f, 0.5f, 0.0)),
        ["SetEthereal(Boolean)"] = (null, f => f.Obj.SetEthereal(true)),
        ["SetFrame(Frame)"] = (null, f => f.Obj.SetFrame(f.Obj.Position.Frame)),
        ["SetHeading(Double)"] = (null, f => f.Obj.SetHeading(90f)),
        ["SetInitialFrame(Frame)"] = (null, f => f.Obj.SetInitialFrame(f.Obj.Position.Frame)),
        ["SetLocalVelocity(Vector3)"] = (null, f => f.Obj.SetLocalVelocity(new Vector3(1f, 0f, 0f))),
        ["SetLuminosity(Single, Single, Double)"] = (null, f => f.Obj.SetLuminosity(0f, 0.5f, 0.0)),
        ["SetOmega(Vector3)"] = (null, f => f.Obj.SetOmega(new Vector3(0f, 0f, 1f))),
        ["SetOnWalkable(Boolean)"] = (null, f => f.Obj.SetOnWalkable(true)),
        ["SetParent(PhysicsObj, UInt32, Frame)"] = (null, f => f.Obj.SetParent(f.Other, 0u, Frame.Identity)),
        ["SetPartDiffusion(UInt32, Single, Single, Double)"] = (null, f => f.Obj.SetPartDiffusion(0u, 0f, 0.5f, 0.0)),
        ["SetPartLuminosity(UInt32, Single, Single, Double)"] = (null, f => f.Obj.SetPartLuminosity(0u, 0f, 0.5f, 0.0)),
        ["SetPartTranslucency(UInt32, Single, Single, Double)"] = (null, f => f.Obj.SetPartTranslucency(0u, 0f, 0.5f, 0.0)),
        ["SetPosition(Position, SetPositionFlags)"] = (null, f => f.Obj.SetPosition(Near(0.5f), SetPositionFlags.Slide)),
        ["SetPositionSimple(Position, Boolean)"] = (null, f => f.Obj.SetPositionSimple(Near(0.5f), true)),
        ["SetScale(Single, Double)"] = (null, f => f.Obj.SetScale(2f, 0.0)),
        ["SetScaleStatic(Single)"] = (null, f => f.Obj.SetScaleStatic(2f)),
        ["SetState(PhysicsState)"] = (null, f => f.Obj.SetState(f.Obj.State)),
        ["SetTranslucency(Single, Double)"] = (null, f => f.Obj.SetTranslucency(0.5f, 1.0)),
        ["SetTranslucency2(Single, Single, Double)"] = (null, f => f.Obj.SetTranslucency2(0f, 0.5f, 1.0)),
        ["SetTranslucencyInternal(Single)"] = (null, f => f.Obj.SetTranslucencyInternal(0.5f)),
        ["SetVelocity(Vector3)"] = (null, f => f.Obj.SetVelocity(new Vector3(1f, 0f, 0f))),
        ["StickToObject(UInt32)"] = (null, f => f.Obj.StickToObject(f.Other.Id)),
        ["StopInterpolating()"] = (null, f => f.Obj.StopInterpolating()),
        ["StorePosition(Position)"] = (null, f => f.Obj.StorePosition(Near(0.5f))),
        ["TeleportHook()"] = (null, f => f.Obj.TeleportHook()),
        ["UnsetParent()"] = (f => f.Obj.SetParent(f.Other, 0u, Frame.Identity), f => f.Obj.UnsetParent()),
        ["StopSticking()"] = (null, f => f.Obj.StopSticking()),
        ["UpdateObject()"] = (null, f => f.Obj.UpdateObject()),
        ["set_DetectionManager(IDetectionManager)"] = (null, f => f.Obj.DetectionManager = new NopSeams()),
        ["set_Movement(IMovementManager)"] = (null, f => f.Obj.Movement = new BasicMovementManager()),
        ["set_PartArray(IPartArray)"] = (null, f => f.Obj.PartArray = new SimplePartArray(numParts: 1, numSpheres: 1)),
        ["set_ParticleManager(IParticleManager)"] = (null, f => f.Obj.ParticleManager = new NopSeams()),
        ["set_ScriptManager(IScriptManager)"] = (null, f => f.Obj.ScriptManager = new NopSeams()),
        ["MoveToObject(UInt32, MovementParameters)"] = (null, f => f.Obj.MoveToObject(f.Other.Id, new MovementParameters())),
        ["TurnToObject(UInt32, MovementParameters)"] = (null, f => f.Obj.TurnToObject(f.Other.Id, new MovementParameters())),
        ["TurnToHeading(MovementParameters)"] = (null, f => f.Obj.TurnToHeading(new MovementParameters { DesiredHeading = 90f })),
        ["StopCompletely()"] = (null, f => f.Obj.StopCompletely()),
    };

    /// <summary>The documented no-wake list (<see cref="PhysicsObj.Touch"/>): public mutators that leave a dormant object
    /// dormant, each with an invocation; safe because a dormant object's retail update never reads what they write.</summary>
    private static readonly Dictionary<string, Action<Fixture>> NoWake = new()
    {
        ["set_Friction(Single)"] = f => f.Obj.Friction = 0.5f,
        ["set_Elasticity(Single)"] = f => f.Obj.Elasticity = 0.5f,
        ["set_TranslucencyOriginal(Single)"] = f => f.Obj.TranslucencyOriginal = 0.25f,
        ["set_Weenie(IWeenieObject)"] = f => f.Obj.Weenie = WeenieTraits.Creature,
        ["set_LastMoveWasAutonomous(Boolean)"] = f => f.Obj.LastMoveWasAutonomous = true,
        // The network timestamps (update_times): read only by the network handlers, never by update_object.
        ["NewerEvent(PhysicsTimeStamp, UInt16)"] = f => f.Obj.NewerEvent(PhysicsTimeStamp.Position, 1),
    };

    /// <summary>Public methods that change nothing of the object (the sweep queries write only the transition they are given).</summary>
    private static readonly HashSet<string> Queries =
    [
        "CheckCollision(PhysicsObj)",
        "DetermineQuadrant(Position, Single, Position)",
        "GetRenderPose(Double)",
        "GetUpdateTime(PhysicsTimeStamp)",
        "IsMovingTo()",
    ];

    public static TheoryData<string> WakingMembers => new(Wakes.Keys.Order(StringComparer.Ordinal));

    public static TheoryData<string> NoWakeMembers => new(NoWake.Keys.Order(StringComparer.Ordinal));

    /// <summary>Public property setters and public methods of <see cref="PhysicsObj"/> (not object's, not getters).</summary>
    private static IEnumerable<string> PublicMutatorCandidates() =>
        typeof(PhysicsObj).GetMethods(BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static)
            .Where(m => m.GetBaseDefinition().DeclaringType != typeof(object))
            .Where(m => !(m.IsSpecialName && m.Name.StartsWith("get_", StringComparison.Ordinal)))
            .Select(Signature);

    /// <summary>The public candidates and the internal methods and setters the engine calls (listed members that became
    /// internal keep their wake cases).</summary>
    private static IEnumerable<string> PublicOrInternalMutatorCandidates() =>
        typeof(PhysicsObj).GetMethods(BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static)
            .Where(m => m.IsPublic || m.IsAssembly)
            .Where(m => m.GetBaseDefinition().DeclaringType != typeof(object))
            .Where(m => !(m.IsSpecialName && m.Name.StartsWith("get_", StringComparison.Ordinal)))
            .Select(Signature);

    private static string Signature(MethodInfo m) =>
        m.Name + "(" + string.Join(", ", m.GetParameters().Select(p => p.ParameterType.IsByRef
            ? p.ParameterType.GetElementType()!.Name
            : p.ParameterType.Name)) + ")";

    /// <summary>A world with no player, and two resting objects put to sleep.</summary>
    private static Fixture MakeDormant(Action<Fixture>? prepare)
    {
        var world = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        var f = new Fixture
        {
            World = world,
            Obj = SceneTestContext.Add(world, 5, Near(0f)),
            Other = SceneTestContext.Add(world, 7, SceneTestContext.At(70f, 50f)),
        };
        prepare?.Invoke(f);
        f.Tick(20);
        Assert.True(f.Obj.IsDormant, "the object did not go dormant");
        f.VisitsWhileDormant = world.LastTickVisitCount;
        Assert.True(f.VisitsWhileDormant < world.ObjectCount);
        return f;
    }

    [Fact]
    public void EveryPublicMutator_WakesOrIsOnTheNoWakeList()
    {
        string[] unknown = PublicMutatorCandidates()
            .Where(s => !Wakes.ContainsKey(s) && !NoWake.ContainsKey(s) && !Queries.Contains(s))
            .Order(StringComparer.Ordinal).ToArray();
        Assert.True(unknown.Length == 0,
            "public members of PhysicsObj in no list (make them call Touch() and add an invocation to Wakes, or document them "
            + "at PhysicsObj.Touch and add them to NoWake, or add a pure query to Queries): " + string.Join(", ", unknown));
    }

    [Fact]
    public void TheListsNameOnlyExistingMembers_AndEachMemberOnce()
    {
        var all = PublicOrInternalMutatorCandidates().ToHashSet();
        string[] stale = Wakes.Keys.Concat(NoWake.Keys).Concat(Queries).Where(s => !all.Contains(s))
            .Order(StringComparer.Ordinal).ToArray();
        Assert.True(stale.Length == 0, "listed but not a public or internal member of PhysicsObj: " + string.Join(", ", stale));
        string[] twice = Wakes.Keys.Concat(NoWake.Keys).Concat(Queries).GroupBy(s => s).Where(g => g.Count() > 1)
            .Select(g => g.Key).ToArray();
        Assert.True(twice.Length == 0, "listed more than once: " + string.Join(", ", twice));
    }

    [Theory]
    [MemberData(nameof(WakingMembers))]
    public void WakingMember_WakesADormantObject_AndItIsVisitedNextTick(string member)
    {
        (Action<Fixture>? prepare, Action<Fixture> invoke) = Wakes[member];
        Fixture f = MakeDormant(prepare);
        invoke(f);
        Assert.False(f.Obj.IsDormant, $"{member} left the object dormant");
        f.Tick();
        Assert.True(f.World.LastTickVisitCount > f.VisitsWhileDormant, $"after {member} the next tick did not visit the object");
    }

    [Theory]
    [MemberData(nameof(NoWakeMembers))]
    public void NoWakeMember_LeavesADormantObjectDormant(string member)
    {
        Fixture f = MakeDormant(null);
        NoWake[member](f);
        Assert.True(f.Obj.IsDormant, $"{member} woke the object: move it to the waking list");
        f.Tick();
        Assert.Equal(f.VisitsWhileDormant, f.World.LastTickVisitCount);
    }

    [Fact]
    public void NoWakeSetters_OnDormantObjects_AreBitIdenticalToVisitingEveryObject()
    {
        // Resting items near a player get the no-wake setters while dormant, then are kicked (friction, translucency floor
        // and elasticity are read once they move): every tick matches a world that visits every object.
        var full = new PhysicsWorld(0.0) { VisitEveryObject = true, Sweep = new FlatGroundSweep() };
        var scene = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        PhysicsWorld[] worlds = [full, scene];
        foreach (PhysicsWorld w in worlds)
        {
            w.Player = SceneTestContext.Add(w, 1, SceneTestContext.At(50f, 50f));
            for (uint i = 0; i < 6; i++)
            {
                SceneTestContext.Add(w, 10 + i, SceneTestContext.At(55f + 3f * i, 52f));
            }
        }

        double t = 0;
        for (int tick = 1; tick <= 120; tick++)
        {
            foreach (PhysicsWorld w in worlds)
            {
                if (tick == 20)
                {
                    Assert.True(w.VisitEveryObject || w.GetObjectById(10)!.IsDormant);
                    for (uint i = 0; i < 6; i++)
                    {
                        PhysicsObj o = w.GetObjectById(10 + i)!;
                        o.Friction = 0.3f + 0.1f * i;
                        o.Elasticity = 0.5f;
                        o.TranslucencyOriginal = 0.25f;
                        o.Weenie = WeenieTraits.Creature;
                        o.LastMoveWasAutonomous = true;
                        o.NewerEvent(PhysicsTimeStamp.Position, 5);
                    }

                    Assert.True(w.VisitEveryObject || w.GetObjectById(10)!.IsDormant);
                }

                if (tick == 40)
                {
                    for (uint i = 0; i < 6; i++)
                    {
                        PhysicsObj o = w.GetObjectById(10 + i)!;
                        o.SetVelocity(new Vector3(2f + i, 0.5f, 0f));
                        o.SetTranslucency(0.1f, 0.0);
                    }
                }

                w.Tick(t + 1.0 / 30.0);
            }

            t += 1.0 / 30.0;
            Assert.True(SceneTestContext.HashWorld(full) == SceneTestContext.HashWorld(scene), $"tick {tick} differs");
        }
    }
}
