using System;

namespace AcDream.Core.Physics.Objects;

/// <summary>
/// What keeps an object from walking as a retail creature would (<see cref="PhysicsObj.SetupIssues"/>). Each is legal (retail
/// has such objects) but a walking creature or player should show <see cref="None"/>.
/// </summary>
[Flags]
public enum ObjectSetupIssues
{
    /// <summary>Nothing: the object can walk, step and collide.</summary>
    None = 0,

    /// <summary>No part array: the object never enters a cell, so it never moves (retail <c>CPhysicsObj::enter_cell</c>
    /// needs one) and velocities set on it do nothing.</summary>
    NoPartArray = 1 << 0,

    /// <summary>A part array without collision spheres: each step keeps the origin and takes only the new orientation, so
    /// root motion and velocity do not move it.</summary>
    NoCollisionSpheres = 1 << 1,

    /// <summary>No movement manager: each step that begins at rest on walkable ground deactivates the object, and only the
    /// world's player wakes it again (within 96 m): near the player it walks at half speed, in a world without a player it
    /// takes one step and stops. <see cref="PhysicsObj.GetOrCreateMotionInterpreter"/> creates one; the world's player gets one when it is
    /// set.</summary>
    NoMovementManager = 1 << 2,

    /// <summary>Step-up or step-down height at or below 0.01 m, retail's value for an object without a Setup: the object
    /// cannot follow terrain unevenness (it stalls on a slope change). Use a Setup's heights, e.g.
    /// <see cref="Parts.SetupPhysics.Human"/>.</summary>
    NoSetupStepHeights = 1 << 3,

    /// <summary>The world sweeps through free space (no terrain, no walls): a world built over a terrain world uses the retail
    /// sweep.</summary>
    FreeSpaceSweep = 1 << 4,

    /// <summary>The object is not in a cell (never entered the world, or could not be placed): the tick skips it.</summary>
    NotInCell = 1 << 5,

    /// <summary>A part array without a motion table (<see cref="Parts.IPartArray.MotionPlayer"/> null) while the object moves
    /// through retail's movement manager (or has none yet): the motion commands (<c>DoMotion(WalkForward)</c>...) reach no
    /// motion table, so the object does not walk, run or turn. Give the part array one, e.g.
    /// <see cref="Motion.SpeedOnlyMotionPlayer"/>. Not reported for an object whose movement manager is a client's own.</summary>
    NoMotionTable = 1 << 6,

    /// <summary>No weenie (<see cref="PhysicsObj.Weenie"/> null) while the object moves through retail's movement manager (or
    /// has none yet): the motion interpreter takes retail's no-weenie branch, run rate 1 (a run is capped at 4 m/s, and the
    /// run rate a server MoveTo carries, <see cref="Motion.MotionInterp.MyRunRate"/>, is ignored) and a 10 m/s jump. Retail
    /// gives every object a weenie (<c>ACCWeenieObject</c>): use <see cref="Motion.RemoteCreatureWeenie.Creature"/> or
    /// <see cref="Motion.RemoteCreatureWeenie.Player"/> for a remote creature or player, <see cref="Motion.PlayerWeenie"/>
    /// for the player. Not reported for an object whose movement manager is a client's own.</summary>
    NoWeenie = 1 << 7,
}
