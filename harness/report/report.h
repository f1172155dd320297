// results/REPORT.md and the convergence plots, built from the CSVs in the results folder.
//
//   results/<experiment>.csv   errors (results_table.h), written by `curvbench run`
//   results/rates.csv          rates of every series
//   results/table2.csv         ring sizes (paper Table 2)
//   results/table4.csv         isosurface input errors (paper Table 4)
//   results/table5_timing.csv, table5_scaling.csv, end_to_end.csv   Table 5 (report/table5.h)
//   results/plots/<panel>_<family>.{png,svg}   one log-log plot per figure panel and mesh family
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/model/results_table.h"
#include "harness/report/model.h"
#include "meshgen/torus_isosurface.h"

namespace curvbench {

struct ReportOptions {
  std::string results_dir = "results";
  bool plots = true;  ///< render PNG and SVG with gnuplot (skipped with a warning if missing)
  /// Write the tables derived on the way (best_radius.csv, recommendations.csv); false renders
  /// only (`curvbench report --site-only`, `make site`: the results folder is left as it is).
  bool write_tables = true;
  /// Polled before each plot; true = give up (REPORT.md is then not written).
  std::function<bool()> stop;
};

/// Writes results/table2.csv: ring sizes of an interior vertex of a regular valence-6 mesh.
void write_table2_csv(const std::string& path);
/// Writes results/table4.csv from the marching-cubes torus meshes up to max_grid_points.
void write_table4_csv(const std::string& path, int max_grid_points);
/// The paper's Table 4 beside ours: the one rendering of it (the report, `curvbench mesh
/// --table4`).
report::Section table4_section(const std::vector<Table4Row>& rows);

/// Everything the report shows, as sections of the report model (report/model.h), built once
/// and rendered to markdown (REPORT.md's details in results/report/) and to HTML (the site).
struct ReportContent {
  std::vector<report::Section> paper;        ///< Tables 2 and 4, the well-shaped tori, Table 5
  std::vector<report::Section> experiments;  ///< one per experiment but the sweeps; id = name
  std::vector<report::Section> studies;      ///< field studies, radius scaling, sweeps + advice,
                                             ///< point clouds
  report::Section point_cloud_summary;       ///< REPORT.md's point-cloud tables (point_clouds.h)
};

/// Builds the content (and, with options.plots, the PNG/SVG plots) from the CSVs in
/// results_dir; std::nullopt if options.stop asked to stop.
std::optional<ReportContent> build_report(const std::vector<Experiment>& experiments,
                                          const ReportOptions& options);

/// Markdown bullets for the outside estimators of an experiment: each `description="..."`, and
/// each method skipped because its command cannot run here (from <results_dir>/skipped.csv,
/// results_table.h), with the reason. Empty when there is neither.
std::string outside_method_notes(const Experiment& e, const std::string& results_dir);

/// Renders a plot of the report model (report/model.h) with gnuplot to <results_dir>/plots/
/// <base>.png and .svg (each under its temp_path() name first, then renamed into place), and on
/// success sets plot.image to "plots/<base>.png" so that the markdown renderer shows it. Returns
/// false if gnuplot is unavailable or fails. If gnuplot was killed by SIGINT or SIGTERM (std::
/// system ignores them in the caller meanwhile), the signal is re-raised.
bool render_plot_files(report::Plot& plot, const std::string& results_dir, const std::string& base);

/// The series of one method per label, in first-seen order, of error rows (x = h, y = error;
/// non-finite or non-positive errors left out; the hover note names level, vertices and case),
/// each styled by plot_styles.h; with `rates`, the label ends with "(rate r)", r the average
/// rate log(e1/eN)/log(h1/hN) over its first and last level; with `slopes`, dashed O(h^p)
/// reference series for the orders those rates round to (1-4), anchored at half the largest
/// error at the coarsest h.
std::vector<report::Series> error_series(const std::vector<ErrorRow>& rows, bool rates = true,
                                         bool slopes = true);

/// Runs gnuplot on `setup` (settings and data blocks) then `plot` (the plot command, drawn once
/// per terminal) into <base>.png and <base>.svg, as render_plot does. Returns false if gnuplot is
/// unavailable or fails; re-raises SIGINT or SIGTERM if gnuplot was killed by one.
bool run_gnuplot(const std::string& base, const std::string& setup, const std::string& plot);

}  // namespace curvbench
