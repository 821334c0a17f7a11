using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class TransitionRetailTests
{
    private sealed class NoCells : ICellSource
    {
        public ObjCell? GetVisible(uint cellId) => null;
    }

    private const uint Cell = 0x80800001;

    // A transition with one sphere of radius r resting on the origin (centre (0, 0, r)), scale 1.
    private static Transition Make(float radius = 0.5f)
    {
        var pool = new TransitionPool(new NoCells());
        Transition t = pool.Make()!;
        t.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, radius), radius) }, 1f);
        return t;
    }

    private static Position At(float x, float y, float z) => new(Cell, new Vector3(x, y, z));

    // ---- pool ------------------------------------------------------------------------------------------------------

    [Fact]
    public void Pool_HandsOutTenTransitions_TheEleventhFails()
    {
        var pool = new TransitionPool(new NoCells());
        var seen = new Transition[TransitionPool.Capacity];
        for (int i = 0; i < TransitionPool.Capacity; i++)
        {
            seen[i] = pool.Make()!;
            Assert.NotNull(seen[i]);
            Assert.Equal(i + 1, pool.Level);
        }

        Assert.Null(pool.Make());
        Assert.Equal(10, pool.Level);
        Assert.Equal(10, new System.Collections.Generic.HashSet<Transition>(seen).Count);
        pool.Cleanup();
        Assert.Same(seen[9], pool.Make());
    }

    [Fact]
    public void Pool_CleanupWithNothingInUse_Throws()
    {
        var pool = new TransitionPool(new NoCells());
        Assert.Throws<InvalidOperationException>(pool.Cleanup);
        Assert.Equal(0, pool.Level);
    }

    // ---- init_sphere ---------------------------------------------------------------------------------------------

    [Fact]
    public void InitSphere_ScalesAndKeepsAtMostTwo_LowPointUnderTheFirst()
    {
        Transition t = Make();
        var spheres = new[]
        {
            new Sphere(new Vector3(0f, 0.5f, 1f), 0.5f),
            new Sphere(new Vector3(0f, 0f, 2f), 0.25f),
            new Sphere(new Vector3(9f, 9f, 9f), 9f),
        };
        t.InitSphere(spheres, 2f);
        // Scale 2: (0, 1, 2) r 1 and (0, 0, 4) r 0.5; the third is dropped; low point (0, 1, 2 - 1) = (0, 1, 1).
        Assert.Equal(2, t.SpherePath.NumSphere);
        Assert.Equal(new Sphere(new Vector3(0f, 1f, 2f), 1f), t.SpherePath.LocalSphere[0]);
        Assert.Equal(new Sphere(new Vector3(0f, 0f, 4f), 0.5f), t.SpherePath.LocalSphere[1]);
        Assert.Equal(new Vector3(0f, 1f, 1f), t.SpherePath.LocalLowPoint);
    }

    // ---- calc_num_steps ------------------------------------------------------------------------------------------

    [Theory]
    // ceil(|offset| / r) steps of offset / n, no cap (ACE caps at 1000).
    [InlineData(1.0f, 0.5f, 2u)] // 1.0 / 0.5 = 2
    [InlineData(1.2f, 0.5f, 3u)] // 2.4 -> 3
    [InlineData(0.3f, 0.5f, 1u)] // below one radius: one step of the whole offset
    [InlineData(0.0f, 0.5f, 0u)] // no movement: no step
    [InlineData(500f, 0.1f, 5000u)] // 5000 steps: more than ACE's cap of 1000
    public void CalcNumSteps_CeilOfDistanceOverRadius(float dx, float radius, uint expected)
    {
        Transition t = Make(radius);
        t.InitPath(null, At(10f, 10f, 0f), At(10f + dx, 10f, 0f));
        t.CalcNumSteps(out Vector3 offset, out Vector3 perStep, out uint n);
        Assert.Equal(expected, n);
        Assert.Equal(dx, offset.X, 3);
        if (n > 0)
        {
            Assert.Equal(dx / n, perStep.X, 4);
        }
    }

    [Fact]
    public void CalcNumSteps_Viewer_FloorPlusOne()
    {
        Transition t = Make(0.5f);
        t.ObjectInfo.State = ObjectInfoState.IsViewer;
        t.InitPath(null, At(10f, 10f, 0f), At(11.2f, 10f, 0f));
        // 1.2 / 0.5 = 2.4: floor + 1 = 3 steps of one radius each (offset * (1 / 2.4) = 0.5).
        t.CalcNumSteps(out _, out Vector3 perStep, out uint n);
        Assert.Equal(3u, n);
        Assert.Equal(0.5f, perStep.X, 5);
    }

    [Fact]
    public void CalcNumSteps_AcrossLandblocks_UsesTheBlockOffset()
    {
        Transition t = Make(0.5f);
        // From x = 191 in block 0x8080 to x = 1 in block 0x8180 (24 * 8 = 192 m east): offset 2 m.
        t.InitPath(null, At(191f, 10f, 0f), new Position(0x81800001, new Vector3(1f, 10f, 0f)));
        t.CalcNumSteps(out Vector3 offset, out _, out uint n);
        Assert.Equal(2f, offset.X);
        Assert.Equal(4u, n);
    }

    // ---- the negligible-step compare (ambiguity, docs/divergences.md) --------------------------------------------

    [Fact]
    public void IsNegligibleOffset_ThresholdIsEpsilonOnTheLength()
    {
        // |offset|² < EPSILON²: 0.99 EPSILON is negligible, 1.01 EPSILON is not; a 1 cm step (|offset|² = 1e-4 < EPSILON)
        // is a real step, which rules out the other reading |offset|² < EPSILON.
        Assert.True(Transition.IsNegligibleOffset(new Vector3(0.99f * PhysicsGlobals.Epsilon, 0f, 0f)));
        Assert.False(Transition.IsNegligibleOffset(new Vector3(1.01f * PhysicsGlobals.Epsilon, 0f, 0f)));
        Assert.False(Transition.IsNegligibleOffset(new Vector3(0.01f, 0f, 0f)));
        Assert.True(Transition.IsNegligibleOffset(Vector3.Zero));
    }

    // ---- adjust_offset -------------------------------------------------------------------------------------------

    [Fact]
    public void AdjustOffset_NoContactNoSliding_Unchanged()
    {
        Transition t = Make();
        Assert.Equal(new Vector3(1f, 2f, 3f), t.AdjustOffset(new Vector3(1f, 2f, 3f)));
    }

    [Fact]
    public void AdjustOffset_IntoSlidingNormal_KeepsOnlyTheAlongWallPart()
    {
        Transition t = Make();
        t.CollisionInfo.SetSlidingNormal(new Vector3(1f, 0f, 0f));
        // (-1, 1, 0)·(1, 0, 0) = -1 < 0: offset - s (offset·s) = (-1, 1, 0) + (1, 0, 0) = (0, 1, 0).
        Assert.Equal(new Vector3(0f, 1f, 0f), t.AdjustOffset(new Vector3(-1f, 1f, 0f)));
        Assert.True(t.CollisionInfo.SlidingNormalValid);
    }

    [Fact]
    public void AdjustOffset_AwayFromSlidingNormal_DropsIt()
    {
        Transition t = Make();
        t.CollisionInfo.SetSlidingNormal(new Vector3(1f, 0f, 0f));
        Assert.Equal(new Vector3(1f, 1f, 0f), t.AdjustOffset(new Vector3(1f, 1f, 0f)));
        Assert.False(t.CollisionInfo.SlidingNormalValid);
    }

    [Fact]
    public void AdjustOffset_IntoFlatContactPlane_ProjectsOntoIt()
    {
        Transition t = Make();
        t.CollisionInfo.SetContactPlane(new CollisionPlane(new Vector3(0f, 0f, 1f), 0f), false);
        // offset·N = -3 <= 0: offset - N (offset·N) = (1, 2, 0). (Contact cell id 0: no lift test.)
        Assert.Equal(new Vector3(1f, 2f, 0f), t.AdjustOffset(new Vector3(1f, 2f, -3f)));
    }

    [Fact]
    public void AdjustOffset_UphillOnATiltedPlane_Projects_DownhillSnapsAlongZ()
    {
        Transition t = Make();
        // N = (-0.6, 0, 0.8): ground rising towards +x with slope 0.75.
        t.CollisionInfo.SetContactPlane(new CollisionPlane(new Vector3(-0.6f, 0f, 0.8f), 0f), false);
        // Uphill (1,0,0): offset·N = -0.6 -> (1,0,0) - N(-0.6) = (1 - 0.36, 0, 0.48) = (0.64, 0, 0.48).
        Vector3 up = t.AdjustOffset(new Vector3(1f, 0f, 0f));
        Assert.Equal(0.64f, up.X, 6);
        Assert.Equal(0f, up.Y);
        Assert.Equal(0.48f, up.Z, 6);
        // Downhill (-1,0,0): offset·N = 0.6 > 0 -> snap_to_plane: z = -(N.x x + N.y y) / N.z = -(0.6) / 0.8 = -0.75.
        Vector3 down = t.AdjustOffset(new Vector3(-1f, 0f, 0f));
        Assert.Equal(new Vector3(-1f, 0f, -0.75f), down);
    }

    [Fact]
    public void AdjustOffset_SlidingOnContactPlane_FollowsTheCrease()
    {
        Transition t = Make();
        t.CollisionInfo.SetContactPlane(new CollisionPlane(new Vector3(0f, 0f, 1f), 0f), false);
        t.CollisionInfo.SetSlidingNormal(new Vector3(1f, 0f, 0f));
        // crease = (s.z N.y - s.y N.z, s.x N.z - s.z N.x, s.y N.x - s.x N.y) = (0, 1, 0); offset (-1, 2, 5) -> crease * 2.
        Assert.Equal(new Vector3(0f, 2f, 0f), t.AdjustOffset(new Vector3(-1f, 2f, 5f)));
    }

    [Fact]
    public void AdjustOffset_SphereSunkIntoContactPlane_LiftsTheCheckPositionNotTheOffset()
    {
        Transition t = Make(0.5f);
        t.InitPath(null, At(10f, 10f, 19.8f), At(10f, 10f, 19.8f));
        t.SpherePath.SetCheckPos(At(10f, 10f, 19.8f), null);
        t.CollisionInfo.SetContactPlane(new CollisionPlane(new Vector3(0f, 0f, 1f), -20f), false);
        t.CollisionInfo.ContactPlaneCellId = Cell;
        // Centre z = 20.3: distance 0.3 < r - EPSILON = 0.4998 -> lift (0.5 - 0.3) / 1 = 0.2 (less than r): origin 19.8 -> 20.
        Vector3 result = t.AdjustOffset(new Vector3(1f, 0f, 0f));
        Assert.Equal(new Vector3(1f, 0f, 0f), result);
        Assert.Equal(20f, t.SpherePath.CheckPos.Frame.Origin.Z, 5);
        Assert.Equal(20.5f, t.SpherePath.GlobalSphere[0].Center.Z, 5);
    }

    // ---- slide_sphere, cliff_slide --------------------------------------------------------------------------------

    private static Transition Moving(Vector3 from, Vector3 to)
    {
        Transition t = Make(0.5f);
        t.InitPath(null, At(from.X, from.Y, from.Z), At(from.X, from.Y, from.Z));
        t.SpherePath.SetCheckPos(At(to.X, to.Y, to.Z), null);
        return t;
    }

    [Fact]
    public void SlideSphere_AlongAWall_KeepsTheMovementAlongTheCrease()
    {
        // Moving (-1, 1, 0) from (10,10,0) into a wall of normal (1, 0, 0), standing on a flat plane.
        Transition t = Moving(new Vector3(10f, 10f, 0f), new Vector3(9f, 11f, 0f));
        t.CollisionInfo.SetContactPlane(new CollisionPlane(new Vector3(0f, 0f, 1f), 0f), false);
        var n = new Vector3(1f, 0f, 0f);
        SpherePath path = t.SpherePath;
        // dir = n x N = (n.y N.z - n.z N.y, N.x n.z - N.z n.x, N.y n.x - N.x n.y) = (0, -1, 0); movement m = (-1, 1, 0);
        // projection = dir (dir·m) / |dir|² = (0, 1, 0); the check moves by projection - m = (1, 0, 0): to (10, 11, 0).
        TransitionState ts = path.GlobalSphere[0].SlideSphere(path, t.CollisionInfo, ref n, path.GlobalCurrCenter[0]);
        Assert.Equal(TransitionState.Slid, ts);
        Assert.Equal(new Vector3(10f, 11f, 0f), path.CheckPos.Frame.Origin);
        Assert.Equal(new Vector3(1f, 0f, 0f), t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void SlideSphere_ZeroNormal_GoesHalfwayBack()
    {
        Transition t = Moving(new Vector3(10f, 10f, 0f), new Vector3(12f, 10f, 0f));
        var n = Vector3.Zero;
        SpherePath path = t.SpherePath;
        Assert.Equal(TransitionState.Adjusted, path.GlobalSphere[0].SlideSphere(path, t.CollisionInfo, ref n, path.GlobalCurrCenter[0]));
        Assert.Equal(new Vector3(11f, 10f, 0f), path.CheckPos.Frame.Origin);
    }

    [Fact]
    public void SlideSphere_HeadOnIntoAWallFacingUp_Collides()
    {
        // Normal parallel to the contact normal and opposed: (0,0,-1) against N = (0,0,1): dir = 0 and n·N = -1 < 0.
        // Retail reverses the movement into the normal: -(m) = -(0, 0, 1) normalised = (0, 0, -1).
        Transition t = Moving(new Vector3(10f, 10f, 0f), new Vector3(10f, 10f, 1f));
        t.CollisionInfo.SetContactPlane(new CollisionPlane(new Vector3(0f, 0f, 1f), 0f), false);
        var n = new Vector3(0f, 0f, -1f);
        SpherePath path = t.SpherePath;
        Assert.Equal(TransitionState.Collided, path.GlobalSphere[0].SlideSphere(path, t.CollisionInfo, ref n, path.GlobalCurrCenter[0]));
        Assert.Equal(new Vector3(0f, 0f, -1f), n);
    }

    [Fact]
    public void CliffSlide_MovesAlongTheHorizontalCreaseNormal_AsRetailComputesIt()
    {
        // Last known plane flat, new contact plane N = (-0.6, 0, 0.8) (rising towards +x). Retail's normal:
        // x = v5 - v4, y = v3 - v5, z = 0 with v3 = c.y lk.z - c.z lk.y = 0, v4 = lk.x c.z - lk.z c.x = 0.6, v5 = 0
        // -> (-0.6, 0, 0), normalised (-1, 0, 0). Movement m = (1, 0, 0); m·n = -1 <= 0 -> offset n (m·n) = (1, 0, 0)
        // and the collision normal n.
        Transition t = Moving(new Vector3(10f, 10f, 0f), new Vector3(11f, 10f, 0f));
        t.CollisionInfo.LastKnownContactPlane = new CollisionPlane(new Vector3(0f, 0f, 1f), 0f);
        TransitionState ts = t.CliffSlide(new CollisionPlane(new Vector3(-0.6f, 0f, 0.8f), 0f));
        Assert.Equal(TransitionState.Adjusted, ts);
        Assert.Equal(new Vector3(12f, 10f, 0f), t.SpherePath.CheckPos.Frame.Origin);
        Assert.Equal(new Vector3(-1f, 0f, 0f), t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void CliffSlide_ParallelPlanes_Ok()
    {
        Transition t = Moving(new Vector3(10f, 10f, 0f), new Vector3(11f, 10f, 0f));
        t.CollisionInfo.LastKnownContactPlane = new CollisionPlane(new Vector3(0f, 0f, 1f), 0f);
        Assert.Equal(TransitionState.Ok, t.CliffSlide(new CollisionPlane(new Vector3(0f, 0f, 1f), -3f)));
    }

    // ---- validate_walkable -----------------------------------------------------------------------------------------

    private static readonly CollisionPlane Ground = new(new Vector3(0f, 0f, 1f), -20f);

    [Fact]
    public void ValidateWalkable_Touching_SetsContactPlane()
    {
        Transition t = Moving(new Vector3(10f, 10f, 20f), new Vector3(10f, 10f, 20f));
        var s = new Sphere(new Vector3(10f, 10f, 20.5f), 0.5f);
        // low point z 20: distance 0 within EPSILON.
        Assert.Equal(TransitionState.Ok, t.ObjectInfo.ValidateWalkable(s, Ground, false, 0f, t.SpherePath, t.CollisionInfo, Cell));
        Assert.True(t.CollisionInfo.ContactPlaneValid);
        Assert.Equal(Cell, t.CollisionInfo.ContactPlaneCellId);
        // Not in contact before (landing): the environment collision is recorded.
        Assert.True(t.CollisionInfo.CollidedWithEnvironment);
        Assert.Equal(new Vector3(0f, 0f, 1f), t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void ValidateWalkable_Sunk_LiftsTheCheckPosition()
    {
        Transition t = Moving(new Vector3(10f, 10f, 19.7f), new Vector3(10f, 10f, 19.7f));
        t.ObjectInfo.State = ObjectInfoState.Contact | ObjectInfoState.OnWalkable;
        var s = new Sphere(new Vector3(10f, 10f, 20.2f), 0.5f);
        // low point 19.7: distance -0.3; dz = -0.3 / 1: the check moves up 0.3. In contact already: no collision normal.
        Assert.Equal(TransitionState.Adjusted, t.ObjectInfo.ValidateWalkable(s, Ground, false, 0f, t.SpherePath, t.CollisionInfo, Cell));
        Assert.Equal(20f, t.SpherePath.CheckPos.Frame.Origin.Z, 5);
        Assert.False(t.CollisionInfo.CollisionNormalValid);
    }

    [Fact]
    public void ValidateWalkable_SteepWhileWalking_NeitherContactNorPush()
    {
        Transition t = Moving(new Vector3(10f, 10f, 19.7f), new Vector3(10f, 10f, 19.7f));
        t.ObjectInfo.State = ObjectInfoState.Contact | ObjectInfoState.OnWalkable;
        // N.z = 0.6 < floor_z: a walker may not stand on it, and the terrain test does not push it out either.
        var steep = new CollisionPlane(new Vector3(0.8f, 0f, 0.6f), -12f - 8f);
        var s = new Sphere(new Vector3(0f, 10f, 20.2f), 0.5f);
        Assert.Equal(TransitionState.Ok, t.ObjectInfo.ValidateWalkable(s, steep, false, 0f, t.SpherePath, t.CollisionInfo, Cell));
        Assert.False(t.CollisionInfo.ContactPlaneValid);
        Assert.Equal(19.7f, t.SpherePath.CheckPos.Frame.Origin.Z);
    }

    [Fact]
    public void ValidateWalkable_DuringAWalkableProbe_SunkIsCollided()
    {
        Transition t = Moving(new Vector3(10f, 10f, 19.7f), new Vector3(10f, 10f, 19.7f));
        t.SpherePath.CheckWalkable = true;
        var s = new Sphere(new Vector3(10f, 10f, 20.2f), 0.5f);
        Assert.Equal(TransitionState.Collided, t.ObjectInfo.ValidateWalkable(s, Ground, false, 0f, t.SpherePath, t.CollisionInfo, Cell));
    }

    [Theory]
    // step_down_amt 0.6, walk_interp 1: interp = (1 - (-1 / 0.6) dz) * 1 with dz = distance.
    [InlineData(-0.3f, true, 0.5f)] // 1 - 0.5 = 0.5: accepted, walk_interp 0.5
    [InlineData(-0.9f, false, 1f)] // 1 - 1.5 = -0.5 < -0.1: refused
    public void ValidateWalkable_StepDown_TracksWalkInterp(float distance, bool accepted, float interp)
    {
        Transition t = Moving(new Vector3(10f, 10f, 20f + distance), new Vector3(10f, 10f, 20f + distance));
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.6f;
        t.SpherePath.WalkInterp = 1f;
        var s = new Sphere(new Vector3(10f, 10f, 20.5f + distance), 0.5f);
        TransitionState ts = t.ObjectInfo.ValidateWalkable(s, Ground, false, 0f, t.SpherePath, t.CollisionInfo, Cell);
        Assert.Equal(accepted ? TransitionState.Adjusted : TransitionState.Collided, ts);
        Assert.Equal(interp, t.SpherePath.WalkInterp, 5);
    }

    [Fact]
    public void ValidateWalkable_WaterDepth_LowersTheRestingHeight()
    {
        // Depth 0.45 added to the low point's distance: touching 0.45 below the surface counts as resting (distance 0).
        Transition t = Moving(new Vector3(10f, 10f, 19.55f), new Vector3(10f, 10f, 19.55f));
        var s = new Sphere(new Vector3(10f, 10f, 20.05f), 0.5f);
        Assert.Equal(TransitionState.Ok, t.ObjectInfo.ValidateWalkable(s, Ground, true, 0.45f, t.SpherePath, t.CollisionInfo, Cell));
        Assert.True(t.CollisionInfo.ContactPlaneValid);
        Assert.True(t.CollisionInfo.ContactPlaneIsWater);
    }
}
