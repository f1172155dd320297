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
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

namespace curvbench {

namespace {

// Prim's frontier: the points not yet in the tree that an edge from it reaches, each with its
// key, the least (weight, parent) offered, in a binary min-heap by (weight, point).
class PrimFrontier {
 public:
  explicit PrimFrontier(int n)
      : slot_(static_cast<size_t>(n), -1),
        weight_(static_cast<size_t>(n)),
        parent_(static_cast<size_t>(n)) {}
  bool empty() const { return heap_.empty(); }
  /// The edge parent -> v of weight w: v's key becomes (w, parent) if that is less.
  void offer(int v, double w, int parent) {
    const size_t i = static_cast<size_t>(v);
    if (slot_[i] >= 0 && !(w < weight_[i] || (w == weight_[i] && parent < parent_[i]))) return;
    weight_[i] = w;
    parent_[i] = parent;
    if (slot_[i] < 0) {
      slot_[i] = static_cast<int>(heap_.size());
      heap_.push_back(v);
    }
    sift_up(slot_[i]);
  }
  /// Removes the least point; returns it and its parent.
  std::pair<int, int> pop() {
    const int v = heap_.front();
    slot_[static_cast<size_t>(v)] = -1;
    const int last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      place(0, last);
      sift_down(0);
    }
    return {v, parent_[static_cast<size_t>(v)]};
  }

 private:
  bool less(int a, int b) const {
    const double wa = weight_[static_cast<size_t>(a)], wb = weight_[static_cast<size_t>(b)];
    return wa < wb || (wa == wb && a < b);
  }
  void place(int s, int v) {
    heap_[static_cast<size_t>(s)] = v;
    slot_[static_cast<size_t>(v)] = s;
  }
  void sift_up(int s) {
    const int v = heap_[static_cast<size_t>(s)];
    while (s > 0) {
      const int up = (s - 1) / 2;
      if (!less(v, heap_[static_cast<size_t>(up)])) break;
      place(s, heap_[static_cast<size_t>(up)]);
      s = up;
    }
    place(s, v);
  }
  void sift_down(int s) {
    const int size = static_cast<int>(heap_.size());
    const int v = heap_[static_cast<size_t>(s)];
    for (;;) {
      int child = 2 * s + 1;
      if (child >= size) break;
      if (child + 1 < size &&
          less(heap_[static_cast<size_t>(child) + 1], heap_[static_cast<size_t>(child)]))
        ++child;
      if (!less(heap_[static_cast<size_t>(child)], v)) break;
      place(s, heap_[static_cast<size_t>(child)]);
      s = child;
    }
    place(s, v);
  }
  std::vector<int> heap_;  // points, a binary heap by (weight, point)
  std::vector<int> slot_;  // a point's place in heap_, -1 when not in it
  std::vector<double> weight_;
  std::vector<int> parent_;
};

}  // namespace

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
  // The symmetrised graph: each directed row edge in both directions (an edge in both rows is
  // listed twice, which changes nothing below).
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

  // Prim's algorithm per component from its lowest index. The next point is the one of least
  // (weight, point) over the edges from the tree, reached from its parent of least (weight,
  // parent), so that ties resolve the same way every time; each frontier point is held once and
  // its key lowered in place (an indexed heap: a heap of edges held 16 per point at 1.4 million
  // points and made this step 10x dearer than the neighbour search).
  PrimFrontier frontier(n);
  std::vector<unsigned char> done(static_cast<size_t>(n), 0);
  std::vector<int> members;
  int count = 0;
  for (int seed = 0; seed < n; ++seed) {
    if (done[static_cast<size_t>(seed)]) continue;
    ++count;
    members.clear();
    frontier.offer(seed, 0.0, seed);
    while (!frontier.empty()) {
      const auto [v, parent] = frontier.pop();
      done[static_cast<size_t>(v)] = 1;
      members.push_back(v);
      if (normals.row(v).dot(normals.row(parent)) < 0.0) normals.row(v) *= -1.0;
      for (auto e = off[static_cast<size_t>(v)]; e < off[static_cast<size_t>(v) + 1]; ++e) {
        const int w = adj[static_cast<size_t>(e)];
        if (done[static_cast<size_t>(w)]) continue;
        frontier.offer(w, 1.0 - std::abs(normals.row(v).dot(normals.row(w))), v);
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

// Steps 1-3 on the first kNormalNeighbours of each row of `nearest`.
PointNormals oriented_normals(const VertexMatrix& points, const PointRows& nearest, bool jet,
                              int threads) {
  const PointRows rows = first_of_rows(nearest, kNormalNeighbours);
  PointNormals out;
  std::vector<unsigned char> degenerate;
  out.normals = jet ? jet_normals(points, rows, threads, degenerate)
                    : pca_normals(points, rows, threads, degenerate);
  out.undetermined =
      orient_normals(points, rows, out.normals, std::move(degenerate), &out.components);
  return out;
}

}  // namespace

PointNormals oriented_pca_normals(const PointSearch& search, int threads) {
  return oriented_pca_normals(search.points(), knn_rows(search, kNormalNeighbours, threads),
                              threads);
}

PointNormals oriented_pca_normals(const VertexMatrix& points, const PointRows& nearest,
                                  int threads) {
  return oriented_normals(points, nearest, false, threads);
}

PointNormals oriented_jet_normals(const PointSearch& search, int threads) {
  return oriented_jet_normals(search.points(), knn_rows(search, kNormalNeighbours, threads),
                              threads);
}

PointNormals oriented_jet_normals(const VertexMatrix& points, const PointRows& nearest,
                                  int threads) {
  return oriented_normals(points, nearest, true, threads);
}

PointNormals given_point_normals(const VertexMatrix& points, const PointRows& nearest,
                                 const VertexMatrix& given, int threads) {
  const int n = static_cast<int>(points.rows());
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
    const VertexMatrix pca =
        pca_normals(points, first_of_rows(nearest, kNormalNeighbours), threads, degenerate);
    for (int i = 0; i < n; ++i)
      if (out.undetermined[static_cast<size_t>(i)]) out.normals.row(i) = pca.row(i);
  }
  return out;
}

}  // namespace curvbench
