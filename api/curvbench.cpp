// The public C++ API (include/curvbench/curvbench.h) over the library's layers.
#include "curvbench/curvbench.h"

#include <cmath>
#include <utility>

#include "api/make_api_estimator.h"
#include "core/text.h"
#include "curvbench/version.h"
#include "harness/model/metrics.h"
#include "harness/model/score.h"
#include "harness/report/recommend_table.h"
#include "mesh/io.h"
#include "mesh/mesh.h"
#include "meshgen/generate.h"
#include "methods/estimate_oriented.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"

namespace curvbench {

namespace {

Mesh to_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  if (V.cols() != 3)
    throw InputError("V: expected n x 3 vertex positions, got " + std::to_string(V.rows()) + " x " +
                     std::to_string(V.cols()));
  if (F.cols() != 3)
    throw InputError("F: expected m x 3 triangle indices, got " + std::to_string(F.rows()) + " x " +
                     std::to_string(F.cols()));
  return Mesh(VertexMatrix(V), FaceMatrix(F), "mesh");
}

MeshAdvice mesh_advice(const Advice& a) {
  MeshAdvice r;
  r.quality = a.mesh_class.quality;
  r.quality_reason = a.mesh_class.reason;
  r.sigma_over_h = a.sigma_over_h;
  r.noise_estimated = a.noise_estimated;
  r.noise_level = a.noise_level;
  r.swept = a.has_choice;
  r.table = a.table;
  r.provenance = a.provenance;
  if (!a.has_choice) return r;
  r.method = a.choice.method;
  r.parameter = a.choice.parameter;
  r.radius = a.choice.radius;
  r.label = a.label;
  r.quantity = a.quantity;
  r.norm = a.norm;
  r.error = a.error;
  r.experiment = a.experiment;
  r.family = a.family;
  r.level = a.level;
  if (!a.has_feature_advice) return r;
  const QuantityAdvice& normals = a.quantities.front();
  if (normals.pick.found) {
    r.normal_method = normals.choice.method;
    r.normal_parameter = normals.choice.parameter;
    r.normal_radius = normals.choice.radius;
    r.normal_label = normals.pick.label;
  }
  const QuantityAdvice& curvature = a.quantities.back();
  r.error_low = curvature.lowest_error;
  r.error_high = curvature.highest_error;
  r.regret_median = curvature.validated.median;
  r.regret_worst = curvature.validated.worst;
  for (const FeatureOutOfRange& o : a.out_of_range) r.out_of_range.push_back(o.name);
  if (!a.has_measured) return r;
  // Measured on the mesh (measure_on_mesh: each quantity has a choice): no swept mesh's error
  // range stands behind it.
  r.measured = true;
  const MeasuredQuantity& normal = a.measured.advice.quantities.front();
  const EstimatorChoice& c = a.measured.candidates[static_cast<size_t>(normal.chosen)];
  r.normal_method = c.method;
  r.normal_parameter = c.parameter;
  r.normal_radius = c.radius;
  r.normal_label = c.label;
  r.normal_predicted = normal.cases[static_cast<size_t>(normal.chosen)].predicted;
  r.error_low = r.error_high = MeshAdvice::kNaN;
  r.regret_median = a.measured.validated.back().median;
  r.regret_worst = a.measured.validated.back().worst;
  return r;
}

// The estimates as the harness's metrics read them.
std::vector<VertexEstimate> vertex_estimates(const EstimateResult& r) {
  std::vector<VertexEstimate> out(r.status.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    VertexEstimate& e = out[i];
    e.normal = r.normal.row(k).transpose();
    e.k1 = r.k1(k);
    e.k2 = r.k2(k);
    e.H = r.H(k);
    e.K = r.K(k);
    e.d1 = r.d1.row(k).transpose();
    e.d2 = r.d2.row(k).transpose();
    e.degree = r.degree(k);
    e.points = r.points(k);
    e.ring = r.ring(k);
    e.status = r.status[i];
  }
  return out;
}

std::vector<SurfacePoint> surface_points(const ExactQuantities& x) {
  std::vector<SurfacePoint> out(x.umbilic.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    SurfacePoint& p = out[i];
    p.point = x.point.row(k).transpose();
    p.normal = x.normal.row(k).transpose();
    p.k1 = x.k1(k);
    p.k2 = x.k2(k);
    p.H = x.H(k);
    p.K = x.K(k);
    p.d1 = x.d1.row(k).transpose();
    p.d2 = x.d2.row(k).transpose();
    p.umbilic = x.umbilic[i];
  }
  return out;
}

const char* type_name(OptionType t) {
  switch (t) {
    case OptionType::boolean:
      return "bool";
    case OptionType::integer:
      return "int";
    case OptionType::real:
      return "double";
    case OptionType::choice:
      return "choice";
    case OptionType::text:
      return "text";
  }
  return "choice";
}

}  // namespace

const char* status_name(Status status) {
  return to_string(status);
}

EstimateResult estimate(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                        const EstimateOptions& options) {
  // Method "auto": the estimator of the advice for the mesh, chosen once the mesh is made.
  const bool automatic = is_auto_method(options.method);
  std::unique_ptr<Estimator> est = automatic ? nullptr : make_api_estimator(options);
  Mesh mesh = to_mesh(V, F);
  EstimateResult out;
  if (automatic) {
    const RecommendationTable table = default_recommendations();
    const std::optional<AdviceTable> cases = advice_cases_beside(table.name);
    const Advice advice = advise(mesh, std::nan(""), table, cases ? &*cases : nullptr);
    if (!advice.has_choice)
      throw InputError(advice.table + ": no sweep ran for " + advice.mesh_class.quality +
                       " meshes at sigma/h " + format_g(advice.noise_level) +
                       ", so method='auto' has no choice; name the method");
    EstimateOptions chosen;
    static_cast<EstimatorOptions&>(chosen) = auto_options(advice.choice, options, true);
    chosen.method = advice.choice.method;
    est = make_api_estimator(chosen);
    out.recommendation = mesh_advice(advice);
  }
  const std::vector<VertexEstimate> res = estimate_oriented(std::move(mesh), *est).estimates;
  const Eigen::Index n = static_cast<Eigen::Index>(res.size());
  out.method = est->label();
  out.normal.resize(n, 3);
  out.d1.resize(n, 3);
  out.d2.resize(n, 3);
  out.k1.resize(n);
  out.k2.resize(n);
  out.H.resize(n);
  out.K.resize(n);
  out.degree.resize(n);
  out.points.resize(n);
  out.ring.resize(n);
  out.status.resize(res.size());
  for (Eigen::Index i = 0; i < n; ++i) {
    const VertexEstimate& e = res[static_cast<size_t>(i)];
    out.normal.row(i) = e.normal.transpose();
    out.d1.row(i) = e.d1.transpose();
    out.d2.row(i) = e.d2.transpose();
    out.k1(i) = e.k1;
    out.k2(i) = e.k2;
    out.H(i) = e.H;
    out.K(i) = e.K;
    out.degree(i) = e.degree;
    out.points(i) = e.points;
    out.ring(i) = e.ring;
    out.status[static_cast<size_t>(i)] = e.status;
  }
  return out;
}

EstimateResult estimate(const Eigen::MatrixXd& V, const EstimateOptions& options) {
  return estimate(V, Eigen::MatrixXi(0, 3), options);
}

void read_mesh(const std::string& path, Eigen::MatrixXd& V, Eigen::MatrixXi& F,
               std::vector<std::string>* warnings) {
  MeshReadReport report;
  const Mesh mesh = read_mesh(path, &report);
  V = mesh.vertices();
  F = mesh.faces();
  if (warnings) *warnings = read_warnings(path, report);
}

MeshAdvice recommend(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                     const RecommendOptions& options) {
  const RecommendationTable table = options.results.empty()
                                        ? default_recommendations()
                                        : read_recommendations_csv(options.results);
  const std::optional<AdviceTable> cases = advice_cases_beside(table.name);
  const Mesh mesh = to_mesh(V, F);
  Advice a = advise(mesh, options.noise, table, cases ? &*cases : nullptr);
  if (options.measure) measure_on_mesh(a, mesh, cases ? &*cases : nullptr, options.threads);
  return mesh_advice(a);
}

TestMesh generate_mesh(const TestMeshOptions& options) {
  MeshSpec spec;
  spec.family = options.family;
  spec.level = options.level;
  spec.noise_order = options.noise_order;
  spec.seed = options.seed;
  for (const auto& [name, value] : options.shape) set_mesh_option(spec.shape, name, value);
  const GeneratedMesh g = generate_mesh(spec);
  const int n = g.mesh.num_vertices();
  TestMesh out;
  out.V = g.mesh.vertices();
  out.F = g.mesh.faces();
  out.surface = g.surface->name();
  out.description = g.description;
  ExactQuantities& x = out.exact;
  x.point.resize(n, 3);
  x.normal.resize(n, 3);
  x.d1.resize(n, 3);
  x.d2.resize(n, 3);
  x.k1.resize(n);
  x.k2.resize(n);
  x.H.resize(n);
  x.K.resize(n);
  x.umbilic.resize(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) {
    const SurfacePoint p = g.surface->evaluate(g.exact_points.row(v).transpose());
    x.point.row(v) = p.point.transpose();
    x.normal.row(v) = p.normal.transpose();
    x.d1.row(v) = p.d1.transpose();
    x.d2.row(v) = p.d2.transpose();
    x.k1(v) = p.k1;
    x.k2(v) = p.k2;
    x.H(v) = p.H;
    x.K(v) = p.K;
    x.umbilic[static_cast<size_t>(v)] = p.umbilic;
  }
  return out;
}

std::vector<MeshOptionDescription> mesh_options() {
  std::vector<MeshOptionDescription> out;
  for (const MeshOptionInfo& o : mesh_option_table())
    out.push_back({o.name, o.default_value, o.help});
  return out;
}

std::vector<QuantityError> score(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                 const ExactQuantities& exact, const EstimateResult& estimate,
                                 const std::string& vertex_set) {
  const VertexSet set = parse_vertex_set(vertex_set);
  const Mesh mesh = to_mesh(V, F);
  const size_t n = static_cast<size_t>(mesh.num_vertices());
  if (estimate.status.size() != n || exact.umbilic.size() != n)
    throw InputError("score: the estimate has " + std::to_string(estimate.status.size()) +
                     " vertices, the exact answer " + std::to_string(exact.umbilic.size()) +
                     ", the mesh " + std::to_string(n));
  static constexpr Quantity kAll[] = {Quantity::normal, Quantity::H,  Quantity::K,
                                      Quantity::k1,     Quantity::k2, Quantity::d1};
  const ScoreResult r =
      score_estimates(mesh, surface_points(exact), vertex_estimates(estimate), kAll, set);
  std::vector<QuantityError> out;
  for (const QuantityScore& s : r.scores)
    out.push_back({to_string(s.quantity), s.l2.value, s.linf.value, s.l2.vertices, s.l2.excluded});
  return out;
}

std::vector<OptionDescription> estimator_options() {
  std::vector<OptionDescription> out;
  for (const OptionInfo& o : estimator_option_schema())
    out.push_back({o.name, o.python_name, type_name(o.type), o.default_text, o.help});
  return out;
}

void set_estimator_option(EstimatorOptions& options, const std::string& name,
                          const OptionValue& value) {
  set_option_value(options, name, value);
}

std::vector<std::string> methods() {
  return estimator_names();
}

std::string version() {
  return kVersion;
}

}  // namespace curvbench
