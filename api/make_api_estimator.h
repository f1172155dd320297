// The estimator of a public EstimateOptions (include/curvbench/curvbench.h), for the C++ API.
#pragma once

#include <memory>

#include "curvbench/curvbench.h"
#include "methods/estimator.h"

namespace curvbench {

/// make_estimator(options.method, options); throws UsageError as make_estimator does, and for a
/// degree that differs from the one attached to the method name ("method LHF-4 names degree 4
/// but degree is 2").
std::unique_ptr<Estimator> make_api_estimator(const EstimateOptions& options);

}  // namespace curvbench
