using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Scene;
using AcDream.Core.Physics.World;
using Xunit;

namespace AcDream.Core.Tests.Scene;

/// <summary>The visiting order (ascending id, then creation order) whatever the order objects are created and removed in.</summary>
public class VisitOrderTests
{
    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void RandomOrderCreationsAndRemovals_TickVisitsInAscendingIdThenCreationOrder(bool visitEveryObject)
    {
        // 3,000 movers created in a random order of ids 1..1,500 and 1,500 of id 0 (no id: equal ids must keep creation order;
        // a non-zero id is unique in a world), ticked, 1,200 of them removed in random order, 700 more created (ids 1..3,000,
        // random; id 0 when the drawn id is in use), ticked again. Each tick must visit exactly the live objects, sorted by
        // (id, creation), as GetObject(i) lists them.
        var world = new PhysicsWorld(0.0) { VisitEveryObject = visitEveryObject };
        var observer = new OrderObserver();
        world.StepObserver = observer;
        var rnd = new Random(31);
        var live = new List<(uint Id, int Created, PhysicsObj Obj)>();
        int created = 0;
        uint[] ids = new uint[3000];
        for (int i = 0; i < ids.Length; i++)
        {
            ids[i] = i % 2 == 0 ? (uint)(1 + i / 2) : 0u;
        }

        Shuffle(rnd, ids);
        foreach (uint id in ids)
        {
            live.Add((id, created++, Mover(world, id)));
        }

        AssertTickVisits(world, observer, live);

        for (int k = 0; k < 1200; k++)
        {
            int at = rnd.Next(live.Count);
            world.RemoveObject(live[at].Obj);
            live.RemoveAt(at);
        }

        for (int k = 0; k < 700; k++)
        {
            uint id = (uint)(1 + rnd.Next(3000));
            if (world.GetObjectById(id) is not null)
            {
                id = 0;
            }

            live.Add((id, created++, Mover(world, id)));
        }

        AssertTickVisits(world, observer, live);
        Assert.Equal(2500, world.ObjectCount);
    }

    [Fact]
    public void VisitOrderList_RandomInsertsAndRemovals_MatchASortedReference_AndAWalkSurvivesChanges()
    {
        // 20,000 random operations (inserts and removals, ids 0..999 with repeats; the objects are made outside the world's
        // object table, which holds one object per non-zero id) against a sorted reference; every 1,000
        // operations the whole list is compared, by rank and by a walk. Then a walk that removes and inserts objects on both
        // sides of its place while it runs: it returns each object in the list when it gets there once, in order.
        var world = new PhysicsWorld(0.0);
        var list = new VisitOrderList();
        var reference = new SortedDictionary<UInt128, PhysicsObj>();
        var members = new List<PhysicsObj>();
        var rnd = new Random(7);
        for (int op = 0; op < 20000; op++)
        {
            if (members.Count == 0 || rnd.Next(100) < 55)
            {
                PhysicsObj o = Unregistered(world, (uint)rnd.Next(1000));
                list.Insert(o);
                reference.Add(VisitOrderList.KeyOf(o), o);
                members.Add(o);
            }
            else
            {
                int at = rnd.Next(members.Count);
                PhysicsObj o = members[at];
                Assert.True(list.Remove(o));
                Assert.False(list.Remove(o));
                reference.Remove(VisitOrderList.KeyOf(o));
                members[at] = members[^1];
                members.RemoveAt(members.Count - 1);
            }

            if (op % 1000 == 999)
            {
                AssertSame(reference, list);
            }
        }

        // A walk that, at every 10th object, removes the next object in the list and one before its place, and inserts a new
        // object with the next id after its own (which it must still reach) and one with id 0 (already passed).
        var expected = new List<PhysicsObj>(reference.Values);
        var seen = new List<PhysicsObj>();
        var removedAhead = new List<PhysicsObj>();
        var removedBehind = new List<PhysicsObj>();
        VisitOrderList.Cursor c = list.Start();
        int n = 0;
        while (list.MoveNext(ref c, out PhysicsObj o))
        {
            seen.Add(o);
            if (++n % 10 != 0)
            {
                continue;
            }

            int at = expected.IndexOf(o);
            if (at + 1 < expected.Count)
            {
                Assert.True(list.Remove(expected[at + 1]));
                removedAhead.Add(expected[at + 1]);
                expected.RemoveAt(at + 1);
            }

            if (at > 0)
            {
                Assert.True(list.Remove(expected[at - 1]));
                removedBehind.Add(expected[at - 1]);
                expected.RemoveAt(at - 1);
                at--;
            }

            PhysicsObj later = Unregistered(world, o.Id + 1); // created last: after every object of id o.Id + 1
            list.Insert(later);
            int place = at + 1;
            while (place < expected.Count && VisitOrderList.Precedes(expected[place], later))
            {
                place++;
            }

            expected.Insert(place, later);
            PhysicsObj earlier = Unregistered(world, 0);
            list.Insert(earlier);
        }

        // The walk returned, in order, each object it reached: those in the list at the end (less the id-0 ones inserted
        // behind it) and those it had passed before they were removed, never one removed before it got there.
        var expectedSeen = new List<PhysicsObj>(expected);
        expectedSeen.AddRange(removedBehind);
        expectedSeen.Sort((a, b) => VisitOrderList.KeyOf(a).CompareTo(VisitOrderList.KeyOf(b)));
        Assert.Equal(expectedSeen, seen);
        foreach (PhysicsObj o in removedAhead)
        {
            Assert.DoesNotContain(o, seen);
        }
    }

    private ulong _created;

    // An object of the world that its object table does not list (the list under test is separate), numbered in creation order.
    private PhysicsObj Unregistered(PhysicsWorld world, uint id) => new(world, id, _created++);

    private static void AssertSame(SortedDictionary<UInt128, PhysicsObj> reference, VisitOrderList list)
    {
        Assert.Equal(reference.Count, list.Count);
        int rank = 0;
        VisitOrderList.Cursor c = list.Start();
        foreach (PhysicsObj expected in reference.Values)
        {
            Assert.Same(expected, list.At(rank++));
            Assert.True(list.MoveNext(ref c, out PhysicsObj walked));
            Assert.Same(expected, walked);
        }

        Assert.False(list.MoveNext(ref c, out _));
    }

    private static void AssertTickVisits(PhysicsWorld world, OrderObserver observer, List<(uint Id, int Created, PhysicsObj Obj)> live)
    {
        var sorted = new List<(uint Id, int Created, PhysicsObj Obj)>(live);
        sorted.Sort((a, b) => a.Id != b.Id ? a.Id.CompareTo(b.Id) : a.Created.CompareTo(b.Created));
        observer.Visited.Clear();
        world.Tick(world.CurrentTime + 0.034);
        Assert.Equal(sorted.Count, observer.Visited.Count);
        for (int i = 0; i < sorted.Count; i++)
        {
            Assert.Same(sorted[i].Obj, observer.Visited[i]);
            Assert.Same(sorted[i].Obj, world.GetObject(i));
        }
    }

    private static void Shuffle(Random rnd, uint[] a)
    {
        for (int i = a.Length - 1; i > 0; i--)
        {
            int j = rnd.Next(i + 1);
            (a[i], a[j]) = (a[j], a[i]);
        }
    }

    private static PhysicsObj Mover(PhysicsWorld world, uint id)
    {
        PhysicsObj o = world.CreateObject(id);
        o.PartArray = new SimplePartArray(numParts: 1, numSpheres: 1);
        o.EnterWorld(new Position(0xA9B40001u, new Vector3(10f + (id % 100) * 0.5f, 10f + (id % 97) * 0.5f, 50f)));
        o.SetState(o.State & ~PhysicsState.Gravity);
        o.CalcAcceleration();
        o.SetVelocity(new Vector3(1f, 0f, 0f));
        return o;
    }

    private sealed class OrderObserver : IStepObserver
    {
        public readonly List<PhysicsObj> Visited = new();

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime) => Visited.Add(obj);
    }
}
