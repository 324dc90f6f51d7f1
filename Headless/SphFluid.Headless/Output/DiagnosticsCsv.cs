using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>One row of diagnostics.csv: the GPU diagnostics, how the frame was stepped, and the CPU measures of the same state.</summary>
public sealed record DiagnosticsRow(double Time, int Frame, StepReport Step, DiagnosticsReport Report, FluidMeasures Measures);

/// <summary>
/// Writes diagnostics.csv, invariant culture, one row per line:
/// time_s, frame, substeps, dt_s, particles, total_mass_kg, kinetic_energy_J, max_speed_mps, nan_count,
/// outside_count (GPU reductions); then per phase &lt;name&gt;_count (a distinct prefix per phase: <see cref="ColumnPrefixes"/>), _compression_avg, _compression_max,
/// _expansion_avg, _expansion_max, _mean_height_m, _bottom_m, _top_m, _floor_share, _wall_share
/// (<see cref="PhaseMeasures"/>); then layering_index, interface_tilt_m, surge_front_m, back_wall_column_m,
/// potential_energy_J (<see cref="FluidMeasures"/>); then clamp_hits (particles the last-resort wall clamp caught since spawn:
/// 0 while the boundary particles hold the fluid); then density_iterations and divergence_iterations (DFSPH: mean
/// corrections per solve since the previous row; 0 with WCSPH) and divergence_error_pct_per_s (mean |D rho / Dt| / rho0,
/// either solver); then density_solves_cut_off and divergence_solves_cut_off (DFSPH: share, 0 to 1, of each kind's solves
/// since the previous row that ran out of rounds before their tolerance; 0 with WCSPH), last so that the columns before
/// them keep their places.
/// NaN where a figure does not exist (an empty phase, no pair to order).
/// </summary>
public sealed class DiagnosticsCsv : IDisposable
{
    static readonly string[] PhaseColumns =
        { "count", "compression_avg", "compression_max", "expansion_avg", "expansion_max", "mean_height_m", "bottom_m", "top_m", "floor_share", "wall_share" };

    static readonly UTF8Encoding Utf8 = new(false);

    readonly Stream _file;
    readonly string _path;
    readonly int _phaseCount;

    /// <summary>Creates the file at <paramref name="path"/>, unbuffered so that a line a full disk refuses fails at its
    /// own write and can be cut back (<see cref="WriteLine"/>).</summary>
    public DiagnosticsCsv(string path, IReadOnlyList<PhaseDescription> phases)
        : this(new FileStream(path, FileMode.Create, FileAccess.Write, FileShare.Read, bufferSize: 0), path, phases)
    {
    }

    /// <summary>Writes to <paramref name="file"/>, which it owns from here, and names <paramref name="path"/> in its errors
    /// (a test passes a stream that fails as a full disk does).</summary>
    public DiagnosticsCsv(Stream file, string path, IReadOnlyList<PhaseDescription> phases)
    {
        _file = file;
        _path = path;
        _phaseCount = phases.Count;
        var header = new StringBuilder("time_s,frame,substeps,dt_s,particles,total_mass_kg,kinetic_energy_J,max_speed_mps,nan_count,outside_count");
        foreach (string n in ColumnPrefixes(phases.Select(p => p.Name)))
            foreach (string column in PhaseColumns) header.Append(',').Append(n).Append('_').Append(column);
        header.Append(",layering_index,interface_tilt_m,surge_front_m,back_wall_column_m,potential_energy_J,clamp_hits,density_iterations,divergence_iterations,divergence_error_pct_per_s,density_solves_cut_off,divergence_solves_cut_off");
        WriteLine(header.ToString());
    }

    public void Append(DiagnosticsRow row)
    {
        var c = CultureInfo.InvariantCulture;
        var r = row.Report;
        var m = row.Measures;
        var line = new StringBuilder();
        line.Append(string.Format(c, "{0:F4},{1},{2},{3:G6},{4},{5:G9},{6:G6},{7:G6},{8},{9}",
            row.Time, row.Frame, row.Step.Substeps, row.Step.TimeStep, r.ParticleCount, r.TotalMass, r.KineticEnergy, r.MaxSpeed, r.NanCount, r.OutsideCount));
        for (int k = 0; k < _phaseCount; k++)
        {
            var p = k < r.Phases.Count ? r.Phases[k] : null;
            var q = m != null && k < m.Phases.Count ? m.Phases[k] : null;
            line.Append(string.Format(c, ",{0},{1:G6},{2:G6},{3:G6},{4:G6},{5:G6},{6:G6},{7:G6},{8:G6},{9:G6}", p?.Count ?? 0,
                q?.CompressionAverage ?? double.NaN, q?.CompressionMax ?? double.NaN, q?.ExpansionAverage ?? double.NaN, q?.ExpansionMax ?? double.NaN,
                q?.MeanHeight ?? double.NaN, q?.Bottom ?? double.NaN, q?.Top ?? double.NaN, q?.FloorShare ?? double.NaN, q?.WallShare ?? double.NaN));
        }
        line.Append(string.Format(c, ",{0:G6},{1:G6},{2:G6},{3:G6},{4:G6},{5},{6:G4},{7:G4},{8:G6},{9:G4},{10:G4}",
            m?.LayeringIndex ?? double.NaN, m?.InterfaceTilt ?? double.NaN, m?.SurgeFront ?? double.NaN, m?.BackWallColumn ?? double.NaN, m?.PotentialEnergy ?? double.NaN, r.ClampHits,
            r.DensitySolveIterations, r.DivergenceSolveIterations, r.DivergenceError, r.DensitySolvesCutOff, r.DivergenceSolvesCutOff));
        WriteLine(line.ToString());
    }

    /// <summary>
    /// Appends one line whole or not at all. The log is appended a row at a time through a run, so it cannot be written
    /// aside and moved into place as the other outputs are (<see cref="OutputFolder.Write"/>); instead a write that a
    /// full disk stops part-way is cut back to the end of the row before, and the log ends on a complete row when the
    /// run stops with the file error.
    /// </summary>
    void WriteLine(string text)
    {
        byte[] bytes = Utf8.GetBytes(text + "\n");
        long before = _file.Length;
        try
        {
            _file.Write(bytes, 0, bytes.Length);
            _file.Flush();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            string cut = "the part of the row written was removed";
            try
            {
                _file.SetLength(before);
            }
            catch (Exception again) when (again is IOException or UnauthorizedAccessException)
            {
                cut = $"the part of the row written could not be removed ({again.Message})";
            }
            throw new IOException($"cannot append to {_path}: {e.Message}; {cut}", e);
        }
    }

    /// <summary>One distinct column prefix per phase name, in phase order (this log's columns and study.csv's). Validation
    /// refuses names that differ only by letter case, but names that differ only by punctuation ("oil-1", "oil 1") still
    /// fold to one prefix here: the second and later take _2, _3, ... so no two columns share a header.</summary>
    public static IReadOnlyList<string> ColumnPrefixes(IEnumerable<string> phaseNames)
    {
        var prefixes = new List<string>();
        var used = new HashSet<string>(StringComparer.Ordinal);
        foreach (string name in phaseNames)
        {
            string baseName = Column(name), n = baseName;
            for (int k = 2; !used.Add(n); k++) n = baseName + "_" + k.ToString(CultureInfo.InvariantCulture);
            prefixes.Add(n);
        }
        return prefixes;
    }

    /// <summary>A phase name as a column prefix: letters, digits and underscores.</summary>
    static string Column(string name)
    {
        var b = new StringBuilder();
        foreach (char ch in name ?? "phase") b.Append(char.IsLetterOrDigit(ch) ? char.ToLowerInvariant(ch) : '_');
        return b.Length == 0 ? "phase" : b.ToString();
    }

    public void Dispose() => _file.Dispose();
}
