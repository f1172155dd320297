// Surface variation (M. Pauly, M. Gross, L. Kobbelt, "Efficient simplification of point-sampled
// surfaces", IEEE Visualization 2002, §2; the `curvature` of PCL's NormalEstimation):
// sigma = lambda0 / (lambda0 + lambda1 + lambda2), lambda0 <= lambda1 <= lambda2 the eigenvalues
// of the covariance of the neighbourhood about its centroid. Degree-free; label "SurfVar".
//
// sigma is NOT a curvature: it is unitless, unsigned (0 <= sigma <= 1/3, 0 on a plane), and on a
// smooth surface it grows like (h kappa)^2 with the neighbourhood's size h, so it tends to 0 under
// refinement whatever the surface. It is reported in the H column only so that the harness scores
// it against the exact H and shows what it is; no other curvature is given.
//
// Per vertex v:
//   neighbourhood  collect_neighbourhood (the rings of option `rings`, default 2; on a point set
//                  the k-NN table that serves collect_neighbourhood), the centre included, every
//                  point with weight 1 (PCL's computePointNormal)
//   normal         the eigenvector of lambda0 (the PCA normal, Hoppe et al. 1992), turned to the
//                  side of the vertex's input normal (MeshContext::approx_normals, or option
//                  vertex-normals): PCL orients towards a viewpoint instead
//   H column       sigma
// computes(): normal and H only. Fewer than 3 points, or all points coincident: status failed. No
// input normal at the vertex (no faces): status sign_undetermined (the normal's sign arbitrary).
#include <Eigen/Eigenvalues>
#include <cmath>
#include <memory>
#include <string>

#include "core/shape_operator.h"
#include "mesh/rings.h"
#include "methods/operators/operator_estimator.h"
#include "methods/vertex_result.h"

namespace curvbench {

namespace {

constexpr double kDefaultRing = 2.0;

struct SurfaceVariationWorkspace final : Workspace {
  explicit SurfaceVariationWorkspace(const Mesh& mesh) : rings(mesh) {}
  RingCollector rings;
};

class SurfaceVariationEstimator final : public OperatorEstimator {
 public:
  explicit SurfaceVariationEstimator(EstimatorOptions options)
      : OperatorEstimator(options, VertexNormals::area, /*ring_option=*/true) {
    options_.rings = half_rings(options_.rings, "surface-variation");
  }

  std::string name() const override { return "surface-variation"; }
  std::string display_name() const override { return "SurfVar"; }
  double default_ring() const override { return kDefaultRing; }
  NeighbourhoodUse neighbourhood_use() const override { return NeighbourhoodUse::neighbours; }
  ComputedQuantities computes() const override {
    return {
        .normal = true, .principal = false, .mean = true, .gaussian = false, .directions = false};
  }

  std::unique_ptr<Workspace> make_workspace(const Mesh& mesh) const override {
    return std::make_unique<SurfaceVariationWorkspace>(mesh);
  }

  void estimate(const MeshContext& ctx, int v, Workspace& base,
                VertexEstimate& out) const override {
    auto& ws = static_cast<SurfaceVariationWorkspace&>(base);
    const double ring = collect_neighbourhood(ctx, ws.rings, v);
    const auto nb = ws.rings.neighbours();
    const int points = 1 + static_cast<int>(nb.size());
    if (points < 3) {
      set_failed(ring, points, out);
      return;
    }
    // Covariance about the centroid, with the coordinates relative to the vertex (rounding).
    const Vec3 x0 = ctx.mesh.position(v);
    Vec3 sum = Vec3::Zero();
    Mat3 second = Mat3::Zero();
    for (int w : nb) {
      const Vec3 d = ctx.mesh.position(w) - x0;
      sum += d;
      second += d * d.transpose();
    }
    const Vec3 mean = sum / points;  // the centre adds d = 0
    const Mat3 cov = second / points - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(cov);
    const Vec3 lambda = eig.eigenvalues().cwiseMax(0.0);  // increasing
    const double total = lambda.sum();
    if (eig.info() != Eigen::Success || !(total > 0.0)) {
      set_failed(ring, points, out);
      return;
    }
    Curvature c;
    c.normal = eig.eigenvectors().col(0);
    const Vec3 side = mesh_data(ctx).normal(ctx, v);
    const double agree = c.normal.dot(side);
    if (agree < 0.0) c.normal = -c.normal;
    c.H = lambda(0) / total;
    // Without an input normal to turn it by, the PCA normal's sign is arbitrary: said so.
    if (set_operator_quantities(c, computes(), points, ring, out) && !(std::abs(agree) > 0.0))
      out.status = VertexStatus::sign_undetermined;
  }
};

}  // namespace

std::unique_ptr<Estimator> make_surface_variation_estimator(EstimatorOptions options) {
  return std::make_unique<SurfaceVariationEstimator>(options);
}

}  // namespace curvbench
