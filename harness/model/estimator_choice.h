// A radius sweep's case label as the estimator `curvbench estimate` runs ("LHF-4 rings=2" ->
// method lhf-4 with rings 2): what the advice from mesh features (harness/report/advice.h), the
// advice measured on the mesh (harness/model/measured_advice.h) and `curvbench recommend` run.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "curvbench/estimator_options.h"

namespace curvbench {

/// What `curvbench estimate` runs for a sweep's case label: "LHF-4 rings=2" -> method "lhf-4",
/// rings 2; "ICC ball-factor=4" -> "icc", ball-factor 4; "Rusinkiewicz" -> "rusinkiewicz" at
/// its 1-ring (split_radius_label, harness/model/results_table.h). The sweeps' method lines set no
/// other option (experiments/sweep-radius.exp), so the label is the whole estimator.
struct EstimatorChoice {
  std::string label;      ///< the case label, as in the table
  std::string method;     ///< --method
  std::string parameter;  ///< "rings", "ball-factor" or "" (the method's own neighbourhood)
  double radius = std::numeric_limits<double>::quiet_NaN();  ///< NaN without a parameter
  EstimatorOptions options;  ///< the radius set (rings or ball_factor), the rest default

  /// The estimate flags: {"--method", "lhf-4", "--rings", "2"}.
  std::vector<std::string> flags() const;
  /// "LHF-4, rings 2", "ICC, ball factor C = 4", "Rusinkiewicz, its 1-ring".
  std::string text() const;
};
/// Throws UsageError when the label names no method make_estimator() knows, or a radius the
/// method does not take.
EstimatorChoice estimator_choice(const std::string& label);
/// The distinct labels, in first-seen order, as estimator choices; throws as estimator_choice.
std::vector<EstimatorChoice> distinct_estimator_choices(const std::vector<std::string>& labels);

}  // namespace curvbench
