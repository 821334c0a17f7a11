using System;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// What a cell's object loop reads to pass over a shadowed object without reading it: the object's origin and cell id, and a
/// reach that is never short of the exact one (|scale| · <see cref="Objects.Parts.SimplePartArray.ObstacleReach"/>, computed
/// in double and rounded up to a float), or the mark of an attached object (never tested) or of one the loop must decide
/// from the object itself (tested in full: a physics BSP, cylinder spheres, another part array, none). Each cell keeps one
/// per listed shadow, at the shadow's index, in its <see cref="ObstacleTable"/>.
/// </summary>
/// <remarks>The object writes it into every cell that lists one of its shadows whenever an input changes
/// (<see cref="PhysicsObj.SyncObstacleSummary"/>: a new frame or cell id, scale, part array, spheres, state, parent); the
/// cell writes it when a shadow is added. <see cref="Verify"/> turns on a check of every entry the loop reads against a fresh
/// computation (the test suite runs with it).</remarks>
// non-retail: a packed copy for the exact early-out of ObjectReach (retail reads every shadowed object)
internal struct ObstacleSummary
{
    /// <summary><see cref="Reach"/> of a parented object: the loop skips it, as retail skips an object with a parent.</summary>
    public const float Parented = float.NegativeInfinity;

    /// <summary><see cref="Reach"/> of an object the loop decides from the object itself (a physics BSP, cylinder spheres,
    /// another part array than <see cref="Objects.Parts.SimplePartArray"/>, no part array).</summary>
    public const float TestFully = float.NaN;

    /// <summary>The object's origin, local to its landblock.</summary>
    public float X, Y, Z;

    /// <summary>The exact reach rounded up to a float (≥ 0), or <see cref="Parented"/>, or <see cref="TestFully"/>.</summary>
    public float Reach;

    /// <summary>The object's position cell id (its landblock: the high 16 bits).</summary>
    public uint CellId;

    /// <summary>The <see cref="AppContext"/> switch that turns <see cref="Verify"/> on (the test project sets it in its
    /// runtime configuration).</summary>
    internal const string VerifySwitch = "AcDream.Core.Physics.VerifyObstacleTables";

    /// <summary>When true, the cells' object loops check every summary they read against
    /// <see cref="PhysicsObj.ComputeObstacleSummary"/>, and every obstacle they pass over against
    /// <see cref="PhysicsObj.IsOutOfReach"/>, and throw on a difference. Read once from the <see cref="VerifySwitch"/>
    /// switch of the process's runtime configuration (off by default; the test project turns it on): configuration fixed
    /// for the process, not state a caller can change, so the JIT folds it away.</summary>
    internal static readonly bool Verify = AppContext.TryGetSwitch(VerifySwitch, out bool on) && on;

    /// <summary>The reach a cell of landblock <paramref name="cellBlock"/> (a cell id's high 16 bits) stores: the marks as
    /// they are; a reach only for an object of that landblock (its origin is then in the cell's frame), else
    /// <see cref="TestFully"/>.</summary>
    public readonly float ReachIn(uint cellBlock) =>
        Reach == Parented || float.IsNaN(Reach) || (CellId != 0 && CellId >> 16 == cellBlock) ? Reach : TestFully;

    /// <inheritdoc />
    public override readonly string ToString() =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture,
            $"(reach {Reach:R} at {X:R}, {Y:R}, {Z:R} in 0x{CellId:X8})");

    /// <summary>The reach |<paramref name="scale"/>| · <paramref name="bound"/> (in double), rounded up to a float.</summary>
    public static float RoundUpReach(float scale, float bound) =>
        Objects.Parts.SimplePartArray.RoundUpToFloat(Math.Abs((double)scale) * bound);
}
