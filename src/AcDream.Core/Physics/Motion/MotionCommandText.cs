using System;
using System.Globalization;

namespace AcDream.Core.Physics.Motion;

/// <summary>How the motion types print a command: its name, or its hex id when it has none.</summary>
internal static class MotionCommandText
{
    /// <summary>The name of <paramref name="command"/> (<c>WalkForward</c>), or its id in hex (<c>0x8000003C</c>).</summary>
    public static string Format(MotionCommand command) =>
        Enum.IsDefined(command) ? command.ToString() : "0x" + ((uint)command).ToString("X8", CultureInfo.InvariantCulture);
}
