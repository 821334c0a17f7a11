using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.WorldData;

/// <summary>
/// One landblock the <see cref="WorldLoader"/> built into the world: its terrain, its indoor cells, and every building,
/// static object and scenery object made for it, in retail's order (buildings, then the landblock's statics, then its
/// scenery, then the indoor cells' statics).
/// </summary>
public sealed class WorldBlock
{
    internal WorldBlock(uint blockId, LandBlock landBlock, LandBlockInfoEntry? info, EnvCell[] envCells, List<WorldObject> objects,
        uint[] missingIds)
    {
        BlockId = blockId;
        LandBlock = landBlock;
        Info = info;
        EnvCells = envCells;
        ObjectList = objects;
        MissingIds = missingIds;
    }

    /// <summary>The landblock id (0xXXYYFFFF).</summary>
    public uint BlockId { get; }

    /// <summary>The terrain now in the world.</summary>
    public LandBlock LandBlock { get; }

    /// <summary>The block's info entry (0xXXYYFFFE), or null when it has none.</summary>
    public LandBlockInfoEntry? Info { get; }

    /// <summary>The indoor cells now in the world, in id order: all of the block's when the <see cref="WorldLoader"/> loaded
    /// it; none when the <see cref="Landscape"/> did (its visible-cell table holds them, <see cref="Landscape.VisibleCells"/>).</summary>
    public IReadOnlyList<EnvCell> EnvCells { get; }

    /// <summary>The buildings, static objects and scenery made for the block, in the order retail makes them.</summary>
    public IReadOnlyList<WorldObject> Objects => ObjectList;

    /// <summary>The entry ids the block's objects needed and the data source did not hold (a Setup, or a part's GfxObj): each
    /// such object was not made, as retail's <c>makeObject</c> fails; the rest of the block stands.</summary>
    public IReadOnlyList<uint> MissingIds { get; }

    internal List<WorldObject> ObjectList { get; }
}
