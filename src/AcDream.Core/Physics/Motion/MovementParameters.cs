using System;

namespace AcDream.Core.Physics.Motion;

/// <summary>The flag bits of <see cref="MovementParameters"/> (retail's <c>MovementParameters</c> bitfield, bit 0 first).</summary>
[Flags]
public enum MovementParameterFlags : uint
{
    /// <summary>No flag.</summary>
    None = 0,

    /// <summary>A move-to may walk (bit 0).</summary>
    CanWalk = 0x1,

    /// <summary>A move-to may run (bit 1).</summary>
    CanRun = 0x2,

    /// <summary>A move-to may side-step (bit 2).</summary>
    CanSidestep = 0x4,

    /// <summary>A move-to may walk backwards (bit 3).</summary>
    CanWalkBackwards = 0x8,

    /// <summary>A move-to may charge (bit 4).</summary>
    CanCharge = 0x10,

    /// <summary>A move-to fails if it must walk (bit 5).</summary>
    FailWalk = 0x20,

    /// <summary>A move-to turns to the final heading (bit 6).</summary>
    UseFinalHeading = 0x40,

    /// <summary>A move-to sticks to its target (bit 7).</summary>
    Sticky = 0x80,

    /// <summary>A move-to moves away (bit 8).</summary>
    MoveAway = 0x100,

    /// <summary>A move-to moves towards (bit 9).</summary>
    MoveTowards = 0x200,

    /// <summary>A move-to measures between spheres (bit 10).</summary>
    UseSpheres = 0x400,

    /// <summary><see cref="MovementParameters.HoldKeyToApply"/> becomes the raw state's hold key (bit 11).</summary>
    SetHoldKey = 0x800,

    /// <summary>The motion was started by this client (bit 12; stored with queued actions).</summary>
    Autonomous = 0x1000,

    /// <summary>A successful motion is recorded in the raw state (bit 13).</summary>
    ModifyRawState = 0x2000,

    /// <summary>A successful motion is recorded in the interpreted state (bit 14).</summary>
    ModifyInterpretedState = 0x4000,

    /// <summary>The motion cancels a running move-to (bit 15).</summary>
    CancelMoveTo = 0x8000,

    /// <summary>Stop completely (bit 16).</summary>
    StopCompletely = 0x10000,

    /// <summary>The motion's link animation does not allow a jump (bit 17).</summary>
    DisableJumpDuringLink = 0x20000,
}

/// <summary>
/// The parameters of one motion command (retail <c>MovementParameters</c>). <c>new MovementParameters()</c> gives retail's
/// defaults (its constructor, acclient.c:339436); <c>default(MovementParameters)</c> gives all zeros (speed 0, no flags),
/// which is not a retail value: every motion entry that takes parameters (<c>DoMotion</c>, <c>StopMotion</c>,
/// <c>DoInterpretedMotion</c>, <c>StopInterpretedMotion</c>, the states' <c>ApplyMotion</c>) refuses it with an
/// <see cref="System.ArgumentException"/>. A value with any field set is accepted (speed 0 and no flags are legal alone).
/// </summary>
public partial struct MovementParameters
{
    /// <summary>Retail's default flags: walk, run, side-step, walk backwards, move towards, use spheres, set hold key,
    /// modify raw and interpreted state, cancel move-to, stop completely (<c>0x1EE0F</c>).</summary>
    public const MovementParameterFlags DefaultFlags = (MovementParameterFlags)0x1EE0Fu;

    /// <summary>Creates retail's default parameters (speed 1, distance to object 0.6 m, fail distance float.MaxValue,
    /// walk/run threshold 15 m, hold key <see cref="HoldKey.Invalid"/>, <see cref="DefaultFlags"/>).</summary>
    // retail: MovementParameters::MovementParameters (acclient.c:339436)
    public MovementParameters()
    {
        MinDistance = 0f;
        DistanceToObject = 0.6f;
        FailDistance = float.MaxValue;
        DesiredHeading = 0f;
        Speed = 1f;
        WalkRunThreshold = 15f;
        ContextId = 0;
        HoldKeyToApply = HoldKey.Invalid;
        ActionStamp = 0;
        Flags = DefaultFlags;
    }

    /// <summary>The flag bits.</summary>
    public MovementParameterFlags Flags;

    /// <summary>Distance to the target object, metres.</summary>
    public float DistanceToObject;

    /// <summary>Minimum distance, metres.</summary>
    public float MinDistance;

    /// <summary>Desired heading, degrees.</summary>
    public float DesiredHeading;

    /// <summary>Speed multiplier of the motion.</summary>
    public float Speed;

    /// <summary>Distance after which a move-to gives up, metres.</summary>
    public float FailDistance;

    /// <summary>Distance above which a move-to runs, metres.</summary>
    public float WalkRunThreshold;

    /// <summary>Context id the completed motion is reported with.</summary>
    public uint ContextId;

    /// <summary>Hold key to apply (<see cref="HoldKey.Invalid"/>: the raw state's current one).</summary>
    public HoldKey HoldKeyToApply;

    /// <summary>Server action stamp of an action.</summary>
    public uint ActionStamp;

    /// <summary>Every field is zero: <c>default(MovementParameters)</c>, which the motion API refuses.</summary>
    internal readonly bool IsAllZero =>
        Flags == MovementParameterFlags.None && DistanceToObject == 0f && MinDistance == 0f && DesiredHeading == 0f
        && Speed == 0f && FailDistance == 0f && WalkRunThreshold == 0f && ContextId == 0 && HoldKeyToApply == HoldKey.Invalid
        && ActionStamp == 0;

    /// <summary>Every field by name (the flags by their names).</summary>
    public readonly override string ToString() => string.Create(System.Globalization.CultureInfo.InvariantCulture,
        $"MovementParameters {{ Flags = {Flags}, Speed = {Speed}, HoldKeyToApply = {HoldKeyToApply}, "
        + $"DistanceToObject = {DistanceToObject}, MinDistance = {MinDistance}, DesiredHeading = {DesiredHeading}, "
        + $"FailDistance = {FailDistance}, WalkRunThreshold = {WalkRunThreshold}, ContextId = {ContextId}, "
        + $"ActionStamp = {ActionStamp} }}");

    internal readonly bool Has(MovementParameterFlags f) => (Flags & f) != 0;
}
