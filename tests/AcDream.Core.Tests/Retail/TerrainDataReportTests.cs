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
