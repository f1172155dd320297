// REPORT.md section "The estimators in common use": the experiments named field-estimators*
// (experiments/field-estimators*.exp) summarised per mesh family, from the errors CSVs and the
// timings CSVs (results_table.h) of the results folder:
//   - a table of the finest level's L2 and Linf errors in normals, H, K and d1, each with the
//     average convergence rate of its series, and the time per vertex;
//   - an accuracy-versus-cost plot (log-log): L2 error in H against the time per vertex, one
//     point per method and level (plots/field-frontier_<experiment>_<family>.{png,svg});
//   - the time to solution (log-log): L2 error in H against the time of the whole mesh's
//     estimation, one curve per method over the levels
//     (plots/field-time_<experiment>_<family>.{png,svg}), and a table of the cheapest method
//     reaching each target error (cheapest_to_reach);
//   - sentences, generated from the numbers, saying which estimators converge on which meshes.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/report/model.h"
#include "harness/report/report.h"

namespace curvbench {

/// A series "converges" when its average L2 rate and its rate between the two finest levels are
/// both at least this (errors in O(h^0.5) or better); otherwise it does not.
inline constexpr double kConvergenceRateThreshold = 0.5;
/// A series whose finest-level error is at most this is exact up to round-off (e.g. d1 on the
/// structured torus, where symmetry makes it exact); its rate means nothing.
inline constexpr double kRoundOffError = 1e-10;

/// The cheapest way to a target error: among `rows` (each method's series of one quantity and
/// norm on one family, ErrorRow::seconds the time of the case), the row of least time whose error
/// is at most the target, and the cheapest such row of another method (the runner-up).
struct CheapestToReach {
  double target = 0.0;
  const ErrorRow* best = nullptr;       ///< nullptr: no row reaches the target
  const ErrorRow* runner_up = nullptr;  ///< nullptr: no other method reaches it
};
CheapestToReach cheapest_to_reach(const std::vector<ErrorRow>& rows, double target);

/// The target errors of the time-to-solution table: the powers of ten from 1e-1 to 1e-8 that
/// some row reaches but some method does not reach at its cheapest row (the others are reached
/// by every method at once), then the next power of ten if no row reaches it.
std::vector<double> time_targets(const std::vector<ErrorRow>& rows);

/// Appends the blocks of the field studies to `out` (the studies' section "field-studies"):
/// per group (the estimators in common use; the meshes that break estimators) a heading of
/// level 0 (the section's own level) and its words, then per experiment and mesh a heading, the
/// errors table, the words on convergence, the two cost plots and the cheapest-to-reach table.
/// Nothing when no field-estimators or hard-meshes experiment has results. With options.plots,
/// the plots are rendered to PNG and SVG (render_plot_files); returns false if options.stop asked
/// to stop meanwhile (the report is then abandoned). `missing_plots` counts plots gnuplot could
/// not render.
bool field_sections(const std::vector<Experiment>& experiments, const ReportOptions& options,
                    int& missing_plots, report::Section& out);

}  // namespace curvbench
