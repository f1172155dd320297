// The estimator registry: make_estimator() and estimator_names() of estimator.h.
//
// Every method is ONE line of CURVBENCH_ESTIMATORS below:
//   X(name, min_degree, max_degree, factory)
// where `factory` is a function `std::unique_ptr<Estimator> factory(EstimatorOptions)` defined in
// the method's own .cpp (in namespace curvbench). The line both declares the factory and adds it
// to the table; the order of the lines is the order of estimator_names(). A degree-free method
// (a discrete operator) has min_degree = max_degree = 0.
#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <vector>

#include "core/errors.h"
#include "methods/estimator.h"

// clang-format off
#define CURVBENCH_ESTIMATORS(X)                 \
  X("lhf", 1, 6, make_lhf_estimator)            \
  X("lop", 1, 6, make_lop_estimator)            \
  X("xu", 2, 2, make_xu_estimator)              \
  X("lscm", 1, 6, make_lscm_estimator)          \
  X("lscm-fast", 1, 6, make_lscm_fast_estimator) \
  X("lscm-cg", 1, 6, make_lscm_cg_estimator)     \
  X("jet", 2, 4, make_jet_estimator)            \
  X("meyer", 0, 0, make_meyer_estimator)        \
  X("taubin", 0, 0, make_taubin_estimator)      \
  X("rusinkiewicz", 0, 0, make_rusinkiewicz_estimator) \
  X("quadric", 0, 0, make_quadric_estimator)    \
  X("goldfeather", 0, 0, make_goldfeather_estimator) \
  X("normal-cycle", 0, 0, make_normal_cycle_estimator)
// clang-format on

namespace curvbench {

#define CURVBENCH_DECLARE_FACTORY(name, lo, hi, factory) \
  std::unique_ptr<Estimator> factory(EstimatorOptions options);
CURVBENCH_ESTIMATORS(CURVBENCH_DECLARE_FACTORY)
#undef CURVBENCH_DECLARE_FACTORY

namespace {

struct Registration {
  const char* name;
  int min_degree;
  int max_degree;
  std::unique_ptr<Estimator> (*make)(EstimatorOptions);
};

#define CURVBENCH_REGISTER(name, lo, hi, factory) Registration{name, lo, hi, &factory},
const Registration kRegistry[] = {CURVBENCH_ESTIMATORS(CURVBENCH_REGISTER)};
#undef CURVBENCH_REGISTER

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string valid_names() {
  std::string s;
  for (const Registration& r : kRegistry) {
    if (!s.empty()) s += ", ";
    s += r.name;
  }
  return s;
}

// Options of single methods (EstimatorOptions: vertex_normals, quadric_constant, ball_factor)
// given to a method that does not use them: an error rather than silently ignored.
std::unique_ptr<Estimator> checked(std::unique_ptr<Estimator> est) {
  const EstimatorOptions& o = est->options();
  const std::string name = est->name();
  if (o.vertex_normals != VertexNormals::method_default && est->takes_degree())
    throw UsageError(
        "vertex-normals applies to the discrete operators only (meyer, taubin, "
        "rusinkiewicz, quadric, goldfeather, normal-cycle), not to '" +
        name + "'");
  if (o.quadric_constant && name != "quadric")
    throw UsageError("quadric-constant applies to method 'quadric' only, not to '" + name + "'");
  if (o.ball_factor != 0.0 && name != "normal-cycle")
    throw UsageError("ball-factor applies to method 'normal-cycle' only, not to '" + name + "'");
  return est;
}

const Registration* find(const std::string& name) {
  for (const Registration& r : kRegistry)
    if (name == r.name) return &r;
  return nullptr;
}

}  // namespace

std::unique_ptr<Estimator> make_estimator(const std::string& name, EstimatorOptions options) {
  std::string base = lower(name);
  const Registration* reg = find(base);
  bool attached = false;
  if (reg == nullptr) {
    // "LHF-2": a trailing "-<digits>" is the degree.
    const size_t dash = base.rfind('-');
    if (dash != std::string::npos && dash + 1 < base.size() && dash + 3 >= base.size() &&
        std::all_of(base.begin() + static_cast<std::ptrdiff_t>(dash + 1), base.end(),
                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; })) {
      reg = find(base.substr(0, dash));
      if (reg != nullptr) {
        if (reg->max_degree == 0)
          throw UsageError("method '" + std::string(reg->name) +
                           "' takes no degree (it is not a polynomial fit): write '" + reg->name +
                           "', not '" + name + "'");
        options.degree = std::stoi(base.substr(dash + 1));
        attached = true;
      }
    }
  }
  if (reg == nullptr)
    throw UsageError("unknown method '" + name + "' (valid: " + valid_names() +
                     ", optionally with the degree attached, e.g. LHF-2)");
  if (reg->max_degree == 0) {
    if (options.degree != 0)
      throw UsageError("method '" + std::string(reg->name) + "' takes no degree (got degree " +
                       std::to_string(options.degree) + "; it is not a polynomial fit)");
    return checked(reg->make(options));
  }
  if (options.degree == 0 && !attached)
    options.degree = std::clamp(2, reg->min_degree, reg->max_degree);
  if (options.degree < reg->min_degree || options.degree > reg->max_degree) {
    const std::string range =
        reg->min_degree == reg->max_degree
            ? std::to_string(reg->min_degree)
            : std::to_string(reg->min_degree) + ".." + std::to_string(reg->max_degree);
    throw UsageError("method '" + std::string(reg->name) + "' does not support degree " +
                     std::to_string(options.degree) + " (valid: " + range + ")");
  }
  return checked(reg->make(options));
}

std::vector<std::string> estimator_names() {
  std::vector<std::string> names;
  for (const Registration& r : kRegistry) names.emplace_back(r.name);
  return names;
}

bool scores_interior_only(const std::string& method) {
  try {
    return make_estimator(method, EstimatorOptions{})->scores_interior_only();
  } catch (const UsageError&) {
    return false;  // not a built-in method
  }
}

}  // namespace curvbench
