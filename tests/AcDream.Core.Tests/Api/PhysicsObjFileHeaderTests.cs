using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// <c>PhysicsObj</c> is split into partial files by concern; the first line of each names that concern and the retail functions
/// it holds (<c>// PhysicsObj — the object tick: update_object, …</c>), which is the class's only index.
/// </summary>
public sealed partial class PhysicsObjFileHeaderTests
{
    [GeneratedRegex(@"^// PhysicsObj — \S.*\S$")]
    private static partial Regex Header();

    private static IEnumerable<string> PartialFiles()
    {
        string root = TerrainDataDir.RepoRoot() ?? throw new InvalidOperationException("repository root not found");
        string dir = Path.Combine(root, "src", "AcDream.Core", "Physics", "Objects");
        return Directory.EnumerateFiles(dir, "PhysicsObj.cs")
                        .Concat(Directory.EnumerateFiles(dir, "PhysicsObj.*.cs"))
                        .Order(StringComparer.Ordinal);
    }

    [Fact]
    public void EveryPhysicsObjPartial_OpensWithItsConcern()
    {
        var files = PartialFiles().ToList();
        Assert.True(files.Count > 10, $"expected the PhysicsObj partial files, found {files.Count}");

        var missing = new List<string>();
        foreach (string file in files)
        {
            string first = File.ReadLines(file).FirstOrDefault() ?? "";
            if (!Header().IsMatch(first))
            {
                missing.Add($"{Path.GetFileName(file)}: \"{first}\"");
            }
        }

        Assert.True(missing.Count == 0, "a PhysicsObj partial must open with `// PhysicsObj — <concern>: <retail functions>.`:\n"
                                        + string.Join("\n", missing));
    }

    [Fact]
    public void EveryPhysicsObjPartial_IsUnder500Lines()
    {
        var over = PartialFiles().Select(f => (Name: Path.GetFileName(f), Lines: File.ReadLines(f).Count()))
                                 .Where(f => f.Lines >= 500)
                                 .Select(f => $"{f.Name}: {f.Lines}")
                                 .ToList();
        Assert.True(over.Count == 0, "over 500 lines:\n" + string.Join("\n", over));
    }
}
