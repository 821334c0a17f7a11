using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// The public mutators under test, found by reflection: every public instance method and public property setter of every
/// library type whose instances the scene's public state reaches (the world, its objects, their part arrays, hooks and
/// managers, the sweep, the terrain and its blocks and cells), so that a new member or a new reachable type is covered
/// without anyone listing it. Each member is named "Type.Name(ParamTypes)".
/// </summary>
internal static class MutatorCatalog
{
    /// <summary>Members not called, each with its reason.</summary>
    public static readonly Dictionary<string, string> Excluded = new(StringComparer.Ordinal)
    {
        // Not value inputs: the tick itself (driven by the suite with good times; its clock argument is covered through
        // Tick(Double) and SetCurrentTime(Double), which are called).
        ["PhysicsWorld.UseTime()"] = "the world tick without an argument; run 30 times after every case",
        // Client-seam callbacks the engine calls; a client never calls them on the built-in implementations with values.
        ["SimplePartArray.HandleMovement()"] = "engine callback (no value input)",
        ["SimplePartArray.HandleEnterWorld()"] = "engine callback (no value input)",
        // Part-array seam calls the object makes with its own validated state (IPartArray); a client calling them directly
        // bypasses the object: each still refuses non-finite values (NonFiniteInputsAreRefusedTests) but may desynchronise
        // the part array from its object, which is the client's business.
        ["SimplePartArray.Update(Single, Frame)"] = "engine seam: the object's step calls it with its quantum",
        ["AnimatedPartArray.CopyPartFrames(Span`1)"] = "span output (the parts' frames, for drawing): AnimatedPartArrayApiTests",
        ["SimplePartArray.SetCellId(UInt32)"] = "engine seam: the object hands its own cell id",
        ["SimplePartArray.SetFrame(Frame)"] = "engine seam: the object hands its own frame",
        // Sweep entry points are the engine's seam to the collision module (CollisionSweep); SweepObject and SetPosition are
        // called (a client sweep may forward to them), the steps below only with the object's own state.
        ["RetailSweep.EtherealCheckForCollisions(PhysicsObj)"] = "engine seam (CollisionSweep)",
        ["RetailSweep.ReportCollisionEnd(PhysicsObj, Boolean)"] = "engine seam (CollisionSweep)",
        // A hook's Execute is the engine's call during process_hooks.
        ["FPHook.Execute(PhysicsObj)"] = "engine callback (process_hooks)",
        // Structural members, not value inputs: landblocks changing under objects (LandblocksChangingUnderObjectsTests,
        // IndoorCellsChangingUnderObjectsTests) and a world releasing its terrain when its sweep changes
        // (TerrainReleasedWhenSweepDetachedTests) have their own tests.
        ["TerrainWorld.AddLandBlock(LandBlock)"] = "structural: LandblocksChangingUnderObjectsTests",
        ["TerrainWorld.RemoveLandBlock(UInt32, ICollection`1)"] = "structural: LandblocksChangingUnderObjectsTests",
        ["PhysicsWorld.set_Sweep(CollisionSweep)"] = "structural: TerrainReleasedWhenSweepDetachedTests",
        // Span parameters cannot be passed through reflection: each is called directly by the test named.
        ["SimplePartArray.SetSpheres(ReadOnlySpan`1)"] = "span: SpanInputsTests.SetSpheres_BadSphere",
        ["SimplePartArray.SetCylSpheres(ReadOnlySpan`1)"] = "span: SpanInputsTests.SetCylSpheres_BadCylinder",
        ["SimplePartArray.SetPhysicsParts(ReadOnlySpan`1, ReadOnlySpan`1, ReadOnlySpan`1)"] = "span: SpanInputsTests.SetPhysicsParts_BadFrameOrScale_IsRefused",
        ["TerrainWorld.AddLandBlock(UInt32, ReadOnlySpan`1, ReadOnlySpan`1)"] = "span, and structural: LandblocksChangingUnderObjectsTests",
        ["TerrainWorld.FindCellList(Position, ReadOnlySpan`1, ReadOnlySpan`1, Span`1, LandCell)"] = "span query: TerrainQueryStabilityTests, LandblockCornerOnTerrainTests",
    };

    private static readonly Assembly Library = typeof(PhysicsWorld).Assembly;

    /// <summary>The object's members that reach its movement manager: also called on the scene's creature, which has retail's
    /// movement manager and interpreter (on the walker, whose manager is a client's own, they answer without moving).</summary>
    private static readonly HashSet<string> MotionMembers = new(StringComparer.Ordinal)
    {
        "HandleMovementEvent", "DoMotion", "StopMotion", "MoveToObject", "TurnToObject", "TurnToHeading", "StopCompletely",
        "StickToObject", "SetPosition", "MoveOrTeleport", "HandleUpdateTarget", "MakeMovementManager",
    };

    /// <summary>Static entry points of the library, called with the scene's creature as their object argument.</summary>
    private static readonly Type[] StaticEntries = [typeof(AcDream.Core.Physics.Motion.Wire.MovementEvent)];

    /// <summary>The member's name in the catalog.</summary>
    public static string Name(MethodInfo m) =>
        m.ReflectedType!.Name + "." + m.Name + "(" + string.Join(", ", m.GetParameters().Select(p => ParamType(p).Name)) + ")";

    /// <summary>A parameter's type without the by-ref.</summary>
    public static Type ParamType(ParameterInfo p) => p.ParameterType.IsByRef ? p.ParameterType.GetElementType()! : p.ParameterType;

    /// <summary>The mutators of the library types reachable from scene <paramref name="s"/>, with the path of the instance
    /// each is called on.</summary>
    public static List<(MethodInfo Method, string Path)> Discover(MisuseScene s)
    {
        PublicState st = PublicState.Capture(s);
        var byType = new Dictionary<Type, string>();
        foreach ((object o, string path) in st.Objects)
        {
            byType.TryAdd(o.GetType(), path);
        }

        var list = new List<(MethodInfo, string)>();
        foreach ((Type t, string path) in byType.OrderBy(kv => kv.Key.Name, StringComparer.Ordinal))
        {
            if (!t.IsPublic && !t.IsNestedPublic)
            {
                continue;
            }

            foreach (MethodInfo m in t.GetMethods(BindingFlags.Public | BindingFlags.Instance))
            {
                if (m.DeclaringType == typeof(object) || m.DeclaringType!.Assembly != Library
                    || (m.IsSpecialName && m.Name.StartsWith("get_", StringComparison.Ordinal))
                    || m.Name is "Equals" or "GetHashCode" or "ToString" or "Deconstruct" || m.IsGenericMethodDefinition)
                {
                    continue;
                }

                list.Add((m, path));
                if (t == typeof(AcDream.Core.Physics.Objects.PhysicsObj))
                {
                    // The object's members are also called on the dormant object: a refusal must not even wake it.
                    list.Add((m, "resting"));
                    if (MotionMembers.Contains(m.Name))
                    {
                        list.Add((m, "creature"));
                    }
                }
            }
        }

        foreach (Type t in StaticEntries)
        {
            foreach (MethodInfo m in t.GetMethods(BindingFlags.Public | BindingFlags.Static))
            {
                if (m.DeclaringType == t && !m.IsGenericMethodDefinition)
                {
                    list.Add((m, "static"));
                }
            }
        }

        return list;
    }

    /// <summary>The instance at <paramref name="path"/> in scene <paramref name="s"/>.</summary>
    public static object? Resolve(MisuseScene s, string path)
    {
        if (path == "resting")
        {
            return s.Resting;
        }

        if (path == "creature")
        {
            return s.Creature;
        }

        if (path == "static")
        {
            return null!;
        }

        foreach ((object o, string p) in PublicState.Capture(s).Objects)
        {
            if (p == path)
            {
                return o;
            }
        }

        throw new InvalidOperationException("No instance at " + path);
    }
}
