#include "api/make_api_estimator.h"

#include <string>

#include "core/errors.h"
#include "methods/vertex_normals.h"

namespace curvbench {

std::unique_ptr<Estimator> make_api_estimator(const EstimateOptions& options) {
  EstimatorOptions eo;
  eo.degree = options.degree;  // 0: the method's default (2 for a fit, none if degree-free)
  eo.ring = options.rings;
  eo.threads = options.threads;
  eo.noisy = options.noisy;
  eo.vertex_normals = parse_vertex_normals(options.vertex_normals);
  eo.quadric_constant = options.quadric_constant;
  eo.ball_factor = options.ball_factor;
  if (options.degree < 0)
    throw UsageError("degree " + std::to_string(options.degree) + ": must be >= 1");
  if (options.rings < 0) throw UsageError("rings: must be >= 0 (0 = the method's default)");
  if (options.threads < 0) throw UsageError("threads: must be >= 0 (0 = all cores)");
  std::unique_ptr<Estimator> est = make_estimator(options.method, eo);
  if (options.degree > 0 && est->options().degree != options.degree)
    throw UsageError("method " + options.method + " names degree " +
                     std::to_string(est->options().degree) + " but degree is " +
                     std::to_string(options.degree));
  return est;
}

}  // namespace curvbench
