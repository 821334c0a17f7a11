using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The layers table of docs/architecture.md is the library's: each layer imports only what its "may import" column lists,
/// read from the compiled code and from the using directives (<see cref="LayerImports"/>), as <see cref="PublicSurfaceTests"/>
/// checks the surface table. The bottom stays at the bottom: <c>Spatial</c> imports nothing of the library, the byte reader
/// (<c>Format</c>) only <c>Spatial</c>, only the world door (<c>WorldData</c>) and the scenery above the loaders (<c>Scenery</c>) import the loaders (<c>Data</c>), and nothing imports the door, the input
/// (<c>Input</c>) or the debug view (<c>Debug</c>).
/// </summary>
public sealed partial class LayeringTests
{
    private static string Root => TerrainDataDir.RepoRoot() ?? throw new InvalidOperationException("repository root not found");

    // | **Collision/Sweep** (`…Collision.Sweep`) | `Spatial`, `Objects` | holds | retail |
    [GeneratedRegex(@"^\| \*\*([\w/]+)\*\* \([^|]*\) \| ([^|]*) \|")]
    private static partial Regex LayerRow();

    [GeneratedRegex(@"`([\w./]+)`")]
    private static partial Regex Quoted();

    /// <summary>The "may import" column, by layer (<c>Collision.Sweep</c>).</summary>
    internal static SortedDictionary<string, SortedSet<string>> Documented()
    {
        var table = new SortedDictionary<string, SortedSet<string>>(StringComparer.Ordinal);
        foreach (string line in File.ReadAllLines(Path.Combine(Root, "docs", "architecture.md")))
        {
            Match m = LayerRow().Match(line);
            if (m.Success)
            {
                string layer = m.Groups[1].Value.Replace('/', '.');
                table[layer] = new SortedSet<string>(Quoted().Matches(m.Groups[2].Value).Select(q => q.Groups[1].Value.Replace('/', '.')),
                                                     StringComparer.Ordinal);
            }
        }

        return table;
    }

    private static string Describe(SortedDictionary<string, SortedDictionary<string, string>> actual) =>
        string.Join(Environment.NewLine, actual.Select(kv => $"{kv.Key}: {string.Join(", ", kv.Value.Keys.Select(k => $"`{k}`"))}"));

    private static void AssertWithinTable(SortedDictionary<string, SortedDictionary<string, string>> actual, string how)
    {
        SortedDictionary<string, SortedSet<string>> table = Documented();
        var problems = new List<string>();
        foreach ((string layer, SortedDictionary<string, string> imports) in actual)
        {
            if (!table.TryGetValue(layer, out SortedSet<string>? allowed))
            {
                problems.Add($"{layer} has no row in docs/architecture.md's layers table");
                continue;
            }

            problems.AddRange(imports.Where(kv => !allowed.Contains(kv.Key))
                                     .Select(kv => $"{layer} imports {kv.Key}, which its row does not list ({kv.Value})"));
        }

        Assert.True(problems.Count == 0,
            $"Imports {how} outside the layers table:{Environment.NewLine}{string.Join(Environment.NewLine, problems)}"
            + $"{Environment.NewLine}{Environment.NewLine}All imports {how}:{Environment.NewLine}{Describe(actual)}");
    }

    [Fact]
    public void CompiledCode_ImportsOnlyWhatTheTableAllows() =>
        AssertWithinTable(LayerImports.FromAssembly(typeof(PhysicsWorld).Assembly), "in the compiled code");

    [Fact]
    public void UsingDirectives_ImportOnlyWhatTheTableAllows() =>
        AssertWithinTable(LayerImports.FromSource(Path.Combine(Root, "src", "AcDream.Core", "Physics")), "in the using directives");

    [Fact]
    public void TheTable_ListsExactlyTheLibrarysLayers()
    {
        var layers = new SortedSet<string>(LayerImports.FromSource(Path.Combine(Root, "src", "AcDream.Core", "Physics")).Keys,
                                           StringComparer.Ordinal);
        Assert.Equal(layers, new SortedSet<string>(Documented().Keys, StringComparer.Ordinal));
    }

    [Fact]
    public void TheBottom_StaysAtTheBottom()
    {
        SortedDictionary<string, SortedSet<string>> table = Documented();
        Assert.Empty(table["Spatial"]);
        Assert.Equal(["Spatial"], table["Format"]);
        foreach ((string layer, SortedSet<string> allowed) in table)
        {
            // The world door (WorldData) and the scenery (pure functions over the region and scene entries) sit on top of
            // the loaders; nothing imports the door.
            if (layer != "WorldData" && layer != "Scenery")
            {
                Assert.DoesNotContain("Data", allowed);
            }

            Assert.DoesNotContain("Input", allowed);
            Assert.DoesNotContain("WorldData", allowed);
            // The debug view (Debug) reads the layers below it; nothing imports it.
            Assert.DoesNotContain("Debug", allowed);
        }

        Assert.DoesNotContain("Scenery", table["Data"]);

        // Below the cycle: neither Spatial nor Format can reach a layer that reaches back to it.
        foreach (string bottom in new[] { "Spatial", "Format" })
        {
            Assert.All(table[bottom], below => Assert.DoesNotContain(bottom, table[below]));
        }
    }

    [Fact]
    public void TheAnalysis_SeesAQualifiedReferenceWithoutAUsing()
    {
        // Format.RetailDataReader reads AFrame (Spatial) and Collision.Primitives.Sphere.UnPack reads through the reader:
        // both edges must be seen from the compiled code alone.
        SortedDictionary<string, SortedDictionary<string, string>> compiled = LayerImports.FromAssembly(typeof(PhysicsWorld).Assembly);
        Assert.Contains("Spatial", compiled["Format"].Keys);
        Assert.Contains("Format", compiled["Collision.Primitives"].Keys);
        Assert.Empty(compiled["Spatial"]);
    }
}
