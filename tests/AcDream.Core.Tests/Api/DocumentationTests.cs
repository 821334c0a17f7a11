using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>Documentation that tooltips and readers see: one summary per type, links that resolve inside the repository.</summary>
public sealed partial class DocumentationTests
{
    private static string Root => TerrainDataDir.RepoRoot() ?? throw new InvalidOperationException("repository root not found");

    [GeneratedRegex(@"^\s*(public|internal)\s+(sealed\s+|static\s+|readonly\s+)*partial\s+(class|struct|record|interface)\s+(\w+)")]
    private static partial Regex PartialType();

    [GeneratedRegex(@"\]\(([^)\s]+)\)")]
    private static partial Regex Link();

    [Fact]
    public void EveryPartialType_HasItsSummaryInOneFileOnly()
    {
        // A partial declaration preceded by an XML summary in two files gives the type two summaries, which the compiler
        // joins: the tooltip then opens with whichever file came first (TerrainWorld, Sphere and LandBlock did).
        var withSummary = new Dictionary<string, List<string>>();
        foreach (string file in Directory.EnumerateFiles(Path.Combine(Root, "src"), "*.cs", SearchOption.AllDirectories))
        {
            string[] lines = File.ReadAllLines(file);
            for (int i = 0; i < lines.Length; i++)
            {
                Match m = PartialType().Match(lines[i]);
                if (!m.Success)
                {
                    continue;
                }

                int j = i - 1;
                while (j >= 0 && (lines[j].TrimStart().StartsWith('[') || lines[j].TrimStart().StartsWith("// ", StringComparison.Ordinal)))
                {
                    j--;
                }

                if (j >= 0 && lines[j].TrimStart().StartsWith("///", StringComparison.Ordinal))
                {
                    string key = Path.GetDirectoryName(file) + "/" + m.Groups[4].Value;
                    if (!withSummary.TryGetValue(key, out List<string>? files))
                    {
                        files = [];
                        withSummary[key] = files;
                    }

                    files.Add(Path.GetFileName(file));
                }
            }
        }

        var doubled = new List<string>();
        foreach (var (type, files) in withSummary)
        {
            if (files.Count > 1)
            {
                doubled.Add(type + ": " + string.Join(", ", files));
            }
        }

        Assert.Empty(doubled);
        Assert.True(withSummary.ContainsKey(Path.Combine(Root, "src", "AcDream.Core", "Physics", "Terrain") + "/TerrainWorld"));
    }

    [Fact]
    public void MarkdownLinks_ResolveInsideTheRepository()
    {
        // Every relative link of README.md, docs/ and the sample points at a file of this repository; none is an absolute
        // path (a note on the author's machine).
        var files = new List<string> { Path.Combine(Root, "README.md") };
        files.AddRange(Directory.EnumerateFiles(Path.Combine(Root, "docs"), "*.md"));
        var bad = new List<string>();
        foreach (string file in files)
        {
            foreach (Match m in Link().Matches(File.ReadAllText(file)))
            {
                string target = m.Groups[1].Value;
                if (target.StartsWith("http://", StringComparison.Ordinal) || target.StartsWith("https://", StringComparison.Ordinal) || target.StartsWith('#'))
                {
                    continue;
                }

                string path = target.Split('#')[0];
                string full = Path.GetFullPath(Path.Combine(Path.GetDirectoryName(file)!, path));
                if (Path.IsPathRooted(path) || !full.StartsWith(Root, StringComparison.Ordinal) || !(File.Exists(full) || Directory.Exists(full)))
                {
                    bad.Add(Path.GetFileName(file) + ": " + target);
                }
            }
        }

        Assert.Empty(bad);
    }
}
