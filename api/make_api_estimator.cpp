#include "api/make_api_estimator.h"

#include <string>

#include "core/errors.h"

namespace curvbench {

std::unique_ptr<Estimator> make_api_estimator(const EstimateOptions& options) {
  std::unique_ptr<Estimator> est = make_estimator(options.method, options);
  if (options.degree > 0 && est->options().degree != options.degree)
    throw UsageError("method " + options.method + " names degree " +
                     std::to_string(est->options().degree) + " but degree is " +
                     std::to_string(options.degree));
  return est;
}

}  // namespace curvbench
