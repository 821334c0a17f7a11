using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

public class TerrainQueryStabilityTests
{
    private static TerrainWorld SlopedWorld()
    {
        var world = new TerrainWorld(TerrainTestData.IdentityTable());
        var rnd = new Random(11);
        for (int bx = 0x10; bx <= 0x11; bx++)
        {
            for (int by = 0x20; by <= 0x21; by++)
            {
                ushort[] t = TerrainTestData.Terrain(1);
                TerrainTestData.SetType(t, 4, 4, 16);
                world.AddLandBlock(LandBlock.MakeId(bx, by), TerrainTestData.Heights((_, _) => rnd.Next(60, 120)), t);
            }
        }

        return world;
    }

    [Fact]
    public void Queries_AllocateNothing()
    {
        TerrainWorld world = SlopedWorld();
        var p = new Position(0x1020003Au, new Vector3(180.25f, 40.5f, 0f));
        Vector3[] centers = [new(191.5f, 40.5f, 0.5f), new(191.5f, 40.5f, 1.5f)];
        float[] radii = [0.6f, 0.6f];
        var ids = new uint[32];
        double gx = 0x10 * 192.0 + 100.5, gy = 0x20 * 192.0 + 190.25;

        void Run()
        {
            world.TryGetTerrainHeight(p, out _);
            world.TryGetTerrainHeight(gx, gy, out _);
            world.TryGetWaterDepth(p, out _);
            world.TryFindTerrainPoly(p, out _, out _, out _);
            world.FindCellList(p, centers, radii, ids, out _);
            LandCell c = world.GetLandCell(0x1020001Du)!;
            c.FindTerrainPoly(new Vector3(100f, 100f, 0f), out _);
            c.GetWaterDepth(new Vector3(100f, 100f, 0f));
            int n = 0;
            LandCell.AddOutsideCellsForSphere(p.ObjCellId, centers[0], radii[0], ids, ref n);
        }

        Run();
        AllocationProbe.AssertSteadyStateAllocatesNothing(() =>
        {
            for (int i = 0; i < 1000; i++)
            {
                Run();
            }
        });
    }

    [Fact]
    public void BadQueries_ThrowOrFailCleanly()
    {
        TerrainWorld world = SlopedWorld();
        Assert.Throws<ArgumentException>(() => world.TryGetTerrainHeight(double.NaN, 1.0, out _));
        Assert.Throws<ArgumentException>(() => world.TryGetTerrainHeight(1.0, double.PositiveInfinity, out _));
        var bad = new Position(0x1020003Au, Vector3.Zero);
        bad.Frame.Origin = new Vector3(float.NaN, 0f, 0f);
        Assert.Throws<ArgumentException>(() => world.TryGetTerrainHeight(bad, out _));

        // Outside the world, past its edges, over unloaded land, with an id that is not a cell: documented false.
        Assert.False(world.TryGetTerrainHeight(-0.5, 10.0, out _));
        Assert.False(world.TryGetTerrainHeight(10.0, TerrainWorld.WorldLength, out _));
        Assert.False(world.TryGetTerrainHeight(10.0, 10.0, out _));
        Assert.False(world.TryGetTerrainHeight(new Position(0x10200000u, new Vector3(5f, 5f, 0f)), out _));
        Assert.False(world.TryGetTerrainHeight(new Position(0x00000001u, new Vector3(-30f, 5f, 0f)), out _));
        Assert.Throws<ArgumentException>(() => world.GetTerrainHeight(10.0, 10.0));
        Assert.Null(world.GetLandCell(0xFF200001u));
        Assert.Null(world.GetLandCell(0x10200041u));
    }

    [Fact]
    public void WorldEdges_EveryBorderCellResolvesAndNothingBeyond()
    {
        // Landblocks at the four corners of the world; the height query works up to the last metre and fails past it.
        var world = new TerrainWorld(TerrainTestData.IdentityTable());
        foreach ((int bx, int by) in new[] { (0, 0), (254, 0), (0, 254), (254, 254) })
        {
            world.AddLandBlock(LandBlock.MakeId(bx, by), TerrainTestData.Heights((vx, vy) => vx + vy), TerrainTestData.Terrain(1));
        }

        double max = TerrainWorld.WorldLength;
        Assert.True(world.TryGetTerrainHeight(0.0, 0.0, out float z00));
        Assert.Equal(0f, z00, 0.001f);
        Assert.True(world.TryGetTerrainHeight(max - 0.001, max - 0.001, out float zmax));
        Assert.Equal(16f, zmax, 0.01f);   // NE vertex index 8 + 8 = 16 -> 16 m
        Assert.False(world.TryGetTerrainHeight(max, 1.0, out _));

        // Re-homing a position past the NE edge fails (adjust_to_outside at the world edge).
        var p = new Position(0xFEFE0040u, new Vector3(192.5f, 10f, 0f));
        Assert.False(world.TryGetTerrainHeight(p, out _));
        Assert.False(p.TryAdjustToOutside());
    }

    [Fact]
    public void RemoveAndReplaceLandBlocks_CountAndLookups()
    {
        TerrainWorld world = SlopedWorld();
        Assert.Equal(4, world.LandBlockCount);
        Assert.NotNull(world.GetLandCell(0x10200001u));
        Assert.True(world.RemoveLandBlock(0x10200001u));
        Assert.False(world.RemoveLandBlock(0x1020FFFFu));
        Assert.Null(world.GetLandCell(0x10200001u));
        Assert.Equal(3, world.LandBlockCount);
        world.AddLandBlock(0x1121FFFFu, new byte[81], TerrainTestData.Terrain(1));   // replaces
        Assert.Equal(3, world.LandBlockCount);
        Assert.Equal(0f, world.GetTerrainHeight(0x11 * 192.0 + 5.0, 0x21 * 192.0 + 5.0));
    }
}
