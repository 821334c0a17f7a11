namespace AcDream.Core.Physics.World;

/// <summary>How a remote object (one the client does not control) follows server position reports: a fidelity switch.</summary>
public enum RemoteSmoothing
{
    /// <summary>Retail: a report within 96 m of the player is queued on the <c>InterpolationManager</c>, which steers the
    /// body towards it at up to twice the motion's speed (<c>CPhysicsObj::MoveOrTeleport</c>, acclient.c:323450).</summary>
    Retail = 0,

    /// <summary>Not retail: every report places the body at once (as retail does only beyond 96 m); between reports the body
    /// moves by its own animation root motion and velocity.</summary>
    Snap = 1,

    /// <summary>Not retail: every report places the body at once, and until the next report the body moves in a straight line at
    /// the velocity of the last two reports (position difference over client-clock difference) instead of its root motion.</summary>
    LinearExtrapolation = 2,
}
