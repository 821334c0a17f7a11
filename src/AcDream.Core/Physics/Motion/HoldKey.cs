namespace AcDream.Core.Physics.Motion;

/// <summary>The hold key that modifies a motion (retail <c>HoldKey</c>): with <see cref="Run"/> a walk becomes a run.</summary>
public enum HoldKey
{
    /// <summary>No hold key given: the raw state's current hold key applies (retail <c>HoldKey_Invalid</c>).</summary>
    Invalid = 0,

    /// <summary>No hold key (retail <c>HoldKey_None</c>), the raw state's default.</summary>
    None = 1,

    /// <summary>The run key (retail <c>HoldKey_Run</c>).</summary>
    Run = 2,
}
