using System.IO;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Tests.Api;

/// <summary>Bad files given to <see cref="TerrainImage.Load"/> (decoding by StbImageSharp; the real image is decoded in
/// <c>RealTerrainTests.TerrainPng_DecodesToTheSampleCsvExactly</c>).</summary>
public sealed class TerrainImageApiTests
{
    [Fact]
    public void Load_RejectsAFileThatIsNotAPng()
    {
        string path = Path.GetTempFileName();
        try
        {
            File.WriteAllText(path, "height,terrain\n");
            Assert.Throws<InvalidDataException>(() => TerrainImage.Load(path));
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact]
    public void Load_RejectsAPngWithoutAnImageHeader()
    {
        // The PNG signature followed by bytes that are no chunk: the decoder finds no IHDR.
        string path = Path.GetTempFileName();
        try
        {
            File.WriteAllBytes(path, [0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12]);
            Assert.Throws<InvalidDataException>(() => TerrainImage.Load(path));
        }
        finally
        {
            File.Delete(path);
        }
    }

    [TerrainDataFact]
    public void Load_RejectsATruncatedPng()
    {
        // The real terrain.png cut after 64 KiB: a valid header (2041 x 2041, 8-bit RGBA), then the image data ends.
        byte[] head = new byte[65536];
        using (FileStream f = File.OpenRead(Path.Combine(TerrainTestData.Dir, "terrain.png")))
        {
            f.ReadExactly(head);
        }

        string path = Path.GetTempFileName();
        try
        {
            File.WriteAllBytes(path, head);
            Assert.Throws<InvalidDataException>(() => TerrainImage.Load(path));
        }
        finally
        {
            File.Delete(path);
        }
    }
}
