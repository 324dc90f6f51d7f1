using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;

namespace SphFluid.Headless.Output;

/// <summary>
/// Progress on stderr: a redrawn bar when stderr is a terminal, otherwise a plain line every tenth of the
/// run (logs and CI stay readable).
/// </summary>
public sealed class ProgressReporter(TextWriter? writer, bool interactive, double total, string unit)
{
    const int BarWidth = 30;
    readonly Stopwatch _clock = Stopwatch.StartNew();
    long _lastDrawMs = -1000;
    int _lastDecile = -1;
    bool _drawn;

    public static bool StderrIsTerminal => !Console.IsErrorRedirected;

    public void Report(double done, string detail)
    {
        if (writer == null) return;
        double fraction = total > 0 ? Math.Clamp(done / total, 0, 1) : 1;
        double elapsed = _clock.Elapsed.TotalSeconds;
        string eta = fraction > 0.01 ? Format(elapsed / fraction - elapsed) : "--:--";
        var c = CultureInfo.InvariantCulture;
        if (interactive)
        {
            long now = _clock.ElapsedMilliseconds;
            if (now - _lastDrawMs < 100 && fraction < 1) return;
            _lastDrawMs = now;
            int filled = (int)(fraction * BarWidth);
            string bar = new string('#', filled) + new string('.', BarWidth - filled);
            writer.Write(string.Format(c, "\r[{0}] {1,5:F1}%  {2:F2}/{3:F2} {4}  {5}  elapsed {6}  eta {7}   ",
                bar, fraction * 100, done, total, unit, detail, Format(elapsed), eta));
            _drawn = true;
        }
        else
        {
            int decile = (int)(fraction * 10);
            if (decile == _lastDecile) return;
            _lastDecile = decile;
            writer.WriteLine(string.Format(c, "progress {0,3:F0}%  {1:F2}/{2:F2} {3}  {4}  elapsed {5}  eta {6}",
                fraction * 100, done, total, unit, detail, Format(elapsed), eta));
        }
        writer.Flush();
    }

    /// <summary>Erases the bar so a line can be printed; the next report draws it again.</summary>
    public void Interrupt()
    {
        if (writer == null || !interactive || !_drawn) return;
        writer.Write("\r" + new string(' ', 150) + "\r");
        writer.Flush();
        _drawn = false;
        _lastDrawMs = -1000;
    }

    /// <summary>Ends the bar's line so later output starts clean.</summary>
    public void Finish()
    {
        if (writer != null && interactive && _drawn) writer.WriteLine();
        _drawn = false;
    }

    static string Format(double seconds)
    {
        if (!double.IsFinite(seconds) || seconds < 0) return "--:--";
        var t = TimeSpan.FromSeconds(seconds);
        return t.TotalHours >= 1 ? t.ToString(@"h\:mm\:ss", CultureInfo.InvariantCulture) : t.ToString(@"mm\:ss", CultureInfo.InvariantCulture);
    }
}
