#include "api/make_api_estimator.h"

#include <string>

#include "core/errors.h"

namespace curvbench {

std::unique_ptr<Estimator> make_api_estimator(const EstimateOptions& options) {
  return make_estimator(options.method, options);
}

}  // namespace curvbench
