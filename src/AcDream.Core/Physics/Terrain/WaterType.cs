namespace AcDream.Core.Physics.Terrain;

/// <summary>
/// How much of a land cell (or a whole landblock) is water. Retail: <c>LandDefs::WaterType</c> (acclient.h:4103).
/// </summary>
public enum WaterType
{
    /// <summary>No corner is water. Retail: <c>NOT_WATER = 0</c>.</summary>
    NotWater = 0,

    /// <summary>Some corners are water. Retail: <c>PARTIALLY_WATER = 1</c>.</summary>
    PartiallyWater = 1,

    /// <summary>Every corner is water (for a landblock: every cell is entirely water). Retail: <c>ENTIRELY_WATER = 2</c>.</summary>
    EntirelyWater = 2,
}
