namespace AcDream.Core.Physics.Collision;

/// <summary>
/// How the sphere path is being inserted into the world. Retail: <c>enum SPHEREPATH::InsertType</c> (acclient.h:6160).
/// </summary>
internal enum InsertType
{
    /// <summary>A sweep from a begin position to an end position (retail <c>TRANSITION_INSERT</c>).</summary>
    Transition = 0,

    /// <summary>Placing the object at one position, searching nearby if it does not fit (retail <c>PLACEMENT_INSERT</c>).</summary>
    Placement = 1,

    /// <summary>The first test of a placement; object collisions are skipped (retail <c>INITIAL_PLACEMENT_INSERT</c>).</summary>
    InitialPlacement = 2,
}
