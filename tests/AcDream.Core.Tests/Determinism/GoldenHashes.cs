namespace AcDream.Core.Tests.Determinism;

/// <summary>Recorded determinism pins (see <see cref="FrameGoldenHashTests"/>).</summary>
internal static class GoldenHashes
{
    public const ulong FrameSequence20000 = 14771659486592977584UL;
}
