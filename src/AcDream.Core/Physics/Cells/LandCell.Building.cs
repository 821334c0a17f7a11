using AcDream.Core.Physics.Collision;

namespace AcDream.Core.Physics.Cells;

/// <summary>The building standing on a land cell (retail's <c>CSortCell</c> layer between <c>CObjCell</c> and <c>CLandCell</c>).</summary>
public sealed partial class LandCell
{
    /// <summary>The building on this cell, or null. Retail: <c>CSortCell::building</c>.</summary>
    public BuildingObj? Building { get; set; }

    /// <summary>The building's shell against the check spheres; OK without a building.</summary>
    // retail: CSortCell::find_collisions (acclient.c:356106)
    public TransitionState FindBuildingCollisions(Transition transition) =>
        Building is null ? TransitionState.Ok : Building.FindBuildingCollisions(transition);
}
