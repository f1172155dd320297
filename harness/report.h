// results/REPORT.md and the convergence plots, built from the CSVs in the results folder.
//
//   results/<experiment>.csv   errors (results_table.h), written by `curvbench run`
//   results/rates.csv          rates of every series
//   results/table2.csv         ring sizes (paper Table 2)
//   results/table4.csv         isosurface input errors (paper Table 4)
//   results/table5_timing.md   Table 5 timing (performance issue), included if present
//   results/plots/<panel>_<family>.{png,svg}   one log-log plot per figure panel and mesh family
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "harness/experiment.h"
#include "harness/results_table.h"

namespace curvbench {

struct ReportOptions {
  std::string results_dir = "results";
  bool plots = true;  ///< render PNG and SVG with gnuplot (skipped with a warning if missing)
  /// Polled before each plot; true = give up (REPORT.md is then not written).
  std::function<bool()> stop;
};

/// Writes results/table2.csv: ring sizes of an interior vertex of a regular valence-6 mesh.
void write_table2_csv(const std::string& path);
/// Writes results/table4.csv from the marching-cubes torus meshes up to max_grid_points.
void write_table4_csv(const std::string& path, int max_grid_points);

/// Builds REPORT.md (and the plots) for the given experiments from the CSVs in results_dir.
/// Returns the path of REPORT.md, or "" if options.stop asked to stop (REPORT.md untouched).
std::string write_report(const std::vector<Experiment>& experiments, const ReportOptions& options);

/// Markdown bullets for the outside estimators of an experiment: each `description="..."`, and
/// each method skipped because its command cannot run here (from <results_dir>/skipped.csv,
/// results_table.h), with the reason. Empty when there is neither.
std::string outside_method_notes(const Experiment& e, const std::string& results_dir);

/// The x axis of a plot: by default the mean edge length h, decreasing to the right, with each
/// method's convergence rate in the legend. The accuracy-versus-cost plots put the time per
/// vertex there instead (the rows' `h` then holds it).
struct PlotAxis {
  std::string label = "mean edge length h";
  bool reversed = true;
  bool rate_in_legend = true;
  bool reference_slopes = true;  ///< dashed O(h^p) lines (x must be h)
};

/// Renders one panel's log-log plot (error vs h, one line per method, rate in the legend) to
/// <base>.png and <base>.svg with gnuplot, each under its temp_path() name first and then renamed
/// into place. Returns false if gnuplot is unavailable or fails. If gnuplot was killed by SIGINT
/// or SIGTERM (std::system ignores them in the caller meanwhile), the signal is re-raised.
bool render_plot(const std::string& base, const std::string& title,
                 const std::vector<ErrorRow>& rows, const PlotAxis& x_axis = {});

/// Runs gnuplot on `setup` (settings and data blocks) then `plot` (the plot command, drawn once
/// per terminal) into <base>.png and <base>.svg, as render_plot does. Returns false if gnuplot is
/// unavailable or fails; re-raises SIGINT or SIGTERM if gnuplot was killed by one.
bool run_gnuplot(const std::string& base, const std::string& setup, const std::string& plot);

}  // namespace curvbench
