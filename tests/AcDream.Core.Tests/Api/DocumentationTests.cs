using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
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

    // Phrases that say ported code is still to come, or that contradict what the library holds. Each matched a comment or a
    // document that had gone stale (the sweep seam "until the collision module provides the retail sweep", "object shadows:
    // a later part of the port", a test helper's "until the library has a human setup preset", PhysicsGlobals' "every retail
    // constant"); the list is kept narrow so that a hit is a claim to check, not a word that happens to appear.
    [GeneratedRegex(@"\b(still|yet|is|are) to come\b|\bnot yet ported\b|\bnot ported yet\b|\b(will|to) be ported\b|\blater part of the port\b"
        + @"|\buntil the collision module\b|\bstands in until\b|\bnot yet implemented\b|\bnot implemented yet\b|\bplaceholder\b"
        + @"|\bno human (setup )?preset\b|\buntil the library has\b|\b(another|a later|a future) change adds\b|\boutdoor terrain today\b"
        + @"|\bevery retail (physics )?constant used\b|\(every retail constant\)",
        RegexOptions.IgnoreCase)]
    private static partial Regex StalePhrase();

    [GeneratedRegex(@"\b(TODO|FIXME|TBD)\b")]
    private static partial Regex WorkMarker();

    /// <summary>
    /// Lines that may hold a stale phrase, each with its reason: (file relative to the root, text the line contains).
    /// </summary>
    private static readonly (string File, string Line, string Reason)[] StalePhraseAllowed =
    [
        ("docs/divergences.md", "## Sweep: what is not ported yet", "the divergence that lists what is missing, and says so"),
        ("docs/divergences.md", "(\"what is not ported yet\")", "a reference to that section by its title"),
        ("docs/transition.md", "and what is not ported yet.", "a reference to that section"),
    ];

    [Fact]
    public void NoCommentOrDocument_SaysPortedCodeIsStillToCome()
    {
        // The comments of the code (src, samples, benchmarks, tests) and the documents (README.md, PACKAGE.md, docs/*.md)
        // hold no phrase that announces a port still to come or a missing piece the library has; this file is left out (it
        // spells the phrases).
        var files = new List<string> { Path.Combine(Root, "README.md"), Path.Combine(Root, "src", "AcDream.Core", "PACKAGE.md") };
        files.AddRange(Directory.EnumerateFiles(Path.Combine(Root, "docs"), "*.md"));
        foreach (string folder in new[] { "src", "samples", "benchmarks", "tests" })
        {
            foreach (string file in Directory.EnumerateFiles(Path.Combine(Root, folder), "*.cs", SearchOption.AllDirectories))
            {
                string sep = Path.DirectorySeparatorChar.ToString();
                if (!file.Contains(sep + "bin" + sep, StringComparison.Ordinal) && !file.Contains(sep + "obj" + sep, StringComparison.Ordinal)
                    && Path.GetFileName(file) != "DocumentationTests.cs")
                {
                    files.Add(file);
                }
            }
        }

        var stale = new List<string>();
        foreach (string file in files)
        {
            string relative = Path.GetRelativePath(Root, file).Replace('\\', '/');
            string[] lines = File.ReadAllLines(file);
            for (int i = 0; i < lines.Length; i++)
            {
                string line = lines[i];
                Match m = StalePhrase().Match(line);
                if (!m.Success)
                {
                    m = WorkMarker().Match(line);
                }

                if (m.Success && !Array.Exists(StalePhraseAllowed, a => a.File == relative && line.Contains(a.Line, StringComparison.Ordinal)))
                {
                    stale.Add($"{relative}:{i + 1}: \"{m.Value}\" in: {line.Trim()}");
                }
            }
        }

        Assert.True(stale.Count == 0, "Stale phrases (fix the text, or allow the line with its reason):\n" + string.Join("\n", stale));
        Assert.True(files.Count > 100);
    }

    [GeneratedRegex(@"^(?:- )?`(\w+)`: (.*)$")]
    private static partial Regex TypeBullet();

    [GeneratedRegex(@"`(\w+)\(")]
    private static partial Regex MethodCall();

    [Fact]
    public void InterpolationDocsPublicApi_NamesOnlyPublicMethods()
    {
        // docs/interpolation.md "Public API (client)": each bullet "- `Type`: ..." names methods of that public type; every
        // `Name(` there must be a public method of it (the page once listed Enqueue, GetNode, AdjustOffset, UseTime and
        // EnqueueNode, none of them public). An entry runs on over its continuation lines.
        string text = File.ReadAllText(Path.Combine(Root, "docs", "interpolation.md"));
        int start = text.IndexOf("## Public API (client)", StringComparison.Ordinal);
        Assert.True(start >= 0, "the section is missing");
        int end = text.IndexOf("\n## ", start + 1, StringComparison.Ordinal);
        string section = text[start..(end < 0 ? text.Length : end)];
        var bullets = new List<string>();
        foreach (string line in section.Split('\n'))
        {
            if (line.StartsWith("- ", StringComparison.Ordinal) || TypeBullet().IsMatch(line))
            {
                bullets.Add(line);
            }
            else if (line.Trim().Length > 0 && bullets.Count > 0)
            {
                bullets[^1] += " " + line.Trim();
            }
        }

        var exported = new Dictionary<string, Type>();
        foreach (Type t in typeof(AcDream.Core.Physics.Objects.PhysicsObj).Assembly.GetExportedTypes())
        {
            exported[t.Name] = t;
        }

        var bad = new List<string>();
        int checkedTypes = 0;
        foreach (string bullet in bullets)
        {
            Match b = TypeBullet().Match(bullet);
            if (!b.Success || !exported.TryGetValue(b.Groups[1].Value, out Type? type))
            {
                continue;
            }

            checkedTypes++;
            foreach (Match m in MethodCall().Matches(b.Groups[2].Value))
            {
                if (type.GetMethods(System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.Static)
                    .All(x => x.Name != m.Groups[1].Value))
                {
                    bad.Add(type.Name + "." + m.Groups[1].Value);
                }
            }
        }

        Assert.Empty(bad);
        Assert.True(checkedTypes >= 2, "expected entries for PhysicsObj and the managers");
    }
}
