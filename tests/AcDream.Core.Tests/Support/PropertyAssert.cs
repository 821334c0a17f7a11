using FsCheck;

namespace AcDream.Core.Tests.Support;

/// <summary>Asserts FsCheck properties: a falsified property fails the test with the shrunk counter-example.</summary>
internal static class PropertyAssert
{
    /// <summary>A reproducible configuration: <paramref name="maxTest"/> cases from a fixed seed (gamma must be odd).</summary>
    public static Config Replayable(int maxTest, ulong seed, ulong gamma) =>
        Config.QuickThrowOnFailure.WithMaxTest(maxTest).WithReplay(seed, gamma);

    /// <summary>Checks <paramref name="property"/> under <paramref name="config"/> and throws when a case falsifies it.</summary>
    public static void Holds(Config config, Property property) => Check.One(config, property);
}
