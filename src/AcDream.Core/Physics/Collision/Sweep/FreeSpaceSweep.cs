using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Collision.Sweep;

/// <summary>
/// The default <see cref="CollisionSweep"/>: a world with no collision geometry. A sweep always succeeds and ends where it
/// was asked to, in the same cell, with no contact plane and no sliding normal; a placement succeeds in the requested cell
/// (adjusted to the outdoor cell under the origin, as <c>store_position</c> does), or sends the object to the lost cell when
/// the cell id is not a valid world cell.
/// </summary>
/// <remarks>Not retail: retail always sweeps against cells. The sweep of a world made without terrain or cells, and of
/// every step in a scene without <see cref="World.SceneEffects.Collision"/>; a world with cells sweeps with
/// <see cref="RetailSweep"/>.</remarks>
public sealed class FreeSpaceSweep : CollisionSweep
{
    /// <summary>The shared stateless instance.</summary>
    public static readonly FreeSpaceSweep Instance = new();

    private FreeSpaceSweep()
    {
    }

    /// <inheritdoc />
    public override bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result)
    {
        result = TransitionResult.FreeSpace(newPos);
        result.CurrentCellId = obj.CellId;
        return true;
    }

    /// <inheritdoc />
    /// <remarks>The free-space answer: the step ends where it was asked to, in the object's cell, and is committed.</remarks>
    internal override bool SweepStep(PhysicsObj obj, in Position newPos, float quantum)
    {
        TransitionResult result = TransitionResult.FreeSpace(newPos);
        result.CurrentCellId = obj.CellId;
        obj.CommitStep(result, quantum);
        return true;
    }

    /// <inheritdoc />
    public override SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags)
    {
        Position p = pos;
        if (!LandDefs.InboundValidCellId(p.ObjCellId) || ((p.ObjCellId & 0xFFFFu) < 0x100u && !p.TryAdjustToOutside()))
        {
            obj.GoToLostCellInternal(pos);
            return SetPositionError.Ok;
        }

        TransitionResult t = TransitionResult.FreeSpace(p);
        obj.CommitTransitionInternal(t);
        return SetPositionError.Ok;
    }
}
