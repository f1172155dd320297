// REPORT.md section "Neighbourhoods that shrink more slowly than h": the experiments with
// `radius-scaling alpha=A c=C` (experiment.h; the radius c h^alpha, docs/algorithms.md §15) side
// by side. Per mesh and quantity (normals, H, K; L2), each method's convergence rate over the
// experiment's levels at every alpha, below the rates that the error bound of the paper's §3
// predicts for a degree-2 fit with O(h^2) input errors (radius_scaling_bounds()).
#pragma once

#include <string>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/model/results_table.h"
#include "harness/report/model.h"
#include "harness/report/report.h"

namespace curvbench {

/// The rates the bound of docs/algorithms.md §15 predicts at radius c h^alpha, degree 2, input
/// errors O(h^2): the worse of the truncation and the input terms.
struct RadiusScalingBounds {
  double normals = 0.0;              ///< min(2 alpha, 2 - alpha)
  double curvature = 0.0;            ///< min(alpha, 2 - 2 alpha)
  double curvature_symmetric = 0.0;  ///< min(2 alpha, 2 - 2 alpha): odd truncation terms cancel
};
RadiusScalingBounds radius_scaling_bounds(double alpha);

/// One method's rate at one alpha: log(e_first/e_last)/log(h_first/h_last) over the levels of
/// its series (measured h), for one mesh label and quantity (L2).
struct RadiusScalingRate {
  std::string family;    ///< mesh label
  std::string method;    ///< label, "Meyer (interior)" when scored on another vertex set
  std::string quantity;  ///< "normal", "H", "K"
  double alpha = 0.0;
  int first_level = 0, last_level = 0;
  double rate = 0.0;
};

/// The rates of `rows` (the errors CSV of one radius-scaling experiment run at `alpha`).
std::vector<RadiusScalingRate> radius_scaling_rates(const std::vector<ErrorRow>& rows,
                                                    double alpha);

/// The section "Neighbourhoods that shrink more slowly than h" (id "radius-scaling"): its words,
/// then per mesh and quantity a heading and the table of the bounds' and the methods' rates at
/// every alpha, each cell with its number. Without a radius-scaling experiment's CSV in
/// options.results_dir: no title and no blocks.
report::Section radius_scaling_section(const std::vector<Experiment>& experiments,
                                       const ReportOptions& options);

}  // namespace curvbench
