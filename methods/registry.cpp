// The estimator registry: make_estimator() and estimator_names() of estimator.h.
//
// Every method is ONE line of CURVBENCH_ESTIMATORS below:
//   X(name, min_degree, max_degree, bench, cost, group, radius, factory, summary)
// name      the --method name; a fit's label adds the degree ("LHF-2")
// min_degree, max_degree  the degrees a fit supports; 0, 0 for a degree-free discrete operator
// bench     the degrees make bench times it at: "2-4", "2", "once" (an operator), or "none"
// cost      seconds per vertex relative to LHF-2 at degree 2 (level-4 torus, one thread,
//           results/table5_timing.csv, rounded): balances the shards of `curvbench run`
// group     the family the results site files it under (MethodGroup): paper_fit (the paper's
//           parameterization-based fits), jet (CGAL's osculating jet), discrete (an operator
//           on the 1-ring or a ball)
// radius    what its neighbourhood size is (NeighbourhoodSize): half_rings (option rings, in
//           steps of 1/2: the fits), whole_rings (option rings, whole: the quadric), ball_factor
//           (option ball-factor: a ball of radius C h), fixed (one 1-ring, nothing to size)
// factory   a function `std::unique_ptr<Estimator> factory(EstimatorOptions)` defined in the
//           method's own .cpp (in namespace curvbench); the line declares it too
// summary   one line for --help and `curvbench methods`
// The order of the lines is the order of method_table() and estimator_names(). A program may add
// its own methods at run time with register_estimator() (after these lines, in call order).
#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/text.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"

// clang-format off
//  X(name,          degrees, bench, cost, group,    radius,      factory,          summary)
#define CURVBENCH_ESTIMATORS(X)                                                                               \
  X("lhf",           1, 6, "2-4", 1.0,  paper_fit, half_rings , make_lhf_estimator,                           \
    "local height function fit of degree d (Wang, Jiao et al. 2009, section 2.2)")                            \
  X("lop",           1, 6, "2",   1.15, paper_fit, half_rings , make_lop_estimator,                           \
    "local orthogonal projection fit of degree d (Wang, Jiao et al. 2009, section 4.2.2)")                    \
  X("xu",            2, 2, "2",   2.4,  paper_fit, fixed      , make_xu_estimator,                            \
    "quadratic fit over Xu's flattened 1-ring (Wang, Jiao et al. 2009, section 4.2.1)")                       \
  X("lscm",          1, 6, "2-4", 22.0, paper_fit, half_rings , make_lscm_estimator,                          \
    "fit over a local least-squares conformal map (CGAL's LSCM; section 4.2.3)")                              \
  X("lscm-fast",     1, 6, "2-4", 2.9,  paper_fit, half_rings , make_lscm_fast_estimator,                     \
    "the same conformal map computed in-house (dense solve on the small patch)")                              \
  X("lscm-cg",       1, 6, "none", 22.0, paper_fit, half_rings , make_lscm_cg_estimator,                      \
    "CGAL's LSCM solved by OpenNL conjugate gradients")                                                       \
  X("jet",           2, 4, "2-4", 11.4, jet      , half_rings , make_jet_estimator,                           \
    "CGAL's Jet_fitting_3 osculating jet (Cazals and Pouget 2005)")                                           \
  X("meyer",         0, 0, "once", 1.1, discrete , fixed      , make_meyer_estimator,                         \
    "cotangent mean curvature, angle-deficit Gaussian curvature (Meyer et al. 2003; libigl)")                 \
  X("taubin",        0, 0, "once", 0.5, discrete , fixed      , make_taubin_estimator,                        \
    "Taubin's curvature tensor from directional curvatures (Taubin 1995)")                                    \
  X("rusinkiewicz",  0, 0, "once", 1.5, discrete , fixed      , make_rusinkiewicz_estimator,                  \
    "per-face second fundamental form averaged at vertices (Rusinkiewicz 2004; trimesh2)")                    \
  X("quadric",       0, 0, "once", 7.0, discrete , whole_rings, make_quadric_estimator,                       \
    "quadric fit over a k-ring (libigl's principal_curvature; Panozzo et al. 2010)")                          \
  X("goldfeather",   0, 0, "once", 1.9, discrete , fixed      , make_goldfeather_estimator,                   \
    "adjacent-normal cubic fit over the 1-ring (Goldfeather and Interrante 2004)")                            \
  X("normal-cycle",  0, 0, "once", 1.5, discrete , ball_factor, make_normal_cycle_estimator,                  \
    "normal cycle curvature tensor over the 1-ring or a ball (Cohen-Steiner and Morvan 2003)")                \
  X("icc",           0, 0, "once", 0.5, discrete , ball_factor, make_icc_estimator,                           \
    "interpolated corrected curvature measures, 1-ring or ball (Lachaud et al. 2020)")           \
  X("apss",          0, 0, "once", 4.5, point_set, half_rings , make_apss_estimator,                 \
    "algebraic sphere fit on points and normals (Guennebaud and Gross 2007)")                     \
  X("surface-variation", 0, 0, "once", 1.6, point_set, half_rings, make_surface_variation_estimator, \
    "PCA normal; PCL's surface variation in the H column: NOT a curvature (Pauly et al. 2002)")
// clang-format on

namespace curvbench {

#define CURVBENCH_DECLARE_FACTORY(name, lo, hi, bench, cost, group, radius, factory, summary) \
  std::unique_ptr<Estimator> factory(EstimatorOptions options);
CURVBENCH_ESTIMATORS(CURVBENCH_DECLARE_FACTORY)
#undef CURVBENCH_DECLARE_FACTORY

namespace {

// make bench's degrees of a registry line: "2-4", "2", "once" (a degree-free method) or "none".
std::vector<int> bench_degrees(const std::string& bench) {
  if (bench == "none") return {};
  if (bench == "once") return {0};
  const int lo = bench[0] - '0';
  const int hi = bench.size() > 2 ? bench[2] - '0' : lo;
  std::vector<int> out;
  for (int d = lo; d <= hi; ++d) out.push_back(d);
  return out;
}

struct Registration {
  MethodInfo info;
  EstimatorFactory make;
};

// The registry: the lines of CURVBENCH_ESTIMATORS, then any register_estimator() additions.
std::vector<Registration>& registry() {
#define CURVBENCH_REGISTER(name, lo, hi, bench, cost, group, radius, factory, summary) \
  Registration{{name, lo, hi, bench_degrees(bench), cost, summary, MethodGroup::group, \
                NeighbourhoodSize::radius},                                            \
               &factory},
  static std::vector<Registration> table = {CURVBENCH_ESTIMATORS(CURVBENCH_REGISTER)};
#undef CURVBENCH_REGISTER
  return table;
}

std::string valid_names() {
  std::string s;
  for (const Registration& r : registry()) s += (s.empty() ? "" : ", ") + r.info.name;
  return s;
}

const Registration* find(const std::string& name);

// Every option set away from its default must suit the method (methods/option_schema.h); the
// registry line says whether its neighbourhood is a ball (option ball-factor).
std::unique_ptr<Estimator> checked(std::unique_ptr<Estimator> est) {
  const Registration* r = find(est->name());
  const bool ball = r && r->info.radius == NeighbourhoodSize::ball_factor;
  check_options_apply(est->options(), {est->name(), est->takes_degree(), est->ring_fit(), ball});
  // The point neighbourhood serves the methods that read neighbours without faces only.
  if (est->options().neighbourhood.kind != PointNeighbourhood::Kind::none &&
      est->neighbourhood_use() != NeighbourhoodUse::neighbours)
    throw UsageError("neighbourhood applies to the methods that read neighbours without faces (" +
                     point_set_methods() + "), not to '" + est->name() + "'");
  return est;
}

const Registration* find(const std::string& name) {
  for (const Registration& r : registry())
    if (name == r.info.name) return &r;
  return nullptr;
}

}  // namespace

namespace {

// The registration make_estimator(name, options) builds from, with options.degree resolved as
// it builds it: the degree attached to the name ("LHF-2"), else options.degree, else a fit's
// default 2 (0 for a degree-free operator). Throws make_estimator's UsageErrors.
const Registration& resolve(const std::string& name, EstimatorOptions& options) {
  validate_options(options);  // the option table's ranges, with its messages, first
  std::string base = ascii_lower(name);
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
        if (!reg->info.is_fit())
          throw UsageError("method '" + reg->info.name +
                           "' takes no degree (it is not a polynomial fit): write '" +
                           reg->info.name + "', not '" + name + "'");
        const int degree = std::stoi(base.substr(dash + 1));
        if (options.degree != 0 && options.degree != degree)
          throw UsageError("method " + name + " names degree " + std::to_string(degree) +
                           " but degree is " + std::to_string(options.degree));
        options.degree = degree;
        validate_options(options);
        attached = true;
      }
    }
  }
  if (reg == nullptr)
    throw UsageError("unknown method '" + name + "' (valid: " + valid_names() +
                     ", optionally with the degree attached, e.g. LHF-2)");
  const MethodInfo& info = reg->info;
  if (!info.is_fit()) {
    if (options.degree != 0)
      throw UsageError("method '" + info.name + "' takes no degree (got degree " +
                       std::to_string(options.degree) + "; it is not a polynomial fit)");
    return *reg;
  }
  if (options.degree == 0 && !attached)
    options.degree = std::clamp(2, info.min_degree, info.max_degree);
  if (options.degree < info.min_degree || options.degree > info.max_degree) {
    const std::string range =
        info.min_degree == info.max_degree
            ? std::to_string(info.min_degree)
            : std::to_string(info.min_degree) + ".." + std::to_string(info.max_degree);
    throw UsageError("method '" + info.name + "' does not support degree " +
                     std::to_string(options.degree) + " (valid: " + range + ")");
  }
  return *reg;
}

}  // namespace

std::unique_ptr<Estimator> make_estimator(const std::string& name, EstimatorOptions options) {
  const Registration& reg = resolve(name, options);
  return checked(reg.make(options));
}

int estimator_degree(const std::string& name, EstimatorOptions options) {
  resolve(name, options);
  return options.degree;
}

void register_estimator(const MethodInfo& info, EstimatorFactory factory) {
  if (info.name.empty() || info.name != ascii_lower(info.name) || factory == nullptr ||
      info.name.find_first_of(" ,=\"#") != std::string::npos)
    throw UsageError(
        "register_estimator: a method needs a lower-case name without spaces, "
        "commas, '=', quotes or '#', and a factory");
  if (info.name == "external" || info.name == "all-operators")
    throw UsageError("register_estimator: '" + info.name + "' is a keyword of experiment files");
  if (find(info.name) != nullptr)
    throw UsageError("register_estimator: method '" + info.name + "' exists already");
  if (info.min_degree < 0 || info.min_degree > info.max_degree ||
      (info.min_degree == 0) != (info.max_degree == 0))
    throw UsageError("register_estimator: method '" + info.name +
                     "': degrees must be 0, 0 (an operator) or 1 <= min <= max");
  registry().push_back({info, factory});
}

std::string display_name(const MethodInfo& method) {
  EstimatorOptions o;
  if (method.is_fit()) o.degree = method.min_degree;
  return make_estimator(method.name, o)->display_name();
}

const char* radius_option(NeighbourhoodSize size) {
  switch (size) {
    case NeighbourhoodSize::half_rings:
    case NeighbourhoodSize::whole_rings:
      return "rings";
    case NeighbourhoodSize::ball_factor:
      return "ball-factor";
    case NeighbourhoodSize::fixed:
      return "";
  }
  return "";
}

const char* to_string(MethodGroup g) {
  switch (g) {
    case MethodGroup::paper_fit:
      return "paper fits";
    case MethodGroup::jet:
      return "jets";
    case MethodGroup::discrete:
      return "discrete operators";
    case MethodGroup::point_set:
      return "point-set estimators";
    case MethodGroup::outside:
      return "outside estimators";
  }
  return "outside estimators";
}

namespace {

// The registration of a name or of a fit's label "<name>-<degree>"; nullptr when none.
const Registration* find_label(const std::string& label) {
  const std::string base = ascii_lower(label);
  if (const Registration* r = find(base)) return r;
  const size_t dash = base.rfind('-');
  if (dash != std::string::npos && dash + 1 < base.size() &&
      std::all_of(base.begin() + static_cast<std::ptrdiff_t>(dash + 1), base.end(),
                  [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }))
    return find(base.substr(0, dash));
  return nullptr;
}

// The registration whose name or label starts a variant's label ("LHF-2 (1.5-ring)", "LHF-2
// rings=3", "ICC-ball2"): the longest name followed by '-' or ' '; nullptr when none.
const Registration* find_variant(const std::string& label) {
  if (const Registration* r = find_label(label.substr(0, label.find(' ')))) return r;
  const std::string base = ascii_lower(label);
  const Registration* best = nullptr;
  for (const Registration& r : registry()) {
    const std::string& n = r.info.name;
    if (base.size() > n.size() && base.compare(0, n.size(), n) == 0 &&
        (base[n.size()] == '-' || base[n.size()] == ' ') &&
        (best == nullptr || n.size() > best->info.name.size()))
      best = &r;
  }
  return best;
}

}  // namespace

const MethodInfo& method_info(const std::string& name_or_label) {
  if (const Registration* r = find_label(name_or_label)) return r->info;
  throw UsageError("unknown method '" + name_or_label + "' (valid: " + valid_names() + ")");
}

MethodGroup method_group(const std::string& label) {
  const Registration* r = find_variant(label);
  return r == nullptr ? MethodGroup::outside : r->info.group;
}

std::vector<MethodInfo> method_table() {
  std::vector<MethodInfo> out;
  for (const Registration& r : registry()) out.push_back(r.info);
  return out;
}

std::vector<std::string> method_labels(int lowest_degree, int highest_degree) {
  std::vector<std::string> out;
  for (const Registration& r : registry()) {
    const MethodInfo& m = r.info;
    if (!m.is_fit()) {
      out.push_back(m.name);
      continue;
    }
    for (int d = std::max(lowest_degree, m.min_degree); d <= std::min(highest_degree, m.max_degree);
         ++d)
      out.push_back(m.name + "-" + std::to_string(d));
  }
  return out;
}

std::vector<std::string> estimator_names() {
  std::vector<std::string> names;
  for (const Registration& r : registry()) names.push_back(r.info.name);
  return names;
}

bool scores_interior_only(const std::string& method) {
  try {
    return make_estimator(method, EstimatorOptions{})->scores_interior_only();
  } catch (const UsageError&) {
    return false;  // not a registered method
  }
}

}  // namespace curvbench
