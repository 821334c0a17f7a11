using System;
using System.IO;

namespace AcDream.Core.Tests.Support.Shared;

/// <summary>
/// Finds the real Dereth terrain fixtures (the folder holding <c>landblock_heights_sample.csv</c>) the same way for the tests,
/// the benchmarks and the report (compiled into both; no xunit here): the environment variable <c>ACDREAM_TERRAIN_DIR</c>
/// when set (a relative value is resolved against the repository root), else <c>../shared/data/ac-terrain</c> beside the
/// repository, found by walking up from the running assembly.
/// </summary>
internal static class TerrainDataDir
{
    /// <summary>The environment variable that names the folder.</summary>
    public const string Variable = "ACDREAM_TERRAIN_DIR";

    /// <summary>The file whose presence marks the folder.</summary>
    public const string MarkerFile = "landblock_heights_sample.csv";

    /// <summary>The folder, or null with <paramref name="reason"/> saying what was looked for and why it was not found.</summary>
    public static string? Find(out string reason) =>
        Resolve(Environment.GetEnvironmentVariable(Variable), RepoRoot(), AppContext.BaseDirectory, out reason);

    /// <summary>
    /// The lookup of <see cref="Find"/> for a given variable value (null or empty: unset), repository root and starting
    /// folder: the value resolved against <paramref name="repoRoot"/> when relative, else the first
    /// <c>../shared/data/ac-terrain</c> beside a folder above <paramref name="startDir"/>; only a folder holding
    /// <see cref="MarkerFile"/> counts.
    /// </summary>
    public static string? Resolve(string? value, string? repoRoot, string startDir, out string reason)
    {
        if (!string.IsNullOrEmpty(value))
        {
            string dir = Path.IsPathRooted(value) || repoRoot is null ? Path.GetFullPath(value) : Path.GetFullPath(Path.Combine(repoRoot, value));
            if (File.Exists(Path.Combine(dir, MarkerFile)))
            {
                reason = $"{Variable}={value} -> {dir}";
                return dir;
            }

            reason = $"{Variable}={value} resolves to {dir}, which has no {MarkerFile}";
            return null;
        }

        for (string? d = startDir; d is not null; d = Path.GetDirectoryName(d.TrimEnd(Path.DirectorySeparatorChar)))
        {
            string candidate = Path.GetFullPath(Path.Combine(d, "..", "shared", "data", "ac-terrain"));
            if (File.Exists(Path.Combine(candidate, MarkerFile)))
            {
                reason = $"found {candidate} (walking up from {startDir})";
                return candidate;
            }
        }

        reason = $"{Variable} is unset and no ../shared/data/ac-terrain lies beside any folder above {startDir}";
        return null;
    }

    /// <summary>The repository root (the first folder above the running assembly holding AcDream.sln), or null.</summary>
    public static string? RepoRoot()
    {
        for (string? d = AppContext.BaseDirectory; d is not null; d = Path.GetDirectoryName(d.TrimEnd(Path.DirectorySeparatorChar)))
        {
            if (File.Exists(Path.Combine(d, "AcDream.sln")))
            {
                return d;
            }
        }

        return null;
    }
}
