using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>One S2C UpdatePosition (0xF748) of any object.</summary>
public readonly record struct MeleeUpdate(double T, uint Guid, Position Position, bool Grounded, ushort SeqPosition, ushort SeqTeleport,
                                          byte[] Body);

/// <summary>One S2C MovementEvent (0xF74C) of any object: its body as the wire carries it after the opcode, and its type.</summary>
public sealed record MeleeMovement(double T, uint Guid, bool Autonomous, byte Type, byte[] Body);

/// <summary>
/// The melee-attack-run recording (../shared/data/replay, README there, "melee-attack-run"): every object's updates and
/// movement events, the objects' create positions, and the poses the player's own client sent. Times are the recording's
/// clock.
/// </summary>
public sealed class MeleeRecording
{
    /// <summary>The recording player, +Dorsvane.</summary>
    public const uint Player = 0x50000013u;

    /// <summary>The monster the player's four MoveToObjects target.</summary>
    public const uint Chicken = 0x8000033Au;

    /// <summary>The other wandering monster.</summary>
    public const uint TheChicken = 0x80000334u;

    /// <summary>The file whose presence says the recording is there.</summary>
    public const string MarkerFile = "melee-attack-run_s2c_movementevent.csv";

    /// <summary>Updates in arrival order.</summary>
    public List<MeleeUpdate> Updates { get; } = new();

    /// <summary>Movement events in arrival order.</summary>
    public List<MeleeMovement> Movements { get; } = new();

    /// <summary>The player's own poses (F61C and F753 at one instant count once).</summary>
    public List<RealPose> Truth { get; } = new();

    /// <summary>The player's own poses with their rotation, as <see cref="Truth"/>.</summary>
    public List<Position> TruthPositions { get; } = new();

    /// <summary>Create (0xF745) time and position of the player and the two monsters.</summary>
    public Dictionary<uint, (double T, Position Position)> Creates { get; } = new();

    /// <summary>Loads the recording from <paramref name="dir"/>.</summary>
    public static MeleeRecording Load(string dir)
    {
        var r = new MeleeRecording();
        foreach (string[] c in Csv.Rows(Path.Combine(dir, "melee-attack-run_creates.csv")))
        {
            uint guid = Csv.U(c[0]);
            if (guid is Player or Chicken or TheChicken)
            {
                r.Creates[guid] = (Csv.D(c[1]), new Position(Csv.U(c[3]), Csv.Frame(c, 4)));
            }
        }

        foreach (string[] c in Csv.Rows(Path.Combine(dir, "melee-attack-run_s2c_updateposition.csv")))
        {
            // The body rebuilt from the columns and decoded by the library (WireBodies).
            byte[] body = WireBodies.UpdatePosition(c);
            UpdatePositionMessage m = WireBodies.DecodePosition(body);
            r.Updates.Add(new MeleeUpdate(Csv.D(c[0]), m.ObjectId, m.Position, m.HasContact, m.PositionTimestamp, m.TeleportTimestamp, body));
        }

        foreach (string[] c in Csv.Rows(Path.Combine(dir, "melee-attack-run_s2c_movementevent.csv")))
        {
            uint guid = Csv.U(c[1]);
            bool autonomous = c[5] == "1";
            // The body after the opcode: guid, instance, movement and server-control stamps, autonomous byte, pad, data.
            byte[] body = WireBodies.MovementEvent(c);
            r.Movements.Add(new MeleeMovement(Csv.D(c[0]), guid, autonomous, body[MovementEventDecoder.BodyHeaderLength], body));
        }

        double last = double.NaN;
        foreach (string[] c in Csv.Rows(Path.Combine(dir, "melee-attack-run_c2s_autonomous.csv")))
        {
            double t = Csv.D(c[0]);
            if (t == last)
            {
                continue;
            }

            last = t;
            var p = new Position(Csv.U(c[1]), Csv.Frame(c, 2));
            r.Truth.Add(new RealPose(t, p.ObjCellId, p.Frame.Origin));
            r.TruthPositions.Add(p);
        }

        return r;
    }

    /// <summary>The player's MoveToObject events, in order.</summary>
    public List<MeleeMovement> PlayerMoveToObjects()
    {
        var list = new List<MeleeMovement>();
        foreach (MeleeMovement m in Movements)
        {
            if (m.Guid == Player && m.Type == 6)
            {
                list.Add(m);
            }
        }

        return list;
    }
}

/// <summary>CSV helpers for the recordings.</summary>
internal static class Csv
{
    public static IEnumerable<string[]> Rows(string path)
    {
        bool header = true;
        foreach (string line in File.ReadLines(path))
        {
            if (header)
            {
                header = false;
                continue;
            }

            if (line.Length != 0)
            {
                yield return SplitQuoted(line);
            }
        }
    }

    // Standard CSV quoting (a name may hold a comma).
    private static string[] SplitQuoted(string line)
    {
        if (!line.Contains('"', StringComparison.Ordinal))
        {
            return line.Split(',');
        }

        var cells = new List<string>();
        var cur = new System.Text.StringBuilder();
        bool quoted = false;
        foreach (char ch in line)
        {
            if (ch == '"')
            {
                quoted = !quoted;
            }
            else if (ch == ',' && !quoted)
            {
                cells.Add(cur.ToString());
                cur.Clear();
            }
            else
            {
                cur.Append(ch);
            }
        }

        cells.Add(cur.ToString());
        return cells.ToArray();
    }

    public static double D(string s) => double.Parse(s, CultureInfo.InvariantCulture);

    public static float F(string s) => float.Parse(s, CultureInfo.InvariantCulture);

    public static uint U(string s) => uint.Parse(s.AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture);

    public static ushort U16(string s) => (ushort)int.Parse(s, CultureInfo.InvariantCulture);

    /// <summary>x, y, z, qw, qx, qy, qz from column <paramref name="at"/>; the quaternion normalised (the CSV's nine
    /// digits are within 6e-7 of unit).</summary>
    public static Frame Frame(string[] c, int at)
    {
        var q = Quaternion.Normalize(new Quaternion(F(c[at + 4]), F(c[at + 5]), F(c[at + 6]), F(c[at + 3])));
        return new Frame(new Vector3(F(c[at]), F(c[at + 1]), F(c[at + 2])), q);
    }
}
