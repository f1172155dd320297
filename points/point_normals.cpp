// PCA and jet normals, their orientation over the neighbour graph, and given normals; see
// point_normals.h.
#include "points/point_normals.h"

#include <CGAL/Eigen_svd.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <tuple>

#include <Eigen/Eigenvalues>

namespace curvbench {

VertexMatrix pca_normals(const VertexMatrix& points, const PointRows& rows, int threads,
                         std::vector<unsigned char>& degenerate) {
  const int n = static_cast<int>(points.rows());
  VertexMatrix normals(n, 3);
  degenerate.assign(static_cast<size_t>(n), 0);
  if (threads <= 0) threads = 1;
#pragma omp parallel for num_threads(threads) schedule(static)
  for (int i = 0; i < n; ++i) {
    const auto b = rows.offsets[static_cast<size_t>(i)];
    const auto e = rows.offsets[static_cast<size_t>(i) + 1];
    const Vec3 p0 = points.row(i).transpose();
    Vec3 mean = Vec3::Zero();
    for (auto j = b; j < e; ++j)
      mean += points.row(rows.neighbours[static_cast<size_t>(j)]).transpose() - p0;
    mean /= static_cast<double>(e - b + 1);  // the centre is the first point (offset 0)
    Mat3 cov = mean * mean.transpose();
    for (auto j = b; j < e; ++j) {
      const Vec3 d = points.row(rows.neighbours[static_cast<size_t>(j)]).transpose() - p0 - mean;
      cov += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(cov);
    const Vec3 lambda = eig.eigenvalues();  // increasing
    normals.row(i) = eig.eigenvectors().col(0).transpose();
    if (e - b < 2 || !(lambda(1) > 1e-12 * lambda(2)) || !normals.row(i).allFinite()) {
      degenerate[static_cast<size_t>(i)] = 1;
      if (!normals.row(i).allFinite()) normals.row(i) = Vec3::UnitZ().transpose();
    }
  }
  return normals;
}

std::vector<unsigned char> orient_normals(const VertexMatrix& points, const PointRows& rows,
                                          VertexMatrix& normals,
                                          std::vector<unsigned char> degenerate, int* components) {
  const int n = static_cast<int>(points.rows());
  // The symmetrised graph: each directed row edge in both directions, deduplicated per row.
  std::vector<std::int64_t> off(static_cast<size_t>(n) + 1, 0);
  for (int i = 0; i < n; ++i)
    for (auto j = rows.offsets[static_cast<size_t>(i)];
         j < rows.offsets[static_cast<size_t>(i) + 1]; ++j) {
      ++off[static_cast<size_t>(i) + 1];
      ++off[static_cast<size_t>(rows.neighbours[static_cast<size_t>(j)]) + 1];
    }
  for (size_t i = 0; i < static_cast<size_t>(n); ++i) off[i + 1] += off[i];
  std::vector<int> adj(static_cast<size_t>(off.back()));
  {
    std::vector<std::int64_t> cursor(off.begin(), off.end() - 1);
    for (int i = 0; i < n; ++i)
      for (auto j = rows.offsets[static_cast<size_t>(i)];
           j < rows.offsets[static_cast<size_t>(i) + 1]; ++j) {
        const int w = rows.neighbours[static_cast<size_t>(j)];
        adj[static_cast<size_t>(cursor[static_cast<size_t>(i)]++)] = w;
        adj[static_cast<size_t>(cursor[static_cast<size_t>(w)]++)] = i;
      }
  }

  // Prim's algorithm per component from its lowest index; the queue orders by (weight, point,
  // parent), so that ties resolve the same way every time.
  using Item = std::tuple<double, int, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  std::vector<unsigned char> done(static_cast<size_t>(n), 0);
  std::vector<int> members;
  int count = 0;
  for (int seed = 0; seed < n; ++seed) {
    if (done[static_cast<size_t>(seed)]) continue;
    ++count;
    members.clear();
    queue.emplace(0.0, seed, seed);
    while (!queue.empty()) {
      const auto [weight, v, parent] = queue.top();
      queue.pop();
      (void)weight;
      if (done[static_cast<size_t>(v)]) continue;
      done[static_cast<size_t>(v)] = 1;
      members.push_back(v);
      if (normals.row(v).dot(normals.row(parent)) < 0.0) normals.row(v) *= -1.0;
      for (auto e = off[static_cast<size_t>(v)]; e < off[static_cast<size_t>(v) + 1]; ++e) {
        const int w = adj[static_cast<size_t>(e)];
        if (done[static_cast<size_t>(w)]) continue;
        queue.emplace(1.0 - std::abs(normals.row(v).dot(normals.row(w))), w, v);
      }
    }
    // The global rule of the component (point_normals.h).
    Vec3 centroid = Vec3::Zero(), sum_n = Vec3::Zero();
    for (const int v : members) {
      centroid += points.row(v).transpose();
      sum_n += normals.row(v).transpose();
    }
    const double size = static_cast<double>(members.size());
    centroid /= size;
    const Vec3 mean_n = sum_n / size;
    double sign = 0.0;
    if (mean_n.norm() < kOpenMean) {
      double flux = 0.0, spread = 0.0;
      for (const int v : members) {
        const Vec3 d = points.row(v).transpose() - centroid;
        flux += normals.row(v).dot(d);
        spread += d.norm();
      }
      if (std::abs(flux) >= kClosedMargin * spread && spread > 0.0) sign = flux > 0.0 ? 1.0 : -1.0;
    } else if (std::abs(mean_n.z()) >= kUpMargin) {
      sign = mean_n.z() > 0.0 ? 1.0 : -1.0;
    }
    for (const int v : members) {
      if (sign < 0.0) normals.row(v) *= -1.0;
      if (sign == 0.0 || members.size() < 3) degenerate[static_cast<size_t>(v)] = 1;
    }
  }
  if (components != nullptr) *components = count;
  return degenerate;
}

VertexMatrix jet_normals(const VertexMatrix& points, const PointRows& rows, int threads,
                         std::vector<unsigned char>& degenerate) {
  using Kernel = CGAL::Simple_cartesian<double>;
  using Fitting = CGAL::Monge_via_jet_fitting<Kernel, Kernel, CGAL::Eigen_svd>;
  constexpr int kDegree = 2;  // CGAL::jet_estimate_normals' default degree_fitting
  constexpr int kMinPoints = (kDegree + 1) * (kDegree + 2) / 2;
  VertexMatrix normals = pca_normals(points, rows, threads, degenerate);
  const int n = static_cast<int>(points.rows());
  if (threads <= 0) threads = 1;
#pragma omp parallel for num_threads(threads) schedule(static)
  for (int i = 0; i < n; ++i) {
    const auto b = rows.offsets[static_cast<size_t>(i)];
    const auto e = rows.offsets[static_cast<size_t>(i) + 1];
    if (degenerate[static_cast<size_t>(i)]) continue;
    if (e - b + 1 < kMinPoints) {
      degenerate[static_cast<size_t>(i)] = 1;
      continue;
    }
    std::vector<Kernel::Point_3> fit_points;
    fit_points.reserve(static_cast<size_t>(e - b + 1));
    const auto point = [&](int v) {
      return Kernel::Point_3(points(v, 0), points(v, 1), points(v, 2));
    };
    fit_points.push_back(point(i));
    for (auto j = b; j < e; ++j)
      fit_points.push_back(point(rows.neighbours[static_cast<size_t>(j)]));
    Vec3 normal = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    try {
      Fitting fitting;
      const Fitting::Monge_form form =
          fitting(fit_points.begin(), fit_points.end(), kDegree, /*monge degree*/ 1);
      const Kernel::Vector_3 m = form.normal_direction();
      normal = Vec3(m.x(), m.y(), m.z());
    } catch (...) {  // a CGAL precondition (checked builds): the point keeps its PCA normal
    }
    if (normal.allFinite() && normal.norm() > 0.0)
      normals.row(i) = normal.normalized().transpose();
    else
      degenerate[static_cast<size_t>(i)] = 1;
  }
  return normals;
}

namespace {

PointNormals oriented_normals(const PointSearch& search, bool jet, int threads) {
  PointNormals out;
  const PointRows rows = knn_rows(search, kNormalNeighbours, threads);
  std::vector<unsigned char> degenerate;
  out.normals = jet ? jet_normals(search.points(), rows, threads, degenerate)
                    : pca_normals(search.points(), rows, threads, degenerate);
  out.undetermined =
      orient_normals(search.points(), rows, out.normals, std::move(degenerate), &out.components);
  return out;
}

}  // namespace

PointNormals oriented_pca_normals(const PointSearch& search, int threads) {
  return oriented_normals(search, false, threads);
}

PointNormals oriented_jet_normals(const PointSearch& search, int threads) {
  return oriented_normals(search, true, threads);
}

PointNormals given_point_normals(const PointSearch& search, const VertexMatrix& given,
                                 int threads) {
  const int n = search.num_points();
  PointNormals out;
  out.normals.resize(n, 3);
  out.undetermined.assign(static_cast<size_t>(n), 0);
  bool any_bad = false;
  for (int i = 0; i < n; ++i) {
    const Vec3 g = given.row(i).transpose();
    const double length = g.norm();
    if (std::isfinite(length) && length > 0.0) {
      out.normals.row(i) = (g / length).transpose();
    } else {
      out.undetermined[static_cast<size_t>(i)] = 1;
      any_bad = true;
    }
  }
  if (any_bad) {  // a stand-in frame for the fits: the unoriented PCA normal
    std::vector<unsigned char> degenerate;
    const VertexMatrix pca = pca_normals(
        search.points(), knn_rows(search, kNormalNeighbours, threads), threads, degenerate);
    for (int i = 0; i < n; ++i)
      if (out.undetermined[static_cast<size_t>(i)]) out.normals.row(i) = pca.row(i);
  }
  return out;
}

}  // namespace curvbench
