using System;

namespace AcDream.Core.Tests.Support;

/// <summary>The fuzz tests' mutations of a valid entry: byte flips, a huge count at a word, random bytes spliced in.</summary>
internal static class ByteMutations
{
    /// <summary>A mutated copy of <paramref name="valid"/>: <paramref name="kind"/> 1, one to four random bytes changed;
    /// 2, one of <paramref name="huge"/> written at a random word; otherwise one to fifteen random bytes inserted at a random
    /// offset.</summary>
    public static byte[] Mutate(Random rng, byte[] valid, int kind, uint[] huge)
    {
        byte[] b = (byte[])valid.Clone();
        switch (kind)
        {
            case 1:
                for (int k = rng.Next(1, 5); k > 0; k--)
                {
                    b[rng.Next(b.Length)] = (byte)rng.Next(256);
                }

                return b;
            case 2:
                int at = rng.Next(b.Length / 4) * 4;
                BitConverter.TryWriteBytes(b.AsSpan(at), huge[rng.Next(huge.Length)]);
                return b;
            default:
                int cut = rng.Next(b.Length);
                int len = rng.Next(1, 16);
                var spliced = new byte[b.Length + len];
                b.AsSpan(0, cut).CopyTo(spliced);
                rng.NextBytes(spliced.AsSpan(cut, len));
                b.AsSpan(cut).CopyTo(spliced.AsSpan(cut + len));
                return spliced;
        }
    }
}
