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

// Prim's frontier: the points not yet in the tree that an edge from it reaches, each once with
// its key, the least (weight, parent) offered, in a 4-ary min-heap by (weight, point). The heap's
// entries carry their keys, so that a point's own record is only its place in the heap (4 bytes
// a point, and the sifts read the small heap alone); the least of four children is picked
// without branches, and a pop sinks the hole to a leaf before the last entry rises into it.
class PrimFrontier {
 public:
  explicit PrimFrontier(int n) : slot_(static_cast<size_t>(n), kFree) {}
  bool empty() const { return heap_.empty(); }
  bool done(int v) const { return slot_[static_cast<size_t>(v)] == kDone; }
  /// The edge parent -> v of weight w, v not in the tree: v's key becomes (w, parent) if that
  /// is less.
  void offer(int v, double w, int parent) {
    const int s = slot_[static_cast<size_t>(v)];
    if (s < 0) {
      heap_.push_back({w, v, parent});
      sift_up(static_cast<int>(heap_.size()) - 1, {w, v, parent});
      return;
    }
    const Entry& key = heap_[static_cast<size_t>(s)];
    if (w < key.weight || (w == key.weight && parent < key.parent)) sift_up(s, {w, v, parent});
  }
  /// Removes the least point and marks it done; returns it and its parent.
  std::pair<int, int> pop() {
    const Entry top = heap_.front();
    slot_[static_cast<size_t>(top.point)] = kDone;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) sift_down(last);
    return {top.point, top.parent};
  }

 private:
  static constexpr int kFree = -1, kDone = -2;  // slot of a point never reached / in the tree
  static constexpr int kArity = 4;
  struct Entry {
    double weight;
    int point;
    int parent;
  };
  static bool less(const Entry& a, const Entry& b) {  // by (weight, point), without branches
    return static_cast<bool>(
        static_cast<int>(a.weight < b.weight) |
        (static_cast<int>(a.weight == b.weight) & static_cast<int>(a.point < b.point)));
  }
  const Entry& at(int s) const { return heap_[static_cast<size_t>(s)]; }
  void place(int s, const Entry& e) {
    heap_[static_cast<size_t>(s)] = e;
    slot_[static_cast<size_t>(e.point)] = s;
  }
  void sift_up(int s, const Entry& e) {
    while (s > 0) {
      const int up = (s - 1) / kArity;
      if (!less(e, at(up))) break;
      place(s, at(up));
      s = up;
    }
    place(s, e);
  }
  // The root's hole down to a leaf along the least children, then e up from there.
  void sift_down(const Entry& e) {
    const int size = static_cast<int>(heap_.size());
    int s = 0;
    for (;;) {
      const int first = kArity * s + 1;
      if (first >= size) break;
      int least = first;
      if (first + kArity <= size) {
        const int a = first + static_cast<int>(less(at(first + 1), at(first)));
        const int b = first + 2 + static_cast<int>(less(at(first + 3), at(first + 2)));
        least = less(at(b), at(a)) ? b : a;
      } else {
        for (int c = first + 1; c < size; ++c) least = less(at(c), at(least)) ? c : least;
      }
      place(s, at(least));
      s = least;
    }
    sift_up(s, e);
  }
  std::vector<int> slot_;  // a point's place in heap_, or kFree, kDone
  std::vector<Entry> heap_;
};

// The edges of the symmetrised neighbour graph that the rows lack: v -> u for each row edge
// u -> v whose reverse is not in v's row, grouped by v (a point's row edges and these are its
// edges in the symmetrised graph; a mutual pair is held once each way, as in the rows).
PointRows reverse_only_edges(const PointRows& rows, int n) {
  const auto row_has = [&](int v, int u) {  // a whole-row scan without branches
    const int* row = rows.neighbours.data() + rows.offsets[static_cast<size_t>(v)];
    const auto size =
        rows.offsets[static_cast<size_t>(v) + 1] - rows.offsets[static_cast<size_t>(v)];
    int found = 0;
    for (std::int64_t j = 0; j < size; ++j) found |= static_cast<int>(row[j] == u);
    return found != 0;
  };
  // The edges in the rows' order, each looking up its target's row: far apart in memory when
  // the points' order is not spatial (random samples: 1.7x dearer without), so the target row
  // of the edge kAhead on is prefetched, and the offset of the one 2 kAhead on.
  constexpr std::int64_t kAhead = 16;
  const std::int64_t edges = rows.offsets[static_cast<size_t>(n)];
  std::vector<std::pair<int, int>> missing;  // (v, u): u -> v in the rows, v -> u not
  int source = 0;
  for (std::int64_t j = 0; j < edges; ++j) {
    while (rows.offsets[static_cast<size_t>(source) + 1] <= j) ++source;
    if (j + 2 * kAhead < edges)
      __builtin_prefetch(
          &rows.offsets[static_cast<size_t>(rows.neighbours[static_cast<size_t>(j + 2 * kAhead)])]);
    if (j + kAhead < edges)
      __builtin_prefetch(&rows.neighbours[static_cast<size_t>(
          rows.offsets[static_cast<size_t>(rows.neighbours[static_cast<size_t>(j + kAhead)])])]);
    const int v = rows.neighbours[static_cast<size_t>(j)];
    if (!row_has(v, source)) missing.emplace_back(v, source);
  }
  PointRows reverse;
  reverse.offsets.assign(static_cast<size_t>(n) + 1, 0);
  for (const auto& [v, u] : missing) ++reverse.offsets[static_cast<size_t>(v) + 1];
  for (size_t i = 0; i < static_cast<size_t>(n); ++i) reverse.offsets[i + 1] += reverse.offsets[i];
  reverse.neighbours.resize(missing.size());
  std::vector<std::int64_t> cursor(reverse.offsets.begin(), reverse.offsets.end() - 1);
  for (const auto& [v, u] : missing)
    reverse.neighbours[static_cast<size_t>(cursor[static_cast<size_t>(v)]++)] = u;
  return reverse;
}

}  // namespace

VertexMatrix pca_normals(const VertexMatrix& points, const PointRows& rows, int threads,
                         std::vector<unsigned char>& degenerate) {
  const int n = static_cast<int>(points.rows());
  VertexMatrix normals(n, 3);
  degenerate.assign(static_cast<size_t>(n), 0);
  if (threads <= 0) threads = 1;
#pragma omp parallel num_threads(threads)
  {
    std::vector<Vec3> offsets;  // the row's points less the centre, gathered once
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      const auto b = rows.offsets[static_cast<size_t>(i)];
      const auto e = rows.offsets[static_cast<size_t>(i) + 1];
      const double x0 = points(i, 0), y0 = points(i, 1), z0 = points(i, 2);
      offsets.resize(static_cast<size_t>(e - b));
      double mx = 0.0, my = 0.0, mz = 0.0;
      for (auto j = b; j < e; ++j) {
        const int v = rows.neighbours[static_cast<size_t>(j)];
        const Vec3 d(points(v, 0) - x0, points(v, 1) - y0, points(v, 2) - z0);
        offsets[static_cast<size_t>(j - b)] = d;
        mx += d.x();
        my += d.y();
        mz += d.z();
      }
      const double count = static_cast<double>(e - b + 1);  // the centre is the first point
      mx /= count;
      my /= count;
      mz /= count;
      // The covariance about the mean (the centre's offset 0 gives the mean's outer product),
      // its lower triangle summed in row order.
      double xx = mx * mx, yx = my * mx, zx = mz * mx, yy = my * my, zy = mz * my, zz = mz * mz;
      for (const Vec3& o : offsets) {
        const double dx = o.x() - mx, dy = o.y() - my, dz = o.z() - mz;
        xx += dx * dx;
        yx += dy * dx;
        zx += dz * dx;
        yy += dy * dy;
        zy += dz * dy;
        zz += dz * dz;
      }
      Mat3 cov;
      cov << xx, yx, zx, yx, yy, zy, zx, zy, zz;
      // The closed-form 3x3 solution (Eigen's computeDirect), 1.6x cheaper than the iterative
      // solver here; its normals differ from the iterative ones by < 1e-14 rad.
      Eigen::SelfAdjointEigenSolver<Mat3> eig;
      eig.computeDirect(cov);
      const Vec3 lambda = eig.eigenvalues();  // increasing
      normals.row(i) = eig.eigenvectors().col(0).transpose();
      if (e - b < 2 || !(lambda(1) > 1e-12 * lambda(2)) || !normals.row(i).allFinite()) {
        degenerate[static_cast<size_t>(i)] = 1;
        if (!normals.row(i).allFinite()) normals.row(i) = Vec3::UnitZ().transpose();
      }
    }
  }
  return normals;
}

std::vector<unsigned char> orient_normals(const VertexMatrix& points, const PointRows& rows,
                                          VertexMatrix& normals,
                                          std::vector<unsigned char> degenerate, int* components) {
  const int n = static_cast<int>(points.rows());
  const PointRows reverse = reverse_only_edges(rows, n);

  // Prim's algorithm per component from its lowest index. The next point is the one of least
  // (weight, point) over the edges from the tree, reached from its parent of least (weight,
  // parent), so that ties resolve the same way every time; each frontier point is held once and
  // its key lowered in place (an indexed heap: a heap of edges held 16 per point at 1.4 million
  // points and made this step 10x dearer than the neighbour search).
  PrimFrontier frontier(n);
  std::vector<int> members;
  int count = 0;
  for (int seed = 0; seed < n; ++seed) {
    if (frontier.done(seed)) continue;
    ++count;
    members.clear();
    frontier.offer(seed, 0.0, seed);
    while (!frontier.empty()) {
      const auto [v, parent] = frontier.pop();
      members.push_back(v);
      if (normals.row(v).dot(normals.row(parent)) < 0.0) normals.row(v) *= -1.0;
      const auto offer_edges = [&](const PointRows& edges) {
        for (auto e = edges.offsets[static_cast<size_t>(v)];
             e < edges.offsets[static_cast<size_t>(v) + 1]; ++e) {
          const int w = edges.neighbours[static_cast<size_t>(e)];
          if (frontier.done(w)) continue;
          frontier.offer(w, 1.0 - std::abs(normals.row(v).dot(normals.row(w))), v);
        }
      };
      offer_edges(rows);
      offer_edges(reverse);
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
