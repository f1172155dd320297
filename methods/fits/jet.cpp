// Jet-d: CGAL's osculating jet fitting, CGAL::Monge_via_jet_fitting (Cazals & Pouget 2005), the
// reference the paper times against in §5.4.
//
// Per vertex v (degree d in 2..4, Monge degree 2):
//   neighbourhood: the same as LHF-d (ring_fit_estimator.h): r0 = options().rings or
//     default_ring(); adaptive: collect_at_least(v, r0, min_neighbours(d), 2 r0), else
//     collect(v, r0). If the ring then holds fewer than (d+1)(d+2)/2 points (centre included),
//     the minimum CGAL accepts, it grows by half rings until it does; if the component runs out
//     first the vertex fails.
//   points: the centre first (CGAL's origin), then the neighbours in discovery order; CGAL does
//     its own PCA frame, preconditioning and unweighted SVD least squares (no eq. 15 weights, no
//     safeguard, no rank-failure rule, no 128-point cap).
//   conventions: CGAL's Monge form is z = (k1 x^2 + k2 y^2)/2 + ... in the right-handed frame
//     (d_max, d_min, n), i.e. k = n . x_uu for its own normal n: the sign convention of
//     estimator.h. Its n comes from the PCA (arbitrary side), so it is made to agree with the
//     area-weighted vertex normal by Monge_form::comply_wrt_given_normal (n -> -n, k_i -> -k_i,
//     k1 <-> k2, d1 <-> d2), which keeps k1 >= k2 and (d1, d2, n) right-handed.
// Output: normal, k1 >= k2, d1, d2, H = (k1+k2)/2, K = k1 k2, degree = d, points = number of
// points fitted, ring = ring collected. Failure (too few points, non-finite result, an exception
// caught by estimate_mesh): status failed, every value NaN (vertex_result.h).
//
// Cost: the ring points go to a reused vector; CGAL allocates its matrices in every call (that
// is the reference's cost).
#include <CGAL/Eigen_svd.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/shape_operator.h"
#include "mesh/rings.h"
#include "methods/estimator.h"
#include "methods/local_frame.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

using JetKernel = CGAL::Simple_cartesian<double>;
using JetFitter = CGAL::Monge_via_jet_fitting<JetKernel, JetKernel, CGAL::Eigen_svd>;

constexpr int kJetMinDegree = 2;
constexpr int kJetMaxDegree = 4;

Vec3 to_vec(const JetKernel::Vector_3& v) {
  return Vec3(v.x(), v.y(), v.z());
}

struct JetWorkspace final : Workspace {
  explicit JetWorkspace(const Mesh& mesh) : rings(mesh) { points.reserve(256); }
  RingCollector rings;
  std::vector<JetKernel::Point_3> points;
  JetFitter fitter;
};

class JetEstimator final : public Estimator {
 public:
  explicit JetEstimator(EstimatorOptions options) : Estimator(options) {
    const EstimatorOptions& o = options_;
    if (o.degree < kJetMinDegree || o.degree > kJetMaxDegree)
      throw UsageError("jet: degree " + std::to_string(o.degree) +
                       " is not supported (valid: 2..4)");
    options_.rings = half_rings(o.rings, "jet");
  }

  std::string name() const override { return "jet"; }
  std::string display_name() const override { return "Jet"; }

  NeighbourhoodUse neighbourhood_use() const override { return NeighbourhoodUse::neighbours; }

  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const override {
    return std::make_unique<JetWorkspace>(mesh);
  }

  void estimate(const MeshContext& ctx, int v, Workspace& base,
                VertexEstimate& out) const override {
    auto& ws = static_cast<JetWorkspace&>(base);
    const Vec3 m0 = ctx.approx_normals.row(v).transpose();
    const int d = options_.degree;
    collect_neighbourhood(ctx, ws.rings, v);
    const size_t needed = static_cast<size_t>(num_coefficients(d));
    while (1 + ws.rings.neighbours().size() < needed && ws.rings.grow()) {
    }
    const double ring = ws.rings.ring();
    const int count = 1 + static_cast<int>(ws.rings.neighbours().size());
    if (static_cast<size_t>(count) < needed) {
      set_failed(ring, 0, out);
      return;
    }
    ws.points.clear();
    const auto add = [&](int w) {
      const Vec3 p = ctx.mesh.position(w);
      ws.points.emplace_back(p.x(), p.y(), p.z());
    };
    add(v);
    for (int w : ws.rings.neighbours()) add(w);

    JetFitter::Monge_form monge =
        ws.fitter(ws.points.begin(), ws.points.end(), static_cast<size_t>(d), 2);
    monge.comply_wrt_given_normal(JetKernel::Vector_3(m0.x(), m0.y(), m0.z()));
    Curvature c;
    c.normal = to_vec(monge.normal_direction());
    c.k1 = monge.principal_curvatures(0);
    c.k2 = monge.principal_curvatures(1);
    c.H = 0.5 * (c.k1 + c.k2);
    c.K = c.k1 * c.k2;
    c.d1 = to_vec(monge.maximal_principal_direction());
    c.d2 = to_vec(monge.minimal_principal_direction());
    if (!set_quantities(c, d, d, count, ring, out)) set_failed(ring, count, out);
  }
};

}  // namespace

std::unique_ptr<Estimator> make_jet_estimator(EstimatorOptions options) {
  return std::make_unique<JetEstimator>(options);
}

}  // namespace curvbench
