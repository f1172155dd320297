// REPORT.md section "The estimators in common use": the experiments named field-estimators*
// (experiments/field_estimators*.exp) summarised per mesh family, from the errors CSVs and the
// timings CSVs (results_table.h) of the results folder:
//   - a table of the finest level's L2 and Linf errors in normals, H, K and d1, each with the
//     average convergence rate of its series, and the time per vertex;
//   - an accuracy-versus-cost plot (log-log): L2 error in H against the time per vertex, one
//     point per method and level (plots/field-frontier_<experiment>_<family>.{png,svg});
//   - sentences, generated from the numbers, saying which estimators converge on which meshes.
#pragma once

#include <sstream>
#include <vector>

#include "harness/experiment.h"
#include "harness/report.h"

namespace curvbench {

/// A series "converges" when its average L2 rate and its rate between the two finest levels are
/// both at least this (errors in O(h^0.5) or better); otherwise it does not.
inline constexpr double kConvergenceRateThreshold = 0.5;
/// A series whose finest-level error is at most this is exact up to round-off (e.g. d1 on the
/// structured torus, where symmetry makes it exact); its rate means nothing.
inline constexpr double kRoundOffError = 1e-10;

/// Appends the section to `md` (nothing when no field-estimators experiment has results).
/// Returns false if options.stop asked to stop while plotting (the report is then abandoned).
/// `missing_plots` counts plots gnuplot could not render.
bool append_field_estimators_section(std::ostringstream& md,
                                     const std::vector<Experiment>& experiments,
                                     const ReportOptions& options, int& missing_plots);

}  // namespace curvbench
