using System;
using System.IO;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// Finds a folder of ../shared/data other than the terrain: the environment variable <see cref="Variable"/> when set (a
/// relative value is resolved against the repository root), else the folder <see cref="FolderName"/> beside the terrain
/// folder (<see cref="TerrainDataDir"/>: both live in ../shared/data). Only a folder holding <see cref="Marker"/> counts; when
/// none is found, the reason says what was looked for.
/// </summary>
internal sealed class SharedDataDir(string variable, string folderName, string marker)
{
    /// <summary>The real cellar geometry dumps (<c>../shared/data/geometry</c>), read by <c>CellarWalkTests</c>.</summary>
    public static readonly SharedDataDir Geometry = new("ACDREAM_GEOMETRY_DIR", "geometry", Path.Combine("cellar-ascent", "0x01000A2B.gfxobj.json"));

    /// <summary>The real network recordings (<c>../shared/data/replay</c>), read by <c>RealMotionReplayTests</c>.</summary>
    public static readonly SharedDataDir Replay = new("ACDREAM_REPLAY_DIR", "replay", "long-movement-run_s2c_movementevent.csv");

    private readonly Lazy<(string? Dir, string Reason)> _found = new(() =>
        (Resolve(variable, folderName, marker, Environment.GetEnvironmentVariable(variable), out string reason), reason));

    /// <summary>The environment variable that names the folder.</summary>
    public string Variable => variable;

    /// <summary>The folder's name beside the terrain folder.</summary>
    public string FolderName => folderName;

    /// <summary>The file, relative to the folder, whose presence marks it.</summary>
    public string Marker => marker;

    /// <summary>The folder, or null.</summary>
    public string? Dir => _found.Value.Dir;

    /// <summary>The folder, or null with <paramref name="reason"/> saying what was looked for and why it was not found.</summary>
    public string? Find(out string reason)
    {
        reason = _found.Value.Reason;
        return _found.Value.Dir;
    }

    /// <summary>The lookup for a given variable value (null or empty: unset).</summary>
    internal static string? Resolve(string variable, string folderName, string marker, string? value, out string reason)
    {
        string dir;
        if (!string.IsNullOrEmpty(value))
        {
            string? root = TerrainDataDir.RepoRoot();
            dir = Path.IsPathRooted(value) || root is null ? Path.GetFullPath(value) : Path.GetFullPath(Path.Combine(root, value));
            if (File.Exists(Path.Combine(dir, marker)))
            {
                reason = $"{variable}={value} -> {dir}";
                return dir;
            }

            reason = $"{variable}={value} resolves to {dir}, which has no {marker}";
            return null;
        }

        string? terrain = TerrainDataDir.Find(out string terrainReason);
        if (terrain is null)
        {
            reason = $"{variable} is unset and the terrain folder, beside which ../shared/data/{folderName} is looked for, is not found ({terrainReason})";
            return null;
        }

        dir = Path.GetFullPath(Path.Combine(terrain, "..", folderName));
        if (File.Exists(Path.Combine(dir, marker)))
        {
            reason = $"found {dir} beside the terrain folder";
            return dir;
        }

        reason = $"{variable} is unset and {dir}, beside the terrain folder, has no {marker}";
        return null;
    }
}
