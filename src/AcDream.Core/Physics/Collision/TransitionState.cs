namespace AcDream.Core.Physics.Collision;

/// <summary>
/// The outcome of one collision test or insertion step of the sweep. Retail: <c>enum TransitionState</c> (acclient.h:6100).
/// </summary>
internal enum TransitionState
{
    /// <summary>No result (retail <c>INVALID_TS = 0</c>): returned by an insertion asked to make no attempt.</summary>
    Invalid = 0,

    /// <summary>The sphere fits where it is (retail <c>OK_TS = 1</c>).</summary>
    Ok = 1,

    /// <summary>The sphere cannot go there (retail <c>COLLIDED_TS = 2</c>).</summary>
    Collided = 2,

    /// <summary>The check position was moved to resolve a contact; test again (retail <c>ADJUSTED_TS = 3</c>).</summary>
    Adjusted = 3,

    /// <summary>The check position was slid along a surface; test again (retail <c>SLID_TS = 4</c>).</summary>
    Slid = 4,
}
