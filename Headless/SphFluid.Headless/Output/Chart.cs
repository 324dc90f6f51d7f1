using System;
using System.IO;
using ScottPlot;

namespace SphFluid.Headless.Output;

/// <summary>
/// One figure of a run (ScottPlot): a title, axes labelled with their units, a legend, written as PNG and SVG. The
/// font is loaded from a file, not looked up by name: the SkiaSharp build that ships without native dependencies has
/// no font discovery, so a named system font would silently render no text.
/// </summary>
public sealed class Chart
{
    /// <summary>Where Headless/install-deps.sh puts the font (Debian's fonts-dejavu-core).</summary>
    public const string FontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    const string FontName = "DejaVu Sans";

    static readonly object FontLock = new();
    static bool _fontLoaded;

    public Plot Plot { get; } = new();

    public int Width { get; init; } = 900;
    public int Height { get; init; } = 540;

    /// <summary>The legend's corner, chosen by each chart where its data leaves room.</summary>
    public Alignment LegendCorner { get; set; } = Alignment.UpperRight;

    /// <summary>Puts the legend below the axes instead: for scattered data, where no corner is sure to be empty.</summary>
    public bool LegendBelow { get; set; }

    public Chart(string title, string xLabel, string yLabel)
    {
        LoadFont();
        Plot.Font.Set(FontName);
        Plot.Title(title);
        Plot.XLabel(xLabel);
        Plot.YLabel(yLabel);
    }

    /// <summary>Writes <paramref name="stem"/>.png and <paramref name="stem"/>.svg through the output folder (so they are
    /// recorded as the run's own files, and written whole or not at all).</summary>
    public void Save(OutputFolder folder, string stem)
    {
        if (LegendBelow) Plot.ShowLegend(Edge.Bottom);
        else Plot.ShowLegend(LegendCorner);
        byte[] png;
        using (var image = Plot.GetImage(Width, Height))
            png = image.GetImageBytes(ImageFormat.Png, 100);
        string svg = Plot.GetSvgXml(Width, Height);
        folder.Write(stem + ".png", file => file.Write(png));
        folder.WriteText(stem + ".svg", svg);
    }

    static void LoadFont()
    {
        lock (FontLock)
        {
            if (_fontLoaded) return;
            if (!File.Exists(FontFile))
                throw new InvalidOperationException($"the chart font {FontFile} is missing: run Headless/install-deps.sh (Debian package fonts-dejavu-core)");
            Fonts.AddFontFile(FontName, FontFile);
            _fontLoaded = true;
        }
    }
}
