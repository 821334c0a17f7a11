using System;
using System.IO;
using AcDream.Core.Physics.Spatial;
using StbImageSharp;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// The whole Dereth heightfield as one image, one pixel per terrain vertex (the fixture <c>terrain.png</c>:
/// 2041 × 2041, 8-bit RGBA, R = height index, G = terrain type, B = road bits). Global vertex (gx, gy) =
/// (landblock x * 8 + vx, landblock y * 8 + vy) is at column gx, row 2040 - gy (row 0 is the north edge).
/// </summary>
/// <remarks>The PNG is decoded with StbImageSharp (8-bit RGBA). Load-time only; it allocates.</remarks>
public sealed class TerrainImage
{
    /// <summary>Vertices along one side of the world: 255 * 8 + 1 = 2041.</summary>
    public const int Side = LandDefs.LCoordLimit + 1;

    private readonly byte[] _height;
    private readonly byte[] _type;
    private readonly byte[] _road;

    private TerrainImage(byte[] height, byte[] type, byte[] road)
    {
        _height = height;
        _type = type;
        _road = road;
    }

    /// <summary>Reads <c>terrain.png</c>.</summary>
    /// <exception cref="InvalidDataException">Not a PNG, not 2041 × 2041 8-bit RGBA non-interlaced, corrupt data, or a
    /// pixel whose terrain type is above 31 or road above 3.</exception>
    public static TerrainImage Load(string path)
    {
        byte[] file = File.ReadAllBytes(path);
        ReadOnlySpan<byte> signature = [0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A];
        if (file.Length < 8 || !file.AsSpan(0, 8).SequenceEqual(signature))
        {
            throw new InvalidDataException($"{path} is not a PNG file.");
        }

        ImageResult image;
        try
        {
            using var stream = new MemoryStream(file, writable: false);
            ImageInfo? info = ImageInfo.FromStream(stream);
            if (info is not { } i || i.BitsPerChannel != 8 || i.ColorComponents != ColorComponents.RedGreenBlueAlpha)
            {
                throw new InvalidDataException($"{path}: only 8-bit RGBA PNG is supported.");
            }

            if (i.Width != Side || i.Height != Side)
            {
                throw new InvalidDataException($"{path}: expected {Side} x {Side} pixels, found {i.Width} x {i.Height}.");
            }

            image = ImageResult.FromMemory(file, ColorComponents.RedGreenBlueAlpha);
        }
        catch (InvalidDataException)
        {
            throw;
        }
        catch (Exception e) when (e is not OutOfMemoryException) // StbImageSharp reports a corrupt file with System.Exception
        {
            throw new InvalidDataException($"{path}: corrupt PNG ({e.Message}).", e);
        }

        int width = image.Width, height = image.Height;
        const int bpp = 4;
        byte[] pixels = image.Data;
        var hgt = new byte[width * height];
        var typ = new byte[width * height];
        var road = new byte[width * height];
        for (int row = 0; row < height; row++)
        {
            ReadOnlySpan<byte> cur = pixels.AsSpan(row * width * bpp, width * bpp);
            for (int col = 0; col < width; col++)
            {
                int p = col * bpp;
                if (cur[p + 1] > 31 || cur[p + 2] > 3)
                {
                    throw new InvalidDataException($"{path}: pixel ({col}, {row}) has terrain type {cur[p + 1]}, road {cur[p + 2]}.");
                }

                int i = row * width + col;
                hgt[i] = cur[p];
                typ[i] = cur[p + 1];
                road[i] = cur[p + 2];
            }
        }

        return new TerrainImage(hgt, typ, road);
    }

    /// <summary>The raw data of landblock column <paramref name="blockX"/>, row <paramref name="blockY"/> (0..254).</summary>
    /// <exception cref="ArgumentOutOfRangeException">A coordinate is outside 0..254.</exception>
    public LandBlockEntry GetLandBlockEntry(int blockX, int blockY)
    {
        uint id = LandBlock.MakeId(blockX, blockY);
        Span<byte> h = stackalloc byte[LandBlock.VertexCount];
        Span<ushort> t = stackalloc ushort[LandBlock.VertexCount];
        for (int vx = 0; vx < LandBlock.SideVertexCount; vx++)
        {
            for (int vy = 0; vy < LandBlock.SideVertexCount; vy++)
            {
                int gx = blockX * LandDefs.BlockSide + vx;
                int gy = blockY * LandDefs.BlockSide + vy;
                int p = (LandDefs.LCoordLimit - gy) * Side + gx;
                int i = vx * LandBlock.SideVertexCount + vy;
                h[i] = _height[p];
                t[i] = TerrainTypes.MakeWord(_road[p], _type[p]);
            }
        }

        return new LandBlockEntry(id, h, t);
    }
}
