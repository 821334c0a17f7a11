using System;
using System.Linq;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.LandscapeEntries;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>Bad input to the landscape: a clear error or a documented result, and the world as it was; a data source that
/// answers garbage mid-stream changes nothing, and the next change can succeed.</summary>
public class LandscapeMisuseTests
{
    private static string Snapshot(Landscape l, PhysicsWorld w, WorldCells c) =>
        $"{l.LoadedCellId:X8} {l.CurrentCellId:X8} {c.Terrain.LandBlockCount} {w.ObjectCount} "
        + string.Join(",", l.Blocks.Select(b => $"{b.BlockId:X8}:{b.Size}:{b.World is not null}"));

    [Theory]
    [InlineData(0x80800000u)]   // cell 0 of a block
    [InlineData(0x80800041u)]   // past the 64 outdoor cells
    [InlineData(0xFF000001u)]   // past the world's 255 blocks
    public void AnInvalidCellId_IsAnArgumentException_AndNothingChanges(uint cellId)
    {
        Landscape l = Landscape(Source(), out PhysicsWorld w, out WorldCells c);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        var before = Snapshot(l, w, c);
        Assert.Throws<ArgumentException>(() => l.ChangePosition(new Position(cellId, new Frame(new Vector3(10f, 10f, 20f), Quaternion.Identity))));
        Assert.Equal(before, Snapshot(l, w, c));
    }

    [Fact]
    public void APositionOutsideItsDomain_IsAnArgumentException()
    {
        Landscape l = Landscape(Source(), out _, out _);
        Assert.Throws<ArgumentException>(() => l.ChangePosition(new Position(Cell(0x80, 0x80, 10f, 10f),
            new Frame(new Vector3(float.NaN, 10f, 20f), Quaternion.Identity))));
        Assert.False(l.HasGrid);
    }

    [Fact]
    public void ACellOfABlockTheSourceLacks_IsNoCell_AndNothingChanges()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld w, out WorldCells c);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        var before = Snapshot(l, w, c);
        Assert.Equal(LandscapeStatus.NoCell, l.ChangePosition(At(0x20, 0x20, 100f, 100f)).Status);
        Assert.Equal(before, Snapshot(l, w, c));
    }

    [Fact]
    public void GarbageMidStream_ChangesNothing_AndTheNextChangeSucceeds()
    {
        DictionarySource s = Source();
        Landscape l = Landscape(s, out PhysicsWorld w, out WorldCells c);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        var before = Snapshot(l, w, c);
        // Moving one block east reads column 0x84 (the grid's new edge) and builds block 0x82 at full detail.
        byte[] good = s.Entries[BlockId(0x84, 0x80)];
        s.Entries[BlockId(0x84, 0x80)] = good.AsSpan(0, 20).ToArray();
        Assert.Throws<RetailDataFormatException>(() => l.ChangePosition(At(0x81, 0x80, 100f, 100f)));
        Assert.Equal(before, Snapshot(l, w, c));

        byte[] goodInfo = s.Entries[0x8280FFFEu];
        s.Entries[BlockId(0x84, 0x80)] = good;
        s.Entries[0x8280FFFEu] = goodInfo.AsSpan(0, 10).ToArray();
        Assert.Throws<RetailDataFormatException>(() => l.ChangePosition(At(0x81, 0x80, 100f, 100f)));
        Assert.Equal(before, Snapshot(l, w, c));

        s.Entries[0x8280FFFEu] = goodInfo;
        Assert.Equal(LandscapeStatus.Updated, l.ChangePosition(At(0x81, 0x80, 100f, 100f)).Status);
        Assert.Equal(Cell(0x81, 0x80, 100f, 100f), l.LoadedCellId);
        Assert.Equal(9, c.Terrain.LandBlockCount);
    }

    [Fact]
    public void ADataSourceThatThrows_ChangesNothing()
    {
        DictionarySource s = Source();
        Landscape l = Landscape(new ThrowingSource(s, BlockId(0x80, 0x84)), out PhysicsWorld w, out WorldCells c);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        var before = Snapshot(l, w, c);
        Assert.Throws<InvalidOperationException>(() => l.ChangePosition(At(0x80, 0x81, 100f, 100f)));
        Assert.Equal(before, Snapshot(l, w, c));
    }

    [Fact]
    public void SetMidRadius_OutOfRange_Throws_AndWithAGrid_IsRefused()
    {
        Landscape l = Landscape(Source(), out _, out _);
        Assert.Throws<ArgumentOutOfRangeException>(() => l.SetMidRadius(0));
        Assert.Throws<ArgumentOutOfRangeException>(() => l.SetMidRadius(AcDream.Core.Physics.WorldData.Landscape.MaxMidRadius + 1));
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        Assert.False(l.SetMidRadius(4));
        Assert.Equal(3, l.MidRadius);
    }

    [Fact]
    public void ChangePosition_FromInsideATick_IsRefused()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld w, out _);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        Exception? caught = null;
        w.StepObserver = new CallbackObserver(() => caught ??= Record.Exception(() => l.ChangePosition(At(0x81, 0x80, 100f, 100f))));
        SweepScene.Walker(w, At(0x80, 0x80, 100f, 100f));
        w.Tick(w.CurrentTime + 0.05);
        Assert.IsType<InvalidOperationException>(caught);
        Assert.Equal(Cell(0x80, 0x80, 100f, 100f), l.LoadedCellId);
    }

    private sealed class CallbackObserver(Action onStep) : IStepObserver
    {
        public void OnStep(AcDream.Core.Physics.Objects.PhysicsObj obj, float quantum, double physicsTime) => onStep();

        public void PlayerPhysicsUpdated(AcDream.Core.Physics.Objects.PhysicsObj player)
        {
        }
    }

    // A source that throws when asked for one id (after the first change, which does not ask for it).
    private sealed class ThrowingSource(DictionarySource inner, uint failing) : AcDream.Core.Physics.Data.IRetailDataSource
    {
        public bool TryGetEntry(uint id, out ReadOnlyMemory<byte> bytes) =>
            id == failing ? throw new InvalidOperationException("disk error") : inner.TryGetEntry(id, out bytes);
    }
}
