using System;
using System.Collections.Generic;
using System.Globalization;
using ScottPlot;
using ScottPlot.TickGenerators;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// A line/scatter chart of the reports, drawn with ScottPlot and saved as SVG: optional log10 axes (the data is plotted as
/// log10 with ticks labelled in the original unit), one series per scene or scenario, markers and/or lines, optional point
/// labels, and a legend.
/// </summary>
internal sealed class ReportChart
{
    private readonly Plot _plot = new();

    public ReportChart(string title, string xLabel, string yLabel)
    {
        _plot.Title(title);
        _plot.XLabel(xLabel);
        _plot.YLabel(yLabel);
    }

    public bool LogX { get; init; }

    public bool LogY { get; init; }

    public int Width { get; init; } = 720;

    public int Height { get; init; } = 420;

    /// <summary>Adds a series; points with non-finite coordinates (or non-positive ones on a log axis) are skipped. Optional
    /// <paramref name="labels"/> (one per point) are written beside the markers.</summary>
    public ReportChart Add(string name, IEnumerable<(double X, double Y)> points, bool lines = true, bool markers = false, IReadOnlyList<string>? labels = null)
    {
        var xs = new List<double>();
        var ys = new List<double>();
        var kept = new List<string>();
        int i = 0;
        foreach (var p in points)
        {
            if (double.IsFinite(p.X) && double.IsFinite(p.Y) && (!LogX || p.X > 0) && (!LogY || p.Y > 0))
            {
                xs.Add(LogX ? Math.Log10(p.X) : p.X);
                ys.Add(LogY ? Math.Log10(p.Y) : p.Y);
                if (labels is not null)
                {
                    kept.Add(labels[i]);
                }
            }

            i++;
        }

        if (xs.Count == 0)
        {
            return this;
        }

        var scatter = _plot.Add.Scatter(xs.ToArray(), ys.ToArray());
        scatter.LegendText = name;
        scatter.LineWidth = lines ? 1.5f : 0f;
        scatter.MarkerSize = markers ? 7f : 0f;
        for (int k = 0; k < kept.Count; k++)
        {
            var text = _plot.Add.Text(kept[k], xs[k], ys[k]);
            text.LabelFontSize = 10;
            text.LabelFontColor = scatter.Color;
            text.LabelOffsetX = 5;
            text.LabelOffsetY = -5;
        }

        return this;
    }

    /// <summary>Writes the chart as SVG to <paramref name="path"/>.</summary>
    public void Save(string path)
    {
        if (LogX)
        {
            _plot.Axes.Bottom.TickGenerator = LogTicks();
        }

        if (LogY)
        {
            _plot.Axes.Left.TickGenerator = LogTicks();
        }

        _plot.ShowLegend(Edge.Right);
        _plot.SaveSvg(path, Width, Height);
    }

    // Ticks at the powers of ten of log10-plotted data, labelled in the original unit, with log-spaced minor ticks.
    private static NumericAutomatic LogTicks() => new()
    {
        MinorTickGenerator = new LogMinorTickGenerator(),
        IntegerTicksOnly = true,
        LabelFormatter = v => Math.Pow(10, v).ToString("G3", CultureInfo.InvariantCulture),
    };
}
