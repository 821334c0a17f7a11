using System;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.World;

// Construction over loaded terrain: the retail collision sweep.
public sealed partial class PhysicsWorld
{
    /// <summary>
    /// Creates a world over <paramref name="terrain"/> with the retail collision sweep (<see cref="RetailSweep"/>): objects
    /// stand on its landblocks, collide with its buildings and cells, and step and slide as in retail. This is the world a
    /// client wants; <see cref="PhysicsWorld(double, PhysicsProfile?, int)"/> without terrain is the free-space sweep, an
    /// explicit choice for scenes with nothing to collide with.
    /// </summary>
    /// <param name="terrain">The landblocks and cells; a terrain world serves one physics world.</param>
    /// <param name="startTime">Initial client time, seconds.</param>
    /// <param name="profile">Time-slicing profile; <see cref="PhysicsProfile.Retail"/> when null.</param>
    /// <param name="hookPoolCapacity">Number of fade hooks preallocated so that fades do not allocate.</param>
    /// <exception cref="ArgumentNullException"><paramref name="terrain"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="startTime"/> is NaN or infinite, or <paramref name="terrain"/>
    /// already serves another world.</exception>
    public PhysicsWorld(TerrainWorld terrain, double startTime = 0.0, PhysicsProfile? profile = null, int hookPoolCapacity = 64)
        : this(startTime, profile, hookPoolCapacity)
    {
        ArgumentNullException.ThrowIfNull(terrain);
        Sweep = new RetailSweep(terrain);
    }

    /// <summary>
    /// Creates a world over <paramref name="cells"/> (a terrain world and its loaded indoor cells) with the retail collision
    /// sweep; as <see cref="PhysicsWorld(TerrainWorld, double, PhysicsProfile?, int)"/> for scenes with building interiors or
    /// dungeons.
    /// </summary>
    /// <param name="cells">The outdoor and indoor cells; they serve one physics world.</param>
    /// <param name="startTime">Initial client time, seconds.</param>
    /// <param name="profile">Time-slicing profile; <see cref="PhysicsProfile.Retail"/> when null.</param>
    /// <param name="hookPoolCapacity">Number of fade hooks preallocated so that fades do not allocate.</param>
    /// <exception cref="ArgumentNullException"><paramref name="cells"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="startTime"/> is NaN or infinite, or <paramref name="cells"/> already
    /// serve another world.</exception>
    public PhysicsWorld(WorldCells cells, double startTime = 0.0, PhysicsProfile? profile = null, int hookPoolCapacity = 64)
        : this(startTime, profile, hookPoolCapacity)
    {
        ArgumentNullException.ThrowIfNull(cells);
        Sweep = new RetailSweep(cells);
    }

    /// <summary>True when the world sweeps objects through free space (<see cref="FreeSpaceSweep"/>: no terrain, no walls).
    /// A world built over a <see cref="TerrainWorld"/> uses the retail sweep.</summary>
    public bool IsFreeSpace => Sweep is FreeSpaceSweep;
}
