using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Text.RegularExpressions;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The public surface table of docs/architecture.md is the library's, counted by the rule that page states: exported types;
/// per type its own (not inherited) public and protected constructors, methods, properties, fields and events; property and
/// event accessors not counted separately (operators are methods); enum values not counted.
/// </summary>
public sealed partial class PublicSurfaceTests
{
    [GeneratedRegex(@"^\| `(AcDream\.Core\.Physics[\w.]*)` \| (\d+) \| ([\d,]+) \|\s*$")]
    private static partial Regex Row();

    internal static SortedDictionary<string, (int Types, int Members)> Count(Assembly asm)
    {
        const BindingFlags Declared = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static
                                      | BindingFlags.DeclaredOnly;
        static bool Visible(MethodBase? m) => m is not null && (m.IsPublic || m.IsFamily || m.IsFamilyOrAssembly);

        var byNamespace = new SortedDictionary<string, (int Types, int Members)>(StringComparer.Ordinal);
        foreach (Type t in asm.GetExportedTypes())
        {
            int members = 0;
            if (!t.IsEnum)
            {
                foreach (MemberInfo m in t.GetMembers(Declared))
                {
                    bool counted = m switch
                    {
                        ConstructorInfo c => Visible(c),
                        MethodInfo mi => Visible(mi) && (!mi.IsSpecialName || mi.Name.StartsWith("op_", StringComparison.Ordinal)),
                        PropertyInfo p => p.GetAccessors(true).Any(a => Visible(a)),
                        FieldInfo f => (f.IsPublic || f.IsFamily || f.IsFamilyOrAssembly) && !f.IsSpecialName,
                        EventInfo e => Visible(e.AddMethod),
                        _ => false,
                    };
                    members += counted ? 1 : 0;
                }
            }

            string ns = t.Namespace ?? "";
            (int types, int total) = byNamespace.GetValueOrDefault(ns);
            byNamespace[ns] = (types + 1, total + members);
        }

        return byNamespace;
    }

    [Fact]
    public void ArchitectureTable_IsTheAssemblysPublicSurface()
    {
        string root = TerrainDataDir.RepoRoot() ?? throw new InvalidOperationException("repository root not found");
        string[] lines = File.ReadAllLines(Path.Combine(root, "docs", "architecture.md"));
        var documented = new SortedDictionary<string, (int Types, int Members)>(StringComparer.Ordinal);
        foreach (string line in lines)
        {
            Match m = Row().Match(line);
            if (m.Success)
            {
                documented[m.Groups[1].Value] = (int.Parse(m.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture),
                                                 int.Parse(m.Groups[3].Value.Replace(",", "", StringComparison.Ordinal),
                                                           System.Globalization.CultureInfo.InvariantCulture));
            }
        }

        SortedDictionary<string, (int Types, int Members)> actual = Count(typeof(PhysicsWorld).Assembly);
        // On a difference, the message carries the rows as they should read (to paste into the table).
        string rows = string.Join(Environment.NewLine, actual.Select(kv => $"| `{kv.Key}` | {kv.Value.Types} | {kv.Value.Members:N0} |"));
        Assert.True(actual.Select(kv => $"{kv.Key} {kv.Value.Types} {kv.Value.Members}")
                          .SequenceEqual(documented.Select(kv => $"{kv.Key} {kv.Value.Types} {kv.Value.Members}")),
                    $"docs/architecture.md's surface table differs from the assembly; the rows should read:{Environment.NewLine}{rows}");

        int types = actual.Values.Sum(v => v.Types), members = actual.Values.Sum(v => v.Members);
        string total = $"**{types} public types, {members:N0} public members**";
        Assert.Contains(lines, l => l.Contains(total, StringComparison.Ordinal));
    }
}
