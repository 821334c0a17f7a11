using System;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>Client frame pacing of a scene run: a steady frame rate, or 60 fps with stutters.</summary>
internal sealed class Pacing
{
    private Pacing(string name, double fps, bool stutter)
    {
        Name = name;
        Fps = fps;
        Stutter = stutter;
    }

    /// <summary>30 frames per second.</summary>
    public static Pacing Fps30 { get; } = new("30 fps", 30.0, false);

    /// <summary>60 frames per second.</summary>
    public static Pacing Fps60 { get; } = new("60 fps", 60.0, false);

    /// <summary>144 frames per second.</summary>
    public static Pacing Fps144 { get; } = new("144 fps", 144.0, false);

    /// <summary>60 fps with a hitch every second: alternately 0.12 s and 0.25 s (and 0.45 s every fifth second).</summary>
    public static Pacing Stutter60 { get; } = new("60 fps + stutters", 60.0, true);

    /// <summary>All four.</summary>
    public static Pacing[] All { get; } = [Fps30, Fps60, Fps144, Stutter60];

    public string Name { get; }

    public double Fps { get; }

    public bool Stutter { get; }

    /// <summary>Client times of the frames covering <paramref name="seconds"/> of play, starting after 0.</summary>
    public double[] Times(double seconds)
    {
        var list = new System.Collections.Generic.List<double>();
        double t = 0.0;
        int frame = 0;
        int second = 0;
        while (t < seconds)
        {
            double dt = 1.0 / Fps;
            frame++;
            if (Stutter && frame % (int)Fps == 0)
            {
                second++;
                dt = second % 5 == 0 ? 0.45 : (second % 2 == 0 ? 0.25 : 0.12);
            }

            t = Math.Min(seconds, t + dt);
            list.Add(t);
        }

        return list.ToArray();
    }
}
