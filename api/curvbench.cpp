// The public C++ API (include/curvbench/curvbench.h) over the library's layers.
#include "curvbench/curvbench.h"

#include <utility>

#include "api/make_api_estimator.h"
#include "curvbench/version.h"
#include "mesh/io.h"
#include "mesh/mesh.h"
#include "methods/estimate_oriented.h"
#include "methods/estimator.h"

namespace curvbench {

const char* status_name(Status status) {
  return to_string(static_cast<VertexStatus>(status));
}

EstimateResult estimate(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                        const EstimateOptions& options) {
  if (V.cols() != 3)
    throw InputError("V: expected n x 3 vertex positions, got " + std::to_string(V.rows()) + " x " +
                     std::to_string(V.cols()));
  if (F.cols() != 3)
    throw InputError("F: expected m x 3 triangle indices, got " + std::to_string(F.rows()) + " x " +
                     std::to_string(F.cols()));
  const std::unique_ptr<Estimator> est = make_api_estimator(options);
  Mesh mesh(VertexMatrix(V), FaceMatrix(F), "mesh");
  const std::vector<VertexEstimate> res = estimate_oriented(std::move(mesh), *est).estimates;
  const Eigen::Index n = static_cast<Eigen::Index>(res.size());
  EstimateResult out;
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
    out.status[static_cast<size_t>(i)] = static_cast<Status>(e.status);
  }
  return out;
}

EstimateResult estimate(const Eigen::MatrixXd& V, const EstimateOptions& options) {
  return estimate(V, Eigen::MatrixXi(0, 3), options);
}

void read_mesh(const std::string& path, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  const Mesh mesh = read_mesh(path);
  V = mesh.vertices();
  F = mesh.faces();
}

std::vector<std::string> methods() {
  return estimator_names();
}

std::string version() {
  return kVersion;
}

}  // namespace curvbench
