using System;
using System.Collections.Generic;
using System.Numerics;
using System.Reflection;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// Every public readable member of the scene, found by reflection and read recursively: public instance properties (without
/// index parameters) and public fields of every library type reachable from the world, the terrain, the sweep and the scene's
/// objects (structs such as Position and Frame member by member, floats by their bits; a library object met twice is recorded
/// by the path where it was first met). Non-finite floats are collected on the side.
/// </summary>
internal sealed class PublicState
{
    private static readonly Assembly Library = typeof(PhysicsWorld).Assembly;

    /// <summary>Public members not read, each with its reason (none today: a refused call leaves even the scene's
    /// bookkeeping, IsDormant and LastTickVisitCount, as it was).</summary>
    private static readonly HashSet<string> NotRead = [];

    private readonly Dictionary<object, string> _seen = new(ReferenceEqualityComparer.Instance);

    private PublicState()
    {
    }

    /// <summary>Member path → value (floats as bits).</summary>
    public SortedDictionary<string, string> Values { get; } = new(StringComparer.Ordinal);

    /// <summary>Paths holding a NaN or an infinity.</summary>
    public List<string> NonFinite { get; } = [];

    /// <summary>Library objects met, in the order met (paths sorted), each with its first path.</summary>
    public List<(object Instance, string Path)> Objects { get; } = [];

    /// <summary>Reads the whole scene.</summary>
    public static PublicState Capture(MisuseScene s)
    {
        var st = new PublicState();
        st.Walk(s.World, "world", 0);
        for (int i = 0; i < s.World.ObjectCount; i++)
        {
            st.Walk(s.World.GetObject(i), $"world.objects[{i}]", 0);
        }

        // The scene's own objects, also when a call removed them from the world.
        st.Walk(s.Walker, "walker", 0);
        st.Walk(s.Other, "other", 0);
        st.Walk(s.Resting, "resting", 0);
        st.Walk(s.Creature, "creature", 0);
        st.Walk(s.Terrain, "terrain", 0);
        // The walker's landblock and land cell (reached through the terrain's queries, not its properties).
        st.Walk(s.Terrain.GetLandBlock(SweepScene.BlockX, SweepScene.BlockY), "block", 0);
        st.Walk(s.Terrain.GetLandCell(MisuseScene.At(100f, 100f).ObjCellId), "cell", 0);
        st.Walk(s.Sweep, "sweep", 0);
        return st;
    }

    /// <summary>The members whose values differ between two captures.</summary>
    public static List<string> Diff(PublicState a, PublicState b)
    {
        var diff = new List<string>();
        foreach ((string k, string v) in a.Values)
        {
            if (!b.Values.TryGetValue(k, out string? w))
            {
                diff.Add($"{k}: {v} -> (gone)");
            }
            else if (v != w)
            {
                diff.Add($"{k}: {v} -> {w}");
            }
        }

        foreach (string k in b.Values.Keys)
        {
            if (!a.Values.ContainsKey(k))
            {
                diff.Add($"{k}: (new) -> {b.Values[k]}");
            }
        }

        return diff;
    }

    private void Record(string path, string value) => Values[path] = value;

    private void Walk(object? v, string path, int depth)
    {
        switch (v)
        {
            case null:
                Record(path, "null");
                return;
            case float f:
                Record(path, $"{BitConverter.SingleToInt32Bits(f):X8}");
                if (!float.IsFinite(f))
                {
                    NonFinite.Add($"{path} = {f}");
                }

                return;
            case double d:
                Record(path, $"{BitConverter.DoubleToInt64Bits(d):X16}");
                if (!double.IsFinite(d))
                {
                    NonFinite.Add($"{path} = {d}");
                }

                return;
            case Vector3 vec:
                Walk(vec.X, path + ".X", depth);
                Walk(vec.Y, path + ".Y", depth);
                Walk(vec.Z, path + ".Z", depth);
                return;
            case Quaternion q:
                Walk(q.W, path + ".W", depth);
                Walk(q.X, path + ".X", depth);
                Walk(q.Y, path + ".Y", depth);
                Walk(q.Z, path + ".Z", depth);
                return;
            case string or bool or Enum:
                Record(path, v.ToString()!);
                return;
        }

        Type t = v.GetType();
        if (t.IsPrimitive)
        {
            Record(path, Convert.ToString(v, System.Globalization.CultureInfo.InvariantCulture)!);
            return;
        }

        if (v is Array arr)
        {
            Record(path + ".Length", arr.Length.ToString(System.Globalization.CultureInfo.InvariantCulture));
            return;
        }

        if (t.Assembly != Library || depth > 12)
        {
            // Client seams and framework objects: identity only.
            Record(path, t.Name);
            return;
        }

        if (!t.IsValueType)
        {
            if (_seen.TryGetValue(v, out string? first))
            {
                Record(path, "ref " + first);
                return;
            }

            _seen[v] = path;
            Objects.Add((v, path));
        }

        Record(path, t.Name);
        foreach (FieldInfo fi in t.GetFields(BindingFlags.Public | BindingFlags.Instance))
        {
            Walk(fi.GetValue(v), path + "." + fi.Name, depth + 1);
        }

        foreach (PropertyInfo pi in t.GetProperties(BindingFlags.Public | BindingFlags.Instance))
        {
            if (pi.GetIndexParameters().Length != 0 || pi.GetMethod is not { IsPublic: true } || pi.PropertyType.IsByRefLike
                || NotRead.Contains(pi.Name))
            {
                continue;
            }

            object? value;
            try
            {
                value = pi.GetValue(v);
            }
            catch (TargetInvocationException e)
            {
                Record(path + "." + pi.Name, "throws " + e.InnerException!.GetType().Name);
                continue;
            }

            Walk(value, path + "." + pi.Name, depth + 1);
        }
    }
}
