// Jet-d: CGAL's osculating jet fitting, CGAL::Monge_via_jet_fitting (Cazals & Pouget 2005), the
// reference the paper times against in §5.4.
//
// Per vertex v (degree d in 2..4, Monge degree 2):
//   neighbourhood: the same as LHF-d (ring_fit_estimator.h): r0 = options().rings or
//     default_ring(); adaptive: collect_at_least(v, r0, min_neighbours(d), 2 r0), else
//     collect(v, r0). If the ring then holds fewer than (d+1)(d+2)/2 points (centre included),
//     the minimum CGAL accepts, it grows by half rings until it does; if the component runs out
//     first, the highest degree its points allow (degree 1 = a plane: the normal, k1 = k2 = 0,
//     status degree_reduced, as the ring fits' safeguard). Where the points of a whole small
//     component single out no plane (kFlatPca; a tetrahedron, an octahedron), CGAL's frame is
//     arbitrary and a normal it gives far from the mesh's is meaningless: degree 1 on the vertex
//     and its 1-ring instead; if that has no plane either (a regular tetrahedron), the vertex
//     normal m0 alone, status partial (failed only without one: an isolated vertex).
//   points: the centre first (CGAL's origin), then the neighbours in discovery order; CGAL does
//     its own PCA frame, preconditioning and unweighted SVD least squares (no eq. 15 weights, no
//     safeguard, no rank-failure rule, no 128-point cap).
//   conventions: CGAL's Monge form is z = (k1 x^2 + k2 y^2)/2 + ... in the right-handed frame
//     (d_max, d_min, n), i.e. k = n . x_uu for its own normal n: the sign convention of
//     estimator.h. Its n comes from the PCA (arbitrary side), so it is made to agree with the
//     area-weighted vertex normal by Monge_form::comply_wrt_given_normal (n -> -n, k_i -> -k_i,
//     k1 <-> k2, d1 <-> d2), which keeps k1 >= k2 and (d1, d2, n) right-handed.
// Output: normal, k1 >= k2, d1, d2, H = (k1+k2)/2, K = k1 k2, degree = d, points = number of
// points fitted, ring = ring collected. Failure (no plane, non-finite result, an exception caught
// by estimate_mesh): status failed, every value NaN (vertex_result.h).
//
// Cost: the ring points go to a reused vector; CGAL allocates its matrices in every call (that
// is the reference's cost).
#include <CGAL/Eigen_svd.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
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
// The points' PCA gives no tangent plane when its smallest eigenvalue is at least this fraction
// of the middle one (1 for the six vertices of an octahedron; about (r k)^2 for a ring of radius r
// on a surface of curvature k). Its frame is then arbitrary: the fit is refused where the normal
// it gives is more than 60 degrees from the mesh's vertex normal (the octahedron's turns by 90;
// at a cube's corner, where the PCA is flat too, a face's normal is 55 degrees away and kept).
constexpr double kFlatPca = 0.5;
constexpr double kMinNormalCosine = 0.5;

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
    collect_neighbourhood(ctx, ws.rings, v);
    while (static_cast<size_t>(1 + ws.rings.neighbours().size()) <
               static_cast<size_t>(num_coefficients(options_.degree)) &&
           ws.rings.grow()) {
    }
    // The component ran out first: the highest degree its points determine (>= 1).
    int d = options_.degree;
    while (d >= 1 && 1 + static_cast<int>(ws.rings.neighbours().size()) < num_coefficients(d)) --d;
    if (d < 1) {
      set_normal_only(m0, 1 + static_cast<int>(ws.rings.neighbours().size()), ws.rings.ring(), out);
      return;
    }
    const Fit first = fit(ctx, v, m0, ws, d, out);
    if (first == Fit::done) return;
    // No tangent plane from the points of a whole small closed surface (an octahedron's six
    // vertices: CGAL's PCA frame is arbitrary): the plane of the vertex and its 1-ring. Elsewhere
    // (the ring can still grow: a corner or a needle of a larger mesh) CGAL's answer stands.
    // (A point neighbourhood, ring 0, never grows: CGAL's answer stands there.)
    const bool whole_component =
        first == Fit::no_plane && ws.rings.ring() > 0.0 && !ws.rings.grow();
    if (first == Fit::no_plane && !whole_component) {
      collect_neighbourhood(ctx, ws.rings, v);
      while (static_cast<size_t>(1 + ws.rings.neighbours().size()) <
                 static_cast<size_t>(num_coefficients(d)) &&
             ws.rings.grow()) {
      }
      if (fit(ctx, v, m0, ws, d, out, false) == Fit::done) return;
    }
    if (whole_component) {
      ws.rings.collect_integer(v, 1);
      if (1 + ws.rings.neighbours().size() >= 3 && fit(ctx, v, m0, ws, 1, out) == Fit::done) return;
    }
    // No jet at all: the vertex normal the jet would have been oriented by, alone (status
    // partial, as the operators do where their fits are singular; failed without one).
    set_normal_only(m0, 1 + static_cast<int>(ws.rings.neighbours().size()), ws.rings.ring(), out);
  }

 private:
  enum class Fit { done, no_plane, not_finite };

  // CGAL's jet of degree d (Monge degree min(d, 2)) through v and the neighbours ws.rings holds.
  // no_plane (with check_plane) where the points' PCA does not single out a plane (the smallest
  // eigenvalue at least kFlatPca times the middle one) and the normal is far from m0; not_finite
  // if a value is not. Degree 1 gives the normal with k1 = k2 = 0 (a plane, as the ring fits'
  // degree reduction), status degree_reduced.
  Fit fit(const MeshContext& ctx, int v, const Vec3& m0, JetWorkspace& ws, int d,
          VertexEstimate& out, bool check_plane = true) const {
    ws.points.clear();
    const auto add = [&](int w) {
      const Vec3 p = ctx.mesh.position(w);
      ws.points.emplace_back(p.x(), p.y(), p.z());
    };
    add(v);
    for (int w : ws.rings.neighbours()) add(w);
    const auto count = static_cast<int>(ws.points.size());
    JetFitter::Monge_form monge =
        ws.fitter(ws.points.begin(), ws.points.end(), static_cast<size_t>(d),
                  static_cast<size_t>(std::min(d, 2)));
    monge.comply_wrt_given_normal(JetKernel::Vector_3(m0.x(), m0.y(), m0.z()));
    Curvature c;
    c.normal = to_vec(monge.normal_direction());
    const bool flat_pca = !(ws.fitter.pca_basis(2).first < kFlatPca * ws.fitter.pca_basis(1).first);
    if (check_plane && flat_pca && !(c.normal.dot(m0) >= kMinNormalCosine)) return Fit::no_plane;
    c.k1 = d >= 2 ? monge.principal_curvatures(0) : 0.0;
    c.k2 = d >= 2 ? monge.principal_curvatures(1) : 0.0;
    c.H = 0.5 * (c.k1 + c.k2);
    c.K = c.k1 * c.k2;
    c.d1 = to_vec(monge.maximal_principal_direction());
    c.d2 = to_vec(monge.minimal_principal_direction());
    return set_quantities(c, d, options_.degree, count, ws.rings.ring(), out) ? Fit::done
                                                                              : Fit::not_finite;
  }
};

}  // namespace

std::unique_ptr<Estimator> make_jet_estimator(EstimatorOptions options) {
  return std::make_unique<JetEstimator>(options);
}

}  // namespace curvbench
