using System;
using System.Buffers.Binary;
using System.IO;
using System.IO.Compression;
using AcDream.Core.Physics.Math;

namespace AcDream.Core.Physics.Terrain;

/// <summary>
/// The whole Dereth heightfield as one image, one pixel per terrain vertex (the fixture <c>terrain.png</c>:
/// 2041 × 2041, 8-bit RGBA, R = height index, G = terrain type, B = road bits). Global vertex (gx, gy) =
/// (landblock x * 8 + vx, landblock y * 8 + vy) is at column gx, row 2040 - gy (row 0 is the north edge).
/// </summary>
/// <remarks>Includes a minimal PNG reader (8-bit RGBA, non-interlaced; all five row filters) built on
/// <see cref="ZLibStream"/>. Load-time only; it allocates.</remarks>
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

        int width = 0, height = 0;
        using var idat = new MemoryStream();
        int pos = 8;
        while (pos + 12 <= file.Length)
        {
            int len = BinaryPrimitives.ReadInt32BigEndian(file.AsSpan(pos));
            if (len < 0 || pos + 12 + (long)len > file.Length)
            {
                throw new InvalidDataException($"{path}: truncated PNG chunk.");
            }

            ReadOnlySpan<byte> type = file.AsSpan(pos + 4, 4);
            ReadOnlySpan<byte> data = file.AsSpan(pos + 8, len);
            if (type.SequenceEqual("IHDR"u8))
            {
                width = BinaryPrimitives.ReadInt32BigEndian(data);
                height = BinaryPrimitives.ReadInt32BigEndian(data[4..]);
                if (data[8] != 8 || data[9] != 6 || data[10] != 0 || data[11] != 0 || data[12] != 0)
                {
                    throw new InvalidDataException($"{path}: only 8-bit RGBA non-interlaced PNG is supported.");
                }
            }
            else if (type.SequenceEqual("IDAT"u8))
            {
                idat.Write(data);
            }
            else if (type.SequenceEqual("IEND"u8))
            {
                break;
            }

            pos += 12 + len;
        }

        if (width != Side || height != Side)
        {
            throw new InvalidDataException($"{path}: expected {Side} x {Side} pixels, found {width} x {height}.");
        }

        const int bpp = 4;
        int stride = width * bpp;
        byte[] raw = new byte[height * (stride + 1)];
        idat.Position = 0;
        using (var z = new ZLibStream(idat, CompressionMode.Decompress))
        {
            z.ReadExactly(raw);
        }

        var hgt = new byte[width * height];
        var typ = new byte[width * height];
        var road = new byte[width * height];
        byte[] prev = new byte[stride];
        byte[] cur = new byte[stride];
        for (int row = 0; row < height; row++)
        {
            int src = row * (stride + 1);
            byte filter = raw[src];
            Unfilter(filter, raw.AsSpan(src + 1, stride), prev, cur, bpp, path);
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

            (prev, cur) = (cur, prev);
        }

        return new TerrainImage(hgt, typ, road);
    }

    /// <summary>The raw data of landblock column <paramref name="blockX"/>, row <paramref name="blockY"/> (0..254).</summary>
    /// <exception cref="ArgumentOutOfRangeException">A coordinate is outside 0..254.</exception>
    public LandBlockData GetLandBlockData(int blockX, int blockY)
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

        return new LandBlockData(id, h, t);
    }

    // PNG row filters (ISO/IEC 15948 §9): None, Sub, Up, Average, Paeth.
    private static void Unfilter(byte filter, ReadOnlySpan<byte> src, ReadOnlySpan<byte> prev, Span<byte> cur, int bpp, string path)
    {
        for (int i = 0; i < src.Length; i++)
        {
            int a = i >= bpp ? cur[i - bpp] : 0;
            int b = prev[i];
            int c = i >= bpp ? prev[i - bpp] : 0;
            int x = src[i];
            cur[i] = filter switch
            {
                0 => (byte)x,
                1 => (byte)(x + a),
                2 => (byte)(x + b),
                3 => (byte)(x + ((a + b) >> 1)),
                4 => (byte)(x + Paeth(a, b, c)),
                _ => throw new InvalidDataException($"{path}: unknown PNG filter {filter}."),
            };
        }
    }

    private static int Paeth(int a, int b, int c)
    {
        int p = a + b - c;
        int pa = System.Math.Abs(p - a);
        int pb = System.Math.Abs(p - b);
        int pc = System.Math.Abs(p - c);
        return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
    }
}
