using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// A parent that is the object itself or one of its descendants would make a cycle in the child lists, and
/// <c>UpdateChildrenInternal</c>, <c>SetFrame</c>, <c>LeaveCell</c> and <c>EnterCell</c> would then recurse without end (a stack
/// overflow no caller can catch). <see cref="PhysicsObj.SetParent"/> refuses it with an <see cref="ArgumentException"/> and
/// leaves every object as it was (retail does not check: docs/divergences.md, "Parent cycles refused").
/// </summary>
public class ParentCycleRefusedTests
{
    private static readonly Frame Offset = Frame.FromHeading(new Vector3(0f, 0f, 1f), 0f);

    private static PhysicsObj Placed(PhysicsWorld world, uint id, float x)
    {
        PhysicsObj o = world.CreateObject(id);
        o.PartArray = new SimplePartArray(numParts: 1, numSpheres: 1);
        Assert.True(o.EnterWorld(new Position(TickTestContext.OutdoorCell, new Vector3(x, 10f, 0f))));
        return o;
    }

    // What a refusal must leave as it was: parent, child lists, cell and frame of every object of the chain.
    private static string State(params PhysicsObj[] objs)
    {
        var sb = new System.Text.StringBuilder();
        foreach (PhysicsObj o in objs)
        {
            sb.Append(o.Id).Append(':').Append(o.Parent?.Id.ToString() ?? "-").Append('/')
              .Append(o.Children?.Count ?? -1).Append('/').Append(o.CellId.ToString("X8")).Append('/')
              .Append(o.Position.Frame.Origin.ToString()).Append(';');
        }

        return sb.ToString();
    }

    [Fact]
    public void TwoCycle_ParentOfMyParent_IsRefused_StateUnchanged()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = Placed(world, 1, 5f);
        PhysicsObj b = Placed(world, 2, 8f);
        Assert.True(b.SetParent(a, 0, Offset));
        string before = State(a, b);

        Assert.Throws<ArgumentException>(() => a.SetParent(b, 0, Offset));

        Assert.Equal(before, State(a, b));
        Assert.Same(a, b.Parent);
        Assert.Null(a.Parent);
        // The scene still ticks: no recursion through the child lists.
        world.Tick(0.05);
        a.SetFrame(Frame.FromHeading(new Vector3(6f, 10f, 0f), 0f));
        // b follows a at Offset: (6, 10, 0) + (0, 0, 1).
        Assert.Equal(new Vector3(6f, 10f, 1f), b.Position.Frame.Origin);
    }

    [Fact]
    public void ThreeCycle_IsRefused_StateUnchanged()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = Placed(world, 1, 5f);
        PhysicsObj b = Placed(world, 2, 8f);
        PhysicsObj c = Placed(world, 3, 11f);
        Assert.True(b.SetParent(a, 0, Offset));
        Assert.True(c.SetParent(b, 0, Offset));
        string before = State(a, b, c);

        Assert.Throws<ArgumentException>(() => a.SetParent(c, 0, Offset));

        Assert.Equal(before, State(a, b, c));
        world.Tick(0.05);
    }

    [Fact]
    public void ChildOfItsOwnChild_IsRefused_StateUnchanged()
    {
        var world = new PhysicsWorld();
        PhysicsObj a = Placed(world, 1, 5f);
        PhysicsObj b = Placed(world, 2, 8f);
        Assert.True(b.SetParent(a, 0, Offset));
        string before = State(a, b);

        // a's own child b as a's parent is the 2-cycle; b (the child) re-attached to itself is the trivial one.
        Assert.Throws<ArgumentException>(() => a.SetParent(b, 3, Frame.Identity));
        Assert.Throws<ArgumentException>(() => b.SetParent(b, 0, Offset));

        Assert.Equal(before, State(a, b));
    }

    [Fact]
    public void Cycle_AmongObjectsWithNoCell_IsRefused()
    {
        // Without cells nothing recurses at once (leave_cell returns early), so only the check can refuse it.
        var world = new PhysicsWorld();
        PhysicsObj a = world.CreateObject(1);
        PhysicsObj b = world.CreateObject(2);
        PhysicsObj c = world.CreateObject(3);
        Assert.True(b.SetParent(a, 0, Offset));
        Assert.True(c.SetParent(b, 0, Offset));
        string before = State(a, b, c);

        Assert.Throws<ArgumentException>(() => a.SetParent(c, 0, Offset));
        Assert.Throws<ArgumentException>(() => a.SetParent(b, 0, Offset));

        Assert.Equal(before, State(a, b, c));
    }

    [Fact]
    public void ReparentingWithinATree_WithoutACycle_IsAccepted()
    {
        // c hangs from b, b from a: c may move up to a (a is an ancestor, not a descendant), and b to a sibling d.
        var world = new PhysicsWorld();
        PhysicsObj a = world.CreateObject(1);
        PhysicsObj b = world.CreateObject(2);
        PhysicsObj c = world.CreateObject(3);
        PhysicsObj d = world.CreateObject(4);
        Assert.True(b.SetParent(a, 0, Offset));
        Assert.True(c.SetParent(b, 0, Offset));

        Assert.True(c.SetParent(a, 0, Offset));
        Assert.True(b.SetParent(d, 0, Offset));

        Assert.Same(a, c.Parent);
        Assert.Same(d, b.Parent);
        Assert.Equal(0, b.Children!.Count);
        Assert.Equal(1, a.Children!.Count);
    }
}
