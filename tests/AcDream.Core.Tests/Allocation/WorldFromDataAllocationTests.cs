using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.WorldSceneEntries;

namespace AcDream.Core.Tests.Allocation;

public class WorldFromDataAllocationTests
{
    [Fact]
    public void AWalkerAmongStaticsBuiltFromData_AllocatesNothingPerTick_AfterWarmUp()
    {
        // A ring of statics made by the door (pines, low and tall rocks, grass, a Setup building) around a walker that circles
        // (2 m/s, 0.5 rad/s: radius 4 m) among them and brushes the nearest: every collision path of the new objects runs.
        PhysicsWorld world = World(out _);
        new WorldLoader(world, Source(
        [
            (Pine, At(100f, 106f)), (LowRock, At(105f, 100f)), (TallRock, At(95f, 100f)), (Grass, At(100f, 94f)),
            (Pine, At(104f, 104f)), (LowRock, At(96f, 96f)),
        ], [new BuildingDef(Building, At(130f, 130f), 0, [])])).Load(Block);
        PhysicsObj w = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(100f, 100f), At(100f, 100f)), 0.5f);
        SweepScene.SetWalk(w, new Vector3(0f, 2f, 0f));
        ((SimplePartArray)w.PartArray!).SequenceOmega = new Vector3(0f, 0f, 0.5f);
        SweepScene.Run(world, 600);
        AllocationProbe.AssertSteadyStateAllocatesNothing(() =>
        {
            for (int i = 0; i < 300; i++)
            {
                world.Tick(world.CurrentTime + SweepScene.Dt);
            }
        });
    }
}
