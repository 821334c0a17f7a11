using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Reflection.Emit;
using System.Text.RegularExpressions;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// What each namespace of the library imports from the others, read two ways: the compiled code (every type a type's
/// signatures, fields, attributes and method bodies name, so a reference written as <c>Collision.Primitives.Sphere</c> without
/// a using counts too) and the source (each file's <c>using AcDream.Core.Physics.…;</c> directives, so an import that only a
/// constant or a cref needs counts too). XML documentation crefs are not imports.
/// </summary>
internal static partial class LayerImports
{
    /// <summary>The library's root namespace; layers are named relative to it (<c>Collision.Primitives</c>).</summary>
    public const string Root = "AcDream.Core.Physics";

    private static readonly Dictionary<short, OperandType> OperandTypes = typeof(OpCodes)
        .GetFields(BindingFlags.Public | BindingFlags.Static)
        .Select(f => (OpCode)f.GetValue(null)!)
        .ToDictionary(o => o.Value, o => o.OperandType);

    /// <summary>The layer (namespace relative to <see cref="Root"/>) of <paramref name="t"/>, or null outside the library.</summary>
    public static string? LayerOf(Type? t)
    {
        while (t is { DeclaringType: not null })
        {
            t = t.DeclaringType;
        }

        string? ns = t?.Namespace;
        if (ns is null || !ns.StartsWith(Root + ".", StringComparison.Ordinal))
        {
            return null;
        }

        return ns[(Root.Length + 1)..];
    }

    /// <summary>For each layer, the layers its compiled code names, each with one example "type → type".</summary>
    public static SortedDictionary<string, SortedDictionary<string, string>> FromAssembly(Assembly asm)
    {
        var result = new SortedDictionary<string, SortedDictionary<string, string>>(StringComparer.Ordinal);
        foreach (Type t in asm.GetTypes())
        {
            string? from = LayerOf(t);
            if (from is null)
            {
                continue;
            }

            var seen = new HashSet<Type>();
            foreach (Type used in TypesNamedBy(t))
            {
                if (seen.Add(used) && LayerOf(used) is { } to && to != from)
                {
                    SortedDictionary<string, string> row = GetRow(result, from);
                    row.TryAdd(to, $"{t.FullName} → {used.FullName}");
                }
            }

            GetRow(result, from);
        }

        return result;
    }

    /// <summary>For each layer (a folder under <c>src/AcDream.Core/Physics</c>), the layers its files' using directives name.</summary>
    public static SortedDictionary<string, SortedDictionary<string, string>> FromSource(string physicsDir)
    {
        var result = new SortedDictionary<string, SortedDictionary<string, string>>(StringComparer.Ordinal);
        foreach (string file in Directory.EnumerateFiles(physicsDir, "*.cs", SearchOption.AllDirectories))
        {
            string rel = Path.GetRelativePath(physicsDir, Path.GetDirectoryName(file)!);
            if (rel == ".")
            {
                continue;
            }

            string from = rel.Replace(Path.DirectorySeparatorChar, '.');
            SortedDictionary<string, string> row = GetRow(result, from);
            foreach (Match m in UsingDirective().Matches(File.ReadAllText(file)))
            {
                string to = m.Groups[1].Value;
                if (to != from)
                {
                    row.TryAdd(to, $"{Path.GetRelativePath(physicsDir, file)}: using {Root}.{to}");
                }
            }
        }

        return result;
    }

    private static SortedDictionary<string, string> GetRow(SortedDictionary<string, SortedDictionary<string, string>> all, string layer)
    {
        if (!all.TryGetValue(layer, out SortedDictionary<string, string>? row))
        {
            row = new SortedDictionary<string, string>(StringComparer.Ordinal);
            all[layer] = row;
        }

        return row;
    }

    private static IEnumerable<Type> TypesNamedBy(Type t)
    {
        const BindingFlags All = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static
                                 | BindingFlags.DeclaredOnly;
        var named = new List<Type>();
        void Add(Type? x)
        {
            if (x is null)
            {
                return;
            }

            if (x.HasElementType)
            {
                Add(x.GetElementType());
                return;
            }

            named.Add(x);
            if (x.IsGenericType && !x.IsGenericTypeDefinition)
            {
                foreach (Type a in x.GetGenericArguments())
                {
                    Add(a);
                }
            }
        }

        void AddAttributes(IEnumerable<CustomAttributeData> attributes)
        {
            foreach (CustomAttributeData a in attributes)
            {
                Add(a.AttributeType);
                foreach (CustomAttributeTypedArgument arg in a.ConstructorArguments)
                {
                    Add(arg.ArgumentType);
                }
            }
        }

        Add(t.BaseType);
        foreach (Type i in t.GetInterfaces())
        {
            Add(i);
        }

        AddAttributes(t.CustomAttributes);
        foreach (FieldInfo f in t.GetFields(All))
        {
            Add(f.FieldType);
            AddAttributes(f.CustomAttributes);
        }

        foreach (PropertyInfo p in t.GetProperties(All))
        {
            Add(p.PropertyType);
        }

        foreach (EventInfo e in t.GetEvents(All))
        {
            Add(e.EventHandlerType);
        }

        foreach (MethodBase m in t.GetMethods(All).Cast<MethodBase>().Concat(t.GetConstructors(All)))
        {
            if (m is MethodInfo mi)
            {
                Add(mi.ReturnType);
            }

            foreach (ParameterInfo p in m.GetParameters())
            {
                Add(p.ParameterType);
            }

            AddAttributes(m.CustomAttributes);
            MethodBody? body = m.GetMethodBody();
            if (body is null)
            {
                continue;
            }

            foreach (LocalVariableInfo l in body.LocalVariables)
            {
                Add(l.LocalType);
            }

            foreach (MemberInfo r in BodyReferences(m, body.GetILAsByteArray() ?? []))
            {
                Add(r as Type ?? r.DeclaringType);
                switch (r)
                {
                    case FieldInfo f: Add(f.FieldType); break;
                    case MethodInfo rm: Add(rm.ReturnType); break;
                }
            }
        }

        return named;
    }

    // The members an IL body's tokens name (calls, field accesses, type operands, ldtoken).
    private static IEnumerable<MemberInfo> BodyReferences(MethodBase m, byte[] il)
    {
        Type[]? typeArgs = m.DeclaringType is { IsGenericType: true } dt ? dt.GetGenericArguments() : null;
        Type[]? methodArgs = m.IsGenericMethod ? m.GetGenericArguments() : null;
        int i = 0;
        while (i < il.Length)
        {
            short code = il[i] == 0xFE ? (short)(0xFE00 | il[i + 1]) : il[i];
            i += il[i] == 0xFE ? 2 : 1;
            OperandType operand = OperandTypes[code];
            switch (operand)
            {
                case OperandType.InlineField:
                case OperandType.InlineMethod:
                case OperandType.InlineTok:
                case OperandType.InlineType:
                    int token = BitConverter.ToInt32(il, i);
                    MemberInfo? r = null;
                    try
                    {
                        r = m.Module.ResolveMember(token, typeArgs, methodArgs);
                    }
                    catch (ArgumentException)
                    {
                        // A token from another module's generic context; outside the library either way.
                    }

                    if (r is not null)
                    {
                        yield return r;
                    }

                    i += 4;
                    break;
                case OperandType.InlineSwitch:
                    i += 4 + 4 * BitConverter.ToInt32(il, i);
                    break;
                case OperandType.InlineNone:
                    break;
                case OperandType.ShortInlineBrTarget:
                case OperandType.ShortInlineI:
                case OperandType.ShortInlineVar:
                    i += 1;
                    break;
                case OperandType.InlineVar:
                    i += 2;
                    break;
                case OperandType.InlineI8:
                case OperandType.InlineR:
                    i += 8;
                    break;
                default:
                    i += 4;
                    break;
            }
        }
    }

    [GeneratedRegex(@"^\s*using\s+AcDream\.Core\.Physics\.([\w.]+)\s*;", RegexOptions.Multiline)]
    private static partial Regex UsingDirective();
}
