using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// A minimal SVG line/scatter chart writer for the reports in docs/. No plotting package (ScottPlot, OxyPlot, SkiaSharp,
/// Plotly.NET) is available on this project's package mirror, so the report draws its few charts itself: axes with
/// ticks, optional log10 axes, one colour per series, markers and/or lines, and a legend.
/// </summary>
internal sealed class SvgChart
{
    private static readonly string[] Palette = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"];
    private readonly List<(string Name, List<(double X, double Y)> Points, bool Lines, bool Markers, List<string>? Labels)> _series = [];

    public SvgChart(string title, string xLabel, string yLabel)
    {
        Title = title;
        XLabel = xLabel;
        YLabel = yLabel;
    }

    public string Title { get; }

    public string XLabel { get; }

    public string YLabel { get; }

    public bool LogX { get; init; }

    public bool LogY { get; init; }

    public int Width { get; init; } = 720;

    public int Height { get; init; } = 420;

    public int LegendWidth { get; init; } = 190;

    /// <summary>Adds a series; points with non-finite coordinates (or non-positive ones on a log axis) are skipped. Optional
    /// <paramref name="labels"/> (one per point) are written beside the markers.</summary>
    public SvgChart Add(string name, IEnumerable<(double X, double Y)> points, bool lines = true, bool markers = false, IReadOnlyList<string>? labels = null)
    {
        var list = new List<(double, double)>();
        List<string>? kept = labels is null ? null : [];
        int i = 0;
        foreach (var p in points)
        {
            if (double.IsFinite(p.X) && double.IsFinite(p.Y) && (!LogX || p.X > 0) && (!LogY || p.Y > 0))
            {
                list.Add(p);
                kept?.Add(labels![i]);
            }

            i++;
        }

        _series.Add((name, list, lines, markers, kept));
        return this;
    }

    public void Save(string path)
    {
        Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(path))!);
        File.WriteAllText(path, Render());
    }

    public string Render()
    {
        const int left = 80, top = 40, bottom = 60;
        int right = LegendWidth;
        int pw = Width - left - right, ph = Height - top - bottom;
        double x0 = double.MaxValue, x1 = double.MinValue, y0 = double.MaxValue, y1 = double.MinValue;
        foreach (var s in _series)
        {
            foreach (var (x, y) in s.Points)
            {
                double tx = TX(x), ty = TY(y);
                x0 = Math.Min(x0, tx);
                x1 = Math.Max(x1, tx);
                y0 = Math.Min(y0, ty);
                y1 = Math.Max(y1, ty);
            }
        }

        if (x0 > x1)
        {
            x0 = 0;
            x1 = 1;
            y0 = 0;
            y1 = 1;
        }

        if (x1 - x0 < 1e-12)
        {
            x0 -= 0.5;
            x1 += 0.5;
        }

        if (y1 - y0 < 1e-12)
        {
            y0 -= 0.5;
            y1 += 0.5;
        }

        double padX = (x1 - x0) * 0.04;
        x0 -= padX;
        x1 += padX;
        double padY = (y1 - y0) * 0.05;
        y0 -= padY;
        y1 += padY;

        var sb = new StringBuilder();
        sb.Append(Inv($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{Width}\" height=\"{Height}\" font-family=\"sans-serif\" font-size=\"12\">\n"));
        sb.Append(Inv($"<rect width=\"{Width}\" height=\"{Height}\" fill=\"white\"/>\n"));
        sb.Append(Inv($"<text x=\"{Width / 2}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">{Esc(Title)}</text>\n"));
        sb.Append(Inv($"<rect x=\"{left}\" y=\"{top}\" width=\"{pw}\" height=\"{ph}\" fill=\"none\" stroke=\"#333\"/>\n"));
        foreach (double fx in Ticks(x0, x1, LogX))
        {
            double px = left + (fx - x0) / (x1 - x0) * pw;
            sb.Append(Inv($"<line x1=\"{px:F1}\" y1=\"{top}\" x2=\"{px:F1}\" y2=\"{top + ph}\" stroke=\"#eee\"/>\n"));
            sb.Append(Inv($"<text x=\"{px:F1}\" y=\"{top + ph + 16}\" text-anchor=\"middle\">{Fmt(LogX ? Math.Pow(10, fx) : fx)}</text>\n"));
        }

        foreach (double fy in Ticks(y0, y1, LogY))
        {
            double py = top + ph - (fy - y0) / (y1 - y0) * ph;
            sb.Append(Inv($"<line x1=\"{left}\" y1=\"{py:F1}\" x2=\"{left + pw}\" y2=\"{py:F1}\" stroke=\"#eee\"/>\n"));
            sb.Append(Inv($"<text x=\"{left - 6}\" y=\"{py + 4:F1}\" text-anchor=\"end\">{Fmt(LogY ? Math.Pow(10, fy) : fy)}</text>\n"));
        }

        sb.Append(Inv($"<text x=\"{left + pw / 2}\" y=\"{Height - 18}\" text-anchor=\"middle\">{Esc(XLabel)}{(LogX ? " (log)" : "")}</text>\n"));
        sb.Append(Inv($"<text transform=\"translate(18,{top + ph / 2}) rotate(-90)\" text-anchor=\"middle\">{Esc(YLabel)}{(LogY ? " (log)" : "")}</text>\n"));

        for (int si = 0; si < _series.Count; si++)
        {
            var s = _series[si];
            string colour = Palette[si % Palette.Length];
            if (s.Lines && s.Points.Count > 1)
            {
                sb.Append("<polyline fill=\"none\" stroke=\"").Append(colour).Append("\" stroke-width=\"1.5\" points=\"");
                foreach (var (x, y) in s.Points)
                {
                    sb.Append(Inv($"{Px(x):F1},{Py(y):F1} "));
                }

                sb.Append("\"/>\n");
            }

            if (s.Markers)
            {
                for (int pi = 0; pi < s.Points.Count; pi++)
                {
                    var (x, y) = s.Points[pi];
                    sb.Append(Inv($"<circle cx=\"{Px(x):F1}\" cy=\"{Py(y):F1}\" r=\"4\" fill=\"{colour}\"/>\n"));
                    if (s.Labels is not null)
                    {
                        sb.Append(Inv($"<text x=\"{Px(x) + 6:F1}\" y=\"{Py(y) - 5:F1}\" font-size=\"10\" fill=\"{colour}\">{Esc(s.Labels[pi])}</text>\n"));
                    }
                }
            }

            int ly = top + 10 + si * 18;
            sb.Append(Inv($"<rect x=\"{left + pw + 12}\" y=\"{ly - 9}\" width=\"12\" height=\"12\" fill=\"{colour}\"/>\n"));
            sb.Append(Inv($"<text x=\"{left + pw + 30}\" y=\"{ly + 2}\">{Esc(s.Name)}</text>\n"));
        }

        sb.Append("</svg>\n");
        return sb.ToString();

        double Px(double x) => left + (TX(x) - x0) / (x1 - x0) * pw;
        double Py(double y) => top + ph - (TY(y) - y0) / (y1 - y0) * ph;
    }

    // Tick positions in axis units: whole decades on a log axis (every other one when more than 8), else 1/2/5 steps.
    private static List<double> Ticks(double lo, double hi, bool log)
    {
        var list = new List<double>();
        if (log)
        {
            double first = Math.Ceiling(lo), last = Math.Floor(hi);
            int step = last - first > 8 ? 2 : 1;
            for (double d = first; d <= last + 1e-9; d += step)
            {
                list.Add(d);
            }

            if (list.Count >= 2)
            {
                return list;
            }

            list.Clear();
        }

        double raw = (hi - lo) / 5.0;
        double mag = Math.Pow(10, Math.Floor(Math.Log10(raw)));
        double unit = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2 * mag : raw / mag < 7.5 ? 5 * mag : 10 * mag;
        for (double v = Math.Ceiling(lo / unit) * unit; v <= hi + unit * 1e-9; v += unit)
        {
            list.Add(v);
        }

        return list;
    }

    private double TX(double x) => LogX ? Math.Log10(x) : x;

    private double TY(double y) => LogY ? Math.Log10(y) : y;

    private static string Fmt(double v) => Math.Abs(v) >= 1e4 || (Math.Abs(v) < 1e-2 && v != 0)
        ? v.ToString("0.##E+0", CultureInfo.InvariantCulture)
        : v.ToString("0.###", CultureInfo.InvariantCulture);

    private static string Esc(string s) => s.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal);

    private static string Inv(FormattableString f) => f.ToString(CultureInfo.InvariantCulture);
}
