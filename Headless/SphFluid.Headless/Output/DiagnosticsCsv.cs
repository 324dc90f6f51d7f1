using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>One row of diagnostics.csv: the GPU diagnostics plus how the frame was stepped and where each phase sits.</summary>
public sealed record DiagnosticsRow(double Time, int Frame, StepReport Step, DiagnosticsReport Report, LayeringSample Layering);

/// <summary>
/// Writes diagnostics.csv: time_s, frame, substeps, dt_s, particles, total_mass_kg, kinetic_energy_J,
/// max_speed_mps, nan_count, outside_count, then per phase &lt;name&gt;_count, _density_error_avg,
/// _density_error_max, _mean_height_m, and finally layering_index. Invariant culture, one row per line.
/// </summary>
public sealed class DiagnosticsCsv : IDisposable
{
    readonly StreamWriter _writer;
    readonly int _phaseCount;

    public DiagnosticsCsv(string path, IReadOnlyList<PhaseDescription> phases)
    {
        _phaseCount = phases.Count;
        _writer = new StreamWriter(path, false, new UTF8Encoding(false)) { NewLine = "\n" };
        var header = new StringBuilder("time_s,frame,substeps,dt_s,particles,total_mass_kg,kinetic_energy_J,max_speed_mps,nan_count,outside_count");
        foreach (var p in phases)
        {
            string n = Column(p.Name);
            header.Append($",{n}_count,{n}_density_error_avg,{n}_density_error_max,{n}_mean_height_m");
        }
        header.Append(",layering_index");
        _writer.WriteLine(header);
    }

    public void Append(DiagnosticsRow row)
    {
        var c = CultureInfo.InvariantCulture;
        var r = row.Report;
        var line = new StringBuilder();
        line.Append(string.Format(c, "{0:F4},{1},{2},{3:G6},{4},{5:G9},{6:G6},{7:G6},{8},{9}",
            row.Time, row.Frame, row.Step.Substeps, row.Step.TimeStep, r.ParticleCount, r.TotalMass, r.KineticEnergy, r.MaxSpeed, r.NanCount, r.OutsideCount));
        for (int k = 0; k < _phaseCount; k++)
        {
            var p = k < r.Phases.Count ? r.Phases[k] : null;
            double height = row.Layering != null && k < row.Layering.MeanHeights.Count ? row.Layering.MeanHeights[k] : double.NaN;
            line.Append(string.Format(c, ",{0},{1:G6},{2:G6},{3:G6}", p?.Count ?? 0, p?.AverageDensityError ?? float.NaN, p?.MaxDensityError ?? float.NaN, height));
        }
        line.Append(string.Format(c, ",{0:G6}", row.Layering?.LayeringIndex ?? double.NaN));
        _writer.WriteLine(line);
        _writer.Flush();
    }

    /// <summary>A phase name as a column prefix: letters, digits and underscores.</summary>
    static string Column(string name)
    {
        var b = new StringBuilder();
        foreach (char ch in name ?? "phase") b.Append(char.IsLetterOrDigit(ch) ? char.ToLowerInvariant(ch) : '_');
        return b.Length == 0 ? "phase" : b.ToString();
    }

    public void Dispose() => _writer.Dispose();
}
