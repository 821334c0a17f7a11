using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Geometry;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Every walk of <see cref="CellarWalkTests"/> (the same routes, the same assertions: cells visited in order, contact, floors,
/// no wall passed) through cells and a shell that were written in retail's byte layout and read back by the library's
/// unpackers (<c>CEnvironment</c> / <c>CCellStruct</c>, <c>CEnvCell</c>, <c>CGfxObj</c>). The dumps hold no BSP trees, so
/// the trees written are the ones today's path builds (BspBuilder's physics trees and the hull-plane cell chains), in retail's
/// node layout (<c>RetailEntries.Tree</c>); the collision then runs through the trees as unpacked.
/// </summary>
public class CellarWalkThroughRetailDataTests : CellarWalkTests
{
    /// <inheritdoc />
    private protected override CellarScene Scene() => CellarScene.Load(GeometryTestData.Dir!, TerrainTestData.Dir, throughRetailBytes: true);
}
