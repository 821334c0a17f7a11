using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The test project's one rule for folders (docs/architecture.md, "Tests"): an intent folder (<c>Retail/</c>,
/// <c>Behavior/</c>, …) holds its tests flat; a sub-folder is only for shared infrastructure or a suite driven as one, never
/// for one file and never for a subsystem of the library.
/// </summary>
public sealed class TestLayoutTests
{
    /// <summary>Library layers a sub-folder must not be named after, besides every namespace segment of the library.</summary>
    private static readonly string[] Layers =
    [
        "Animation", "Data", "Motion", "Objects", "Collision", "Cells", "Terrain", "World", "Scene", "Spatial", "Format",
        "Input", "Managers",
    ];

    private static string TestsDir =>
        Path.Combine(TerrainDataDir.RepoRoot() ?? throw new InvalidOperationException("repository root not found"),
            "tests", "AcDream.Core.Tests");

    /// <summary>Every sub-folder, at any depth, of each intent folder (build output left out).</summary>
    private static IEnumerable<string> SubFolders()
    {
        foreach (string intent in Directory.EnumerateDirectories(TestsDir))
        {
            string name = Path.GetFileName(intent);
            if (name is "bin" or "obj" || name.StartsWith('.'))
            {
                continue;
            }

            foreach (string sub in Directory.EnumerateDirectories(intent, "*", SearchOption.AllDirectories))
            {
                yield return sub;
            }
        }
    }

    private static string Relative(string dir) => Path.GetRelativePath(TestsDir, dir).Replace('\\', '/');

    [Fact]
    public void IntentSubFolders_NeverHoldJustOneFile()
    {
        string[] oneFile = SubFolders()
            .Where(d => Directory.EnumerateFiles(d, "*.cs", SearchOption.AllDirectories).Count() == 1)
            .Select(Relative)
            .Order(StringComparer.Ordinal)
            .ToArray();

        Assert.Empty(oneFile);
    }

    [Fact]
    public void IntentSubFolders_AreNeverNamedAfterALibraryLayer()
    {
        var layers = new HashSet<string>(Layers, StringComparer.OrdinalIgnoreCase);
        foreach (string? ns in typeof(PhysicsObj).Assembly.GetTypes().Select(t => t.Namespace).Distinct())
        {
            if (ns is not null && ns.StartsWith("AcDream.Core.Physics.", StringComparison.Ordinal))
            {
                layers.UnionWith(ns["AcDream.Core.Physics.".Length..].Split('.'));
            }
        }

        string[] named = SubFolders()
            .Where(d => layers.Contains(Path.GetFileName(d)))
            .Select(Relative)
            .Order(StringComparer.Ordinal)
            .ToArray();

        Assert.Empty(named);
    }
}
