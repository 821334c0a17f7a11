using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Math;
using Xunit;

namespace AcDream.Core.Tests.Replay.Real;

/// <summary>One S2C 0xF748 UpdatePosition row.</summary>
internal readonly record struct UpdatePositionRow(double Time, uint Guid, Position Position, bool Grounded, ushort SeqPosition, ushort SeqTeleport);

/// <summary>One own pose a client sent (C2S 0xF61C / 0xF753 / 0xF61B).</summary>
internal readonly record struct OwnPoseRow(double Time, Position Position);

/// <summary>One S2C 0xF74C MovementEvent row with its decoded movement data.</summary>
internal readonly record struct MovementEventRow(double Time, uint Guid, bool Autonomous, int Length, MovementData Data);

/// <summary>
/// The real retail traffic of <c>../shared/data/replay</c> (README there: columns, guids, clock offsets). The folder comes from
/// <c>ACDREAM_REPLAY_DIR</c> when set, else <c>../shared/data/replay</c> beside the repository root (found by walking up
/// from the test assembly to the folder that holds AcDream.sln).
/// </summary>
internal static class ReplayData
{
    /// <summary>Environment variable that overrides the folder.</summary>
    public const string Variable = "ACDREAM_REPLAY_DIR";

    private static readonly Lazy<string?> DirLazy = new(FindDir);

    /// <summary>The folder, or null when absent.</summary>
    public static string? Dir => DirLazy.Value;

    /// <summary>Why replay tests skip, or null when the data is present.</summary>
    public static string? SkipReason => Dir is null
        ? $"Real replay data not found: set {Variable} or place shared/data/replay beside the repository (../shared/data/replay)."
        : null;

    /// <summary>All UpdatePositions of <paramref name="recording"/>.</summary>
    public static List<UpdatePositionRow> UpdatePositions(string recording)
    {
        var rows = new List<UpdatePositionRow>();
        foreach (string[] f in Rows(recording + "_s2c_updateposition.csv"))
        {
            // t_rel,guid,flags,objcell_id,x,y,z,qw,qx,qy,qz,vx,vy,vz,has_velocity,is_grounded,seq_instance,seq_position,seq_teleport,...
            rows.Add(new UpdatePositionRow(D(f[0]), Hex(f[1]), Pose(f, 3), f[15] == "1", (ushort)int.Parse(f[17], CultureInfo.InvariantCulture),
                (ushort)int.Parse(f[18], CultureInfo.InvariantCulture)));
        }

        return rows;
    }

    /// <summary>All own poses the recorder of <paramref name="recording"/> sent.</summary>
    public static List<OwnPoseRow> OwnPoses(string recording)
    {
        var rows = new List<OwnPoseRow>();
        foreach (string[] f in Rows(recording + "_c2s_autonomous.csv"))
        {
            // t_rel,objcell_id,x,y,z,qw,qx,qy,qz,...
            rows.Add(new OwnPoseRow(D(f[0]), Pose(f, 1)));
        }

        return rows;
    }

    /// <summary>All MovementEvents of <paramref name="recording"/>, each decoded (a decoding error throws).</summary>
    public static List<MovementEventRow> MovementEvents(string recording)
    {
        var rows = new List<MovementEventRow>();
        foreach (string[] f in Rows(recording + "_s2c_movementevent.csv"))
        {
            // t_rel,guid,seq_instance,seq_movement,seq_server_control,autonomous,movement_data_hex,msg_idx
            byte[] bytes = Convert.FromHexString(f[6]);
            rows.Add(new MovementEventRow(D(f[0]), Hex(f[1]), f[5] == "1", bytes.Length, MovementData.Decode(bytes)));
        }

        return rows;
    }

    /// <summary>The recordings of the folder.</summary>
    public static readonly string[] Recordings =
        ["fellowship-one-vassal", "fellowship-two-monarch", "fellowship-three-vassal", "long-movement-run"];

    /// <summary>Landblock-global origin: (lbx·192 + x, lby·192 + y, z).</summary>
    public static Vector3 Global(in Position p)
    {
        uint lbx = p.ObjCellId >> 24;
        uint lby = (p.ObjCellId >> 16) & 0xFF;
        Vector3 o = p.Frame.Origin;
        return new Vector3((float)(lbx * 192.0 + o.X), (float)(lby * 192.0 + o.Y), o.Z);
    }

    private static Position Pose(string[] f, int at)
    {
        uint cell = Hex(f[at]);
        var origin = new Vector3(F(f[at + 1]), F(f[at + 2]), F(f[at + 3]));
        var q = new Quaternion(F(f[at + 5]), F(f[at + 6]), F(f[at + 7]), F(f[at + 4]));
        if (q.LengthSquared() < 0.5f)
        {
            q = Quaternion.Identity;
        }

        return new Position(cell, new Frame(origin, Quaternion.Normalize(q)));
    }

    private static IEnumerable<string[]> Rows(string file)
    {
        string dir = Dir ?? throw new InvalidOperationException(SkipReason);
        bool header = true;
        foreach (string line in File.ReadLines(Path.Combine(dir, file)))
        {
            if (header)
            {
                header = false;
                continue;
            }

            if (line.Length > 0)
            {
                yield return line.Split(',');
            }
        }
    }

    private static double D(string s) => double.Parse(s, CultureInfo.InvariantCulture);

    private static float F(string s) => float.Parse(s, CultureInfo.InvariantCulture);

    private static uint Hex(string s) => uint.Parse(s.AsSpan(s.StartsWith("0x", StringComparison.Ordinal) ? 2 : 0), NumberStyles.HexNumber, CultureInfo.InvariantCulture);

    private static string? FindDir()
    {
        string? env = Environment.GetEnvironmentVariable(Variable);
        if (!string.IsNullOrEmpty(env))
        {
            return Directory.Exists(env) ? Path.GetFullPath(env) : null;
        }

        for (DirectoryInfo? d = new(AppContext.BaseDirectory); d is not null; d = d.Parent)
        {
            if (File.Exists(Path.Combine(d.FullName, "AcDream.sln")))
            {
                string candidate = Path.GetFullPath(Path.Combine(d.FullName, "..", "shared", "data", "replay"));
                return Directory.Exists(candidate) ? candidate : null;
            }
        }

        return null;
    }
}

/// <summary>A fact that needs the real replay data; skipped with a message naming where it looks when absent.</summary>
public sealed class ReplayDataFactAttribute : FactAttribute
{
    /// <summary>Skips the test when the data is absent.</summary>
    public ReplayDataFactAttribute()
    {
        if (ReplayData.SkipReason is { } reason)
        {
            Skip = reason;
        }
    }
}
