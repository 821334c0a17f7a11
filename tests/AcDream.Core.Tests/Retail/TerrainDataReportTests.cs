using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// A fact that says in its display name where the real terrain comes from, or, skipped, why the real-terrain tests are skipped:
/// <c>dotnet test</c> at its default verbosity lists skipped tests by display name (not by skip reason), so the reason shows
/// in every run that lacks the data.
/// </summary>
public sealed class TerrainDataStatusFactAttribute : FactAttribute
{
    /// <summary>Names the folder, or skips with the reason in the display name.</summary>
    public TerrainDataStatusFactAttribute()
    {
        string? dir = TerrainTestData.FindDir(out string reason);
        if (dir is null)
        {
            DisplayName = "Real-terrain tests are skipped: " + reason;
            Skip = "Real terrain data not found: " + reason + ".";
        }
        else
        {
            DisplayName = "Real-terrain tests read " + dir;
        }
    }
}

/// <summary>The status line of the real-terrain tests (see <see cref="TerrainDataStatusFactAttribute"/>).</summary>
public sealed class TerrainDataReportTests
{
    /// <summary>The folder found holds the marker file the loaders read first.</summary>
    [TerrainDataStatusFact]
    public void Reports_where_the_real_terrain_comes_from()
    {
        string? dir = TerrainTestData.FindDir(out _);
        Assert.NotNull(dir);
        Assert.True(System.IO.File.Exists(System.IO.Path.Combine(dir, TerrainDataDir.MarkerFile)));
    }
}

/// <summary>
/// The same status line for another folder of ../shared/data (<see cref="SharedDataDir"/>): "geometry" (the cellar dumps of
/// <c>CellarWalkTests</c>) or "replay" (the recordings of <c>RealMotionReplayTests</c>). Its display name says where the data
/// comes from or, skipped, why the tests that read it are skipped, so that a run without the data says so at the default
/// verbosity.
/// </summary>
public sealed class SharedDataStatusFactAttribute : FactAttribute
{
    /// <summary>Names the folder of <paramref name="folder"/> ("geometry" or "replay"), or skips with the reason.</summary>
    public SharedDataStatusFactAttribute(string folder)
    {
        SharedDataDir data = SharedDataReportTests.Of(folder);
        string? dir = data.Find(out string reason);
        if (dir is null)
        {
            DisplayName = $"Real-{folder} tests are skipped: {reason}";
            Skip = $"Real {folder} data not found: {reason}.";
        }
        else
        {
            DisplayName = $"Real-{folder} tests read {dir}";
        }
    }
}

/// <summary>The status lines of the geometry and replay tests (see <see cref="SharedDataStatusFactAttribute"/>).</summary>
public sealed class SharedDataReportTests
{
    /// <summary>The lookup of a folder name.</summary>
    internal static SharedDataDir Of(string folder) => folder switch
    {
        "geometry" => SharedDataDir.Geometry,
        "replay" => SharedDataDir.Replay,
        _ => throw new System.ArgumentException("Unknown data folder: " + folder, nameof(folder)),
    };

    /// <summary>The geometry folder found holds the dump the cellar scene reads first.</summary>
    [SharedDataStatusFact("geometry")]
    public void Reports_where_the_real_geometry_comes_from() => AssertFound(SharedDataDir.Geometry);

    /// <summary>The replay folder found holds the recording the replay tests read first.</summary>
    [SharedDataStatusFact("replay")]
    public void Reports_where_the_real_replay_comes_from() => AssertFound(SharedDataDir.Replay);

    [Fact]
    public void AVariableNamingAFolderWithoutTheMarker_IsNotFound_AndTheReasonSaysWhy()
    {
        string dir = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "acdream-nodata-" + System.Guid.NewGuid().ToString("N"));
        Assert.Null(SharedDataDir.Resolve("ACDREAM_REPLAY_DIR", "replay", "marker.csv", dir, out string reason));
        Assert.Equal($"ACDREAM_REPLAY_DIR={dir} resolves to {dir}, which has no marker.csv", reason);
    }

    private static void AssertFound(SharedDataDir data)
    {
        string? dir = data.Find(out _);
        Assert.NotNull(dir);
        Assert.True(System.IO.File.Exists(System.IO.Path.Combine(dir, data.Marker)));
    }
}

/// <summary>The terrain folder lookup shared by the tests and the report (<see cref="TerrainDataDir.Resolve"/>).</summary>
public sealed class TerrainDataDirTests : System.IDisposable
{
    // A scratch tree: <tmp>/work/repo/tests/bin (the running assembly), <tmp>/work/shared/data/ac-terrain (the data).
    private readonly string _top = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "acdream-terrain-" + System.Guid.NewGuid().ToString("N"));

    private string Repo => System.IO.Path.Combine(_top, "work", "repo");

    private string Bin => System.IO.Path.Combine(Repo, "tests", "bin");

    private string Data => System.IO.Path.Combine(_top, "work", "shared", "data", "ac-terrain");

    public TerrainDataDirTests()
    {
        System.IO.Directory.CreateDirectory(Bin);
        System.IO.Directory.CreateDirectory(Data);
        System.IO.File.WriteAllText(System.IO.Path.Combine(Data, TerrainDataDir.MarkerFile), "");
    }

    public void Dispose() => System.IO.Directory.Delete(_top, recursive: true);

    [Fact]
    public void RelativeVariable_IsResolvedAgainstTheRepositoryRoot()
    {
        // README's value, "../shared/data/ac-terrain", from a test whose working folder is tests/bin.
        Assert.Equal(Data, TerrainDataDir.Resolve("../shared/data/ac-terrain", Repo, Bin, out _));
    }

    [Fact]
    public void Unset_FindsTheSharedFolderByWalkingUp()
    {
        Assert.Equal(Data, TerrainDataDir.Resolve(null, Repo, Bin, out string reason));
        Assert.StartsWith("found ", reason, System.StringComparison.Ordinal);
    }

    [Fact]
    public void AFolderWithoutTheData_IsNotFound_AndTheReasonSaysWhere()
    {
        Assert.Null(TerrainDataDir.Resolve("nowhere", Repo, Bin, out string reason));
        Assert.Contains(System.IO.Path.Combine(Repo, "nowhere"), reason, System.StringComparison.Ordinal);
        System.IO.File.Delete(System.IO.Path.Combine(Data, TerrainDataDir.MarkerFile));
        Assert.Null(TerrainDataDir.Resolve(null, Repo, Bin, out reason));
        Assert.Contains("unset", reason, System.StringComparison.Ordinal);
    }
}
