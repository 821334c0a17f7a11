using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.WorldData;

namespace AcDream.Samples.FirstScene;

/// <summary>What the scene must show (checked at the end, so that CI's smoke run fails when the recipe breaks): the player
/// walked and ran, jumped, reached the hut's wall without entering it, the creature followed its reports, the fade
/// finished, the chaser reached the player and the player turned to face it.</summary>
internal sealed class SceneCheck
{
    private Vector3 _start;
    private bool _started;
    private float _path;
    private Vector3 _last;
    private float _jumpHeight;
    private float _closestToHut = float.MaxValue;
    private bool _airborne;
    private bool _atWall;

    /// <summary>Records the player after a frame.</summary>
    public void Observe(TerrainWorld terrain, PhysicsObj player, double now)
    {
        Vector3 o = player.Position.Frame.Origin;
        if (!_started)
        {
            _start = o;
            _last = o;
            _started = true;
        }

        _path += Vector2.Distance(new Vector2(o.X, o.Y), new Vector2(_last.X, _last.Y));
        _last = o;
        bool airborne = (player.TransientState & TransientState.Contact) == 0;
        if (airborne != _airborne)
        {
            Console.WriteLine($"{now,6:F2}  {(airborne ? "left the ground" : "landed")} at ({o.X:F2}, {o.Y:F2}, {o.Z:F2})");
            _airborne = airborne;
        }

        if (airborne && terrain.TryGetTerrainHeight(player.Position, out float g))
        {
            _jumpHeight = MathF.Max(_jumpHeight, o.Z - g);
        }

        if (now > 13.5)
        {
            float d = Scene.DistanceToHut(o);
            _closestToHut = MathF.Min(_closestToHut, d);
            bool atWall = d < SetupPhysicsRadius + 0.1f;
            if (atWall != _atWall)
            {
                Console.WriteLine($"{now,6:F2}  {(atWall ? "reached the hut's wall, sliding along it" : "past the hut's corner")} at ({o.X:F2}, {o.Y:F2})");
                _atWall = atWall;
            }
        }
    }

    /// <summary>Prints the summary; 0 when every expectation holds, else 1.</summary>
    public int Report(RemoteCreature remote, Chaser chaser, double now)
    {
        // Walk 4 s at 3.12 and 2 s turning (18.7 m), run 4 s at 6 (24 m), the jump (about 9 m), then 8.5 s of walking (26.5 m).
        bool walked = _path > 60f;
        // 4 m/s up under 9.8 m/s²: 0.82 m of free flight after a first step of 4/30 m: about 0.95 m over level ground (more
        // where the ground falls away under the jump).
        bool jumped = _jumpHeight is > 0.5f and < 1.5f;
        // The feet sphere (radius 0.48) stays where its last collision-free step ended and slides from there: the origin keeps
        // between 0.48 m and 0.48 m plus one step's approach from the wall (3.12 m/s x cos 25.5° x 1/30 s = 0.094 m at this
        // walk and frame rate; Behavior/WallStopDistanceTests), never inside.
        float radius = SetupPhysicsRadius;
        bool hut = _closestToHut > radius - 0.05f && _closestToHut < radius + 0.1f;
        float error = remote.ErrorAt(now);
        bool followed = remote.Reports > 100 && error < 1.5f;
        bool fadeDone = remote.Obj is not null && remote.Obj.Translucency == 1f;
        Console.WriteLine();
        Console.WriteLine($"path {_path:F1} m (start {_start.X:F1}, {_start.Y:F1}): {(walked ? "ok" : "FAIL")}");
        Console.WriteLine($"jump height {_jumpHeight:F2} m: {(jumped ? "ok" : "FAIL")}");
        Console.WriteLine($"closest to the hut wall {_closestToHut:F2} m (feet radius {radius:F2}): {(hut ? "ok, slid along it" : "FAIL")}");
        Console.WriteLine($"creature: {remote.Reports} reports, {error:F2} m from the server's position: {(followed ? "ok" : "FAIL")}");
        Console.WriteLine($"fade finished: {(fadeDone ? "ok" : "FAIL")}");
        // The move-to ends 0.6 m (distance_to_object) from the player's cylinder, both radius 0.48: centres about 1.56 m apart,
        // plus at most one run step's overshoot check; 2.2 m allows a step of the player walking away meanwhile.
        bool chased = chaser.Arrived && chaser.Distance < 2.2f;
        Console.WriteLine($"chaser: arrived {chaser.Distance:F2} m from the player: {(chased ? "ok" : "FAIL")}");
        // TurnToObject ends facing the target (the heading within the turn's last step, 1.5 rad/s x 1/30 s = 2.9 degrees).
        bool faced = chaser.PlayerFacingError < 5.0;
        Console.WriteLine($"player faces the chaser: {chaser.PlayerFacingError:F1} degrees off: {(faced ? "ok" : "FAIL")}");
        return walked && jumped && hut && followed && fadeDone && chased && faced ? 0 : 1;
    }

    /// <summary>Prints the walk out's summary: the player crossed into the block to the south and the landscape followed it
    /// (its load point in the player's block, the 3 × 3 around it at full detail, as far as the data holds blocks, and in
    /// the world); 0 when every expectation holds, else 1.</summary>
    public int ReportCrossing(PhysicsObj player, Landscape landscape)
    {
        uint block = player.Position.ObjCellId >> 16;
        uint south = (Scene.CentreBlock >> 16) - 1;
        bool crossed = block == south && player.CellId != 0;
        Console.WriteLine($"walked out of 0x{Scene.CentreBlock >> 16:X4} into 0x{block:X4}: {(crossed ? "ok" : "FAIL")}");
        bool followed = landscape.LoadedCellId >> 16 == block;
        int full = 0, expected = 0;
        bool right = true;
        foreach (LandscapeBlock b in landscape.Blocks)
        {
            int dx = (int)(b.BlockId >> 24) - (int)(block >> 8), dy = (int)((b.BlockId >> 16) & 0xFF) - (int)(block & 0xFF);
            bool near = Math.Abs(dx) <= 1 && Math.Abs(dy) <= 1;
            expected += near ? 1 : 0;
            full += b.IsFullDetail ? 1 : 0;
            right &= near == (b.World is not null);
        }

        followed &= right && full == expected && expected > 0;
        Console.WriteLine($"the world followed: load point 0x{landscape.LoadedCellId:X8}, {full} landblocks at full detail (the 3 x 3 around the player that the data holds): {(followed ? "ok" : "FAIL")}");
        return crossed && followed ? 0 : 1;
    }

    private static float SetupPhysicsRadius => SetupPhysics.Human.Spheres[0].Radius;
}
