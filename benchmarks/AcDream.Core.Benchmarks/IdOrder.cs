using System;

namespace AcDream.Core.Benchmarks;

/// <summary>The order in which a benchmark creates or removes objects, by id.</summary>
public enum IdOrder
{
    /// <summary>Ascending ids (1, 2, 3, …): for removal, oldest first.</summary>
    Ascending,

    /// <summary>Descending ids: for removal, newest first.</summary>
    Descending,

    /// <summary>A fixed pseudo-random permutation of the ids (seed 12345).</summary>
    Random,
}

/// <summary>Id sequences in an <see cref="IdOrder"/>.</summary>
internal static class IdOrders
{
    /// <summary>The ids 1..<paramref name="n"/> in <paramref name="order"/>.</summary>
    public static uint[] Ids(int n, IdOrder order)
    {
        var ids = new uint[n];
        for (int i = 0; i < n; i++)
        {
            ids[i] = order == IdOrder.Descending ? (uint)(n - i) : (uint)(i + 1);
        }

        if (order == IdOrder.Random)
        {
            var rnd = new Random(12345);
            for (int i = n - 1; i > 0; i--)
            {
                int j = rnd.Next(i + 1);
                (ids[i], ids[j]) = (ids[j], ids[i]);
            }
        }

        return ids;
    }
}
