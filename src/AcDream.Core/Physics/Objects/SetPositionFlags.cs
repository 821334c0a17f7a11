using System;

namespace AcDream.Core.Physics.Objects;

/// <summary>Flags of a position request (retail <c>SetPositionFlag</c>, acclient.h:6123).</summary>
[Flags]
public enum SetPositionFlags : uint
{
    /// <summary>No flag.</summary>
    None = 0,

    /// <summary>PLACEMENT_SPF.</summary>
    Placement = 0x1,

    /// <summary>TELEPORT_SPF.</summary>
    Teleport = 0x2,

    /// <summary>RESTORE_SPF.</summary>
    Restore = 0x4,

    /// <summary>SLIDE_SPF: the placement may slide to a free spot.</summary>
    Slide = 0x10,

    /// <summary>DONOTCREATECELLS_SPF.</summary>
    DoNotCreateCells = 0x20,

    /// <summary>SCATTER_SPF.</summary>
    Scatter = 0x100,

    /// <summary>RANDOMSCATTER_SPF.</summary>
    RandomScatter = 0x200,

    /// <summary>LINE_SPF.</summary>
    Line = 0x400,

    /// <summary>SEND_POSITION_EVENT_SPF.</summary>
    SendPositionEvent = 0x1000,
}

/// <summary>Result of a position request (retail <c>SetPositionError</c>, acclient.h:6111).</summary>
public enum SetPositionError
{
    /// <summary>OK_SPE.</summary>
    Ok = 0,

    /// <summary>GENERAL_FAILURE_SPE.</summary>
    GeneralFailure = 1,

    /// <summary>NO_VALID_POSITION_SPE.</summary>
    NoValidPosition = 2,

    /// <summary>NO_CELL_SPE.</summary>
    NoCell = 3,

    /// <summary>COLLIDED_SPE.</summary>
    Collided = 4,

    /// <summary>INVALID_ARGUMENTS.</summary>
    InvalidArguments = 0x100,
}
