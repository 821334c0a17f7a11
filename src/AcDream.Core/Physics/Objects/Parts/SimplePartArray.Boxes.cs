using System;

namespace AcDream.Core.Physics.Objects.Parts;

// The parts' bounding boxes of an object made from its data id (retail's CPhysicsPart list), for the static cell list.
public sealed partial class SimplePartArray
{
    private PartBox[] _partBoxes = Array.Empty<PartBox>();

    /// <summary>Each part's frame and bounding box (empty unless the object was made from a data id): what
    /// <c>find_bbox_cell_list</c> reads of retail's parts.</summary>
    internal ReadOnlySpan<PartBox> PartBoxes => _partBoxes;

    /// <summary>Sets the parts' boxes (at creation, never in a tick).</summary>
    internal void SetPartBoxes(PartBox[] boxes)
    {
        _partBoxes = boxes;
        PlacedBoxes = new PlacedPartBox[boxes.Length];
    }

    /// <summary>Scratch for the parts placed where the object stands (one per part), so that a cell list allocates nothing.</summary>
    internal PlacedPartBox[] PlacedBoxes { get; private set; } = Array.Empty<PlacedPartBox>();
}
