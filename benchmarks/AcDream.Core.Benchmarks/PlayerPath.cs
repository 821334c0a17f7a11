namespace AcDream.Core.Benchmarks;

/// <summary>How the player moves in <see cref="SceneRestingObjectsBenchmarks"/>.</summary>
public enum PlayerPath
{
    /// <summary>A 2 m square, turning every 30 ticks, as the other movers.</summary>
    Square,

    /// <summary>A 51 m line east and back west, turning every 750 ticks.</summary>
    Line,

    /// <summary>Standing still.</summary>
    Still,
}
