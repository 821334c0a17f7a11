// PhysicsObj — hiding: set_hidden, run when the HIDDEN state bit changes.
using AcDream.Core.Physics.Collision.Sweep;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
    /// <summary>
    /// Hides or shows the object: hidden, its children are not drawn, it stops reporting collisions (those in progress end)
    /// and ignores them, and the voyeurs of its cell are told it left; shown, the reverse, the collisions it still touches
    /// reported again and the voyeurs told it entered. The part array is told each time (retail re-enters the world).
    /// </summary>
    /// <remarks>The hide and unhide scripts of the physics script table (<c>PS_Hidden</c>, <c>PS_UnHide</c>) and the parts'
    /// no-draw flags are the renderer's: not played here (docs/divergences.md).</remarks>
    // retail: CPhysicsObj::set_hidden (acclient.c:322077)
    internal void SetHidden(bool hidden)
    {
        ChildList? children = Children;
        if (hidden)
        {
            _state |= PhysicsState.Hidden;
            for (int i = 0; children is not null && i < children.Count; i++)
            {
                children.GetObject(i)._state |= PhysicsState.NoDraw;
            }

            if ((_state & PhysicsState.ReportCollisions) != 0)
            {
                World.Sweep.ReportCollisionEnd(this, true);
                _state &= ~PhysicsState.ReportCollisions;
            }

            _state |= PhysicsState.IgnoreCollisions;
            _cell?.HideObject(this);
            PartArray?.HandleEnterWorld();
        }
        else
        {
            _state &= ~PhysicsState.Hidden;
            for (int i = 0; children is not null && i < children.Count; i++)
            {
                children.GetObject(i)._state &= ~PhysicsState.NoDraw;
            }

            _state &= ~PhysicsState.IgnoreCollisions;
            if ((_state & PhysicsState.ReportCollisions) == 0)
            {
                _state |= PhysicsState.ReportCollisions;
                if (World.Sweep is RetailSweep sweep)
                {
                    ReportCollisionStart(sweep);
                }
            }

            PartArray?.HandleEnterWorld();
            _cell?.UnhideObject(this);
        }
    }
}
