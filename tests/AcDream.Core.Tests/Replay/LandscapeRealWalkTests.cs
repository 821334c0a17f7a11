using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Replay;

/// <summary>A fact that needs the real terrain (<see cref="TerrainTestData"/>) and the replay recordings
/// (<see cref="SharedDataDir.Replay"/>); skipped with the reason when either is absent.</summary>
public sealed class TerrainAndReplayDataFactAttribute : FactAttribute
{
    /// <summary>Skips the test when the fixtures are not found.</summary>
    public TerrainAndReplayDataFactAttribute()
    {
        if (TerrainTestData.FindDir(out string reason) is null)
        {
            Skip = "Real terrain data not found: " + reason + ".";
        }
        else if (SharedDataDir.Replay.Find(out string replayReason) is null)
        {
            Skip = "Real replay data not found: " + replayReason + ".";
        }
    }
}

/// <summary>
/// The landscape on the real Dereth terrain (every landblock of terrain.png, no landblock infos): a walker crossing from
/// Holtburg's 0xA9B4 into 0xA9B5 with the landscape following it every tick, and the recorded positions of a real player
/// (long-movement-run, 0x5000001D: Holtburg, a portal into dungeon 0x01F9, 0x9DAF, dungeon 0x038C) driven through it. The
/// invariants of <c>LScape</c> are checked after every change: the grid centred on the player's block, its 3 × 3 at full
/// detail and in the world, nothing else in the world, the player never lost.
/// </summary>
public class LandscapeRealWalkTests(ITestOutputHelper output)
{
    // Every landblock of the real heightfield, without infos, as retail entries (read on demand).
    private sealed class TerrainSource(TerrainImage image) : IRetailDataSource
    {
        public int BlockReads { get; private set; }

        public bool TryGetEntry(uint id, out ReadOnlyMemory<byte> bytes)
        {
            if ((id & 0xFFFFu) != 0xFFFFu)
            {
                bytes = default;
                return false;
            }

            BlockReads++;
            LandBlockEntry e = image.GetLandBlockEntry((int)(id >> 24), (int)((id >> 16) & 0xFF));
            bytes = WorldDataBytes.LandBlock(id, false, e.Terrain, e.Height);
            return true;
        }
    }

    private static Landscape Make(out PhysicsWorld world, out WorldCells cells, out TerrainSource source)
    {
        cells = new WorldCells(new Physics.Terrain.TerrainWorld(TerrainTestData.RealTable));
        world = new PhysicsWorld(0.0) { Sweep = new RetailSweep(cells) };
        source = new TerrainSource(TerrainTestData.Image);
        return new Landscape(new WorldLoader(world, source));
    }

    // The grid is centred on the load point's block, its 3 × 3 (inside the world) is at full detail and is exactly what the
    // world's terrain holds.
    private static void AssertInvariants(Landscape l, WorldCells cells)
    {
        LandDefs.BlockIdToLCoord(l.LoadedCellId, out int lx, out int ly);
        int cx = lx / 8, cy = ly / 8;
        int r = l.MidRadius;
        int full = 0;
        for (int ix = 0; ix < l.MidWidth; ix++)
        {
            for (int iy = 0; iy < l.MidWidth; iy++)
            {
                int bx = cx - r + ix, by = cy - r + iy;
                LandscapeBlock? b = l.GetBlock(ix, iy);
                bool inWorld = bx >= 0 && by >= 0 && bx < 255 && by < 255;
                Assert.Equal(inWorld, b is not null);
                if (b is null)
                {
                    continue;
                }

                Assert.Equal(((uint)bx << 24) | ((uint)by << 16) | 0xFFFFu, b.BlockId);
                bool ring1 = Math.Abs(ix - r) <= 1 && Math.Abs(iy - r) <= 1;
                Assert.Equal(ring1, b.IsFullDetail);
                Assert.Equal(ring1, cells.Terrain.GetLandBlock(bx, by) is not null);
                full += ring1 ? 1 : 0;
            }
        }

        Assert.Equal(full, cells.Terrain.LandBlockCount);
    }

    [TerrainDataFact]
    public void AWalkerCrossingABlockBoundary_IsFollowed_EveryTick()
    {
        Landscape l = Make(out PhysicsWorld world, out WorldCells cells, out _);
        l.SetMidRadius(2);
        // Holtburg 0xA9B4, 20 m south of its north edge, facing north (+y).
        var start = new Position(0xA9B40000u | (4 * 8 + 7 + 1), new Frame(new Vector3(100f, 172f, 0f), Quaternion.Identity));
        l.ChangePosition(start);
        start.Frame.Origin.Z = SweepScene.Ground(cells.Terrain, start);
        PhysicsObj walker = SweepScene.Walker(world, start, id: 1);
        world.Player = walker;
        SweepScene.SetWalk(walker, new Vector3(0f, 4f, 0f));
        var blocks = new List<uint>();
        for (int t = 0; t < 200; t++)
        {
            LandscapeChange c = l.ChangePosition(walker.Position);
            Assert.NotEqual(LandscapeStatus.NoCell, c.Status);
            AssertInvariants(l, cells);
            world.Tick(world.CurrentTime + SweepScene.Dt);
            Assert.NotEqual(0u, walker.CellId);
            uint block = walker.CellId & 0xFFFF0000u;
            if (blocks.Count == 0 || blocks[^1] != block)
            {
                blocks.Add(block);
            }
        }

        Assert.Equal(new[] { 0xA9B40000u, 0xA9B50000u }, blocks);
        output.WriteLine($"walker ends at 0x{walker.CellId:X8} {walker.Position.Frame.Origin}");
    }

    [TerrainAndReplayDataFact]
    public void ARealPlayersRecordedPositions_DrivenThroughTheLandscape_KeepItsInvariants()
    {
        Landscape l = Make(out PhysicsWorld world, out WorldCells cells, out TerrainSource source);
        l.SetMidRadius(2);
        string path = Path.Combine(SharedDataDir.Replay.Dir!, "long-movement-run_s2c_updateposition.csv");
        int updated = 0, noCell = 0, same = 0;
        uint lastBlock = 0;
        foreach (string[] c in Csv.Rows(path))
        {
            if (c[1] != "0x5000001D")
            {
                continue;
            }

            uint cell = Convert.ToUInt32(c[3], 16);
            var origin = new Vector3(F(c[4]), F(c[5]), F(c[6]));
            var q = new Quaternion(F(c[8]), F(c[9]), F(c[10]), F(c[7]));
            var p = new Position(cell, new Frame(origin, Quaternion.Normalize(q)));
            uint block = cell & 0xFFFF0000u;
            bool far = lastBlock != 0 && (Math.Abs((int)(block >> 24) - (int)(lastBlock >> 24)) > 1
                || Math.Abs((int)((block >> 16) & 0xFF) - (int)((lastBlock >> 16) & 0xFF)) > 1);
            string before = $"{l.LoadedCellId:X8} {l.CurrentCellId:X8} {cells.Terrain.LandBlockCount} {cells.EnvCellCount}";
            LandscapeChange change = l.ChangePosition(p, blocking: far);
            switch (change.Status)
            {
                case LandscapeStatus.NoCell:
                    // A dungeon cell: the terrain-only source has no landblock infos, so the cell cannot be built.
                    Assert.True(LandDefs.IsEnvCell(cell));
                    Assert.Equal(before, $"{l.LoadedCellId:X8} {l.CurrentCellId:X8} {cells.Terrain.LandBlockCount} {cells.EnvCellCount}");
                    noCell++;
                    break;
                case LandscapeStatus.SameCell:
                    same++;
                    break;
                default:
                    Assert.False(LandDefs.IsEnvCell(cell));
                    Assert.Equal(cell, l.CurrentCellId);
                    Assert.Equal(cell, l.LoadedCellId);
                    AssertInvariants(l, cells);
                    updated++;
                    lastBlock = block;
                    break;
            }
        }

        output.WriteLine($"{updated} updates, {same} same cell, {noCell} dungeon cells, {source.BlockReads} block reads");
        // The recording visits Holtburg (0xA9B4), two dungeons and 0x9DAF: both outdoor places are built.
        Assert.True(updated >= 2);
        Assert.True(noCell >= 1);
        Assert.Equal(9, cells.Terrain.LandBlockCount);
    }

    private static float F(string s) => float.Parse(s, CultureInfo.InvariantCulture);
}
