// k-d tree neighbour search over a point set; see point_search.h.
#include "points/point_search.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <nanoflann.hpp>

namespace curvbench {

namespace {

// nanoflann's view of the rows of a VertexMatrix.
struct MatrixAdaptor {
  const VertexMatrix* points;
  size_t kdtree_get_point_count() const { return static_cast<size_t>(points->rows()); }
  double kdtree_get_pt(size_t i, size_t dim) const {
    return (*points)(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(dim));
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using KdTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, MatrixAdaptor>,
                                        MatrixAdaptor, 3, std::uint32_t>;

// The k nearest hits in PointHit form, straight into the caller's buffer: nanoflann's
// KNNResultSet (the same insertion, so the same hits), without its separate index and distance
// arrays.
class NearestHits {
 public:
  NearestHits(PointHit* hits, size_t capacity) : hits_(hits), capacity_(capacity) {
    hits_[capacity_ - 1].distance2 = std::numeric_limits<double>::max();
  }
  size_t size() const { return count_; }
  bool full() const { return count_ == capacity_; }
  double worstDist() const { return hits_[capacity_ - 1].distance2; }
  bool addPoint(double d2, std::uint32_t index) {
    size_t i = count_;
    for (; i > 0 && hits_[i - 1].distance2 > d2; --i)
      if (i < capacity_) hits_[i] = hits_[i - 1];
    if (i < capacity_) hits_[i] = {static_cast<int>(index), d2};
    if (count_ < capacity_) ++count_;
    return true;
  }

 private:
  PointHit* hits_;
  size_t capacity_;
  size_t count_ = 0;
};

void sort_hits(std::vector<PointHit>& hits) {
  std::sort(hits.begin(), hits.end(), [](const PointHit& a, const PointHit& b) {
    return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
  });
}

constexpr int kBlock = 1024;  // points per block of the parallel row gather

// A neighbour as one sortable integer: a non-negative distance's bits (which order as its value
// does) above the index. __extension__: a GCC and Clang type, outside ISO C++.
__extension__ typedef unsigned __int128 NeighbourKey;

// A gathering thread's own state between its queries (the grid's; the tree needs none).
struct RowScratch {
  std::vector<NeighbourKey> keys;  // CellGrid::knn_of's sort keys
  std::vector<double> d2;          // and squared distances
  double last_kth = 0.0;           // the squared k-th distance of its last row
};

// The rows of every point, query(i, at, hits, scratch) giving point i's (at: its place in order).
// The points are queried in `order` (every point once, neighbours close together: the tree's leaf
// order or the grid's cell order), so that consecutive queries touch the same memory, in fixed
// blocks of that order, each gathered by one thread into its own buffer and then copied to its
// points' places: the same rows for any number of threads.
template <class Query>
PointRows gather_rows(std::span<const std::uint32_t> order, int threads, Query&& query) {
  const int n = static_cast<int>(order.size());
  if (threads <= 0) threads = omp_get_max_threads();
  const int blocks = (n + kBlock - 1) / kBlock;
  threads = std::max(1, std::min(threads, blocks));
  std::vector<std::vector<int>> gathered(static_cast<size_t>(blocks));
  PointRows rows;
  rows.offsets.assign(static_cast<size_t>(n) + 1, 0);
  std::exception_ptr error;
#pragma omp parallel num_threads(threads)
  {
    std::vector<PointHit> hits;
    RowScratch scratch;
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < blocks; ++b) {
      try {
        auto& out = gathered[static_cast<size_t>(b)];
        for (int at = b * kBlock; at < std::min(n, (b + 1) * kBlock); ++at) {
          const int i = static_cast<int>(order[static_cast<size_t>(at)]);
          query(i, at, hits, scratch);
          for (const PointHit& h : hits) out.push_back(h.index);
          rows.offsets[static_cast<size_t>(i) + 1] = static_cast<std::int64_t>(hits.size());
        }
      } catch (...) {
#pragma omp critical(point_rows_error)
        if (!error) error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
  for (size_t i = 0; i < static_cast<size_t>(n); ++i) rows.offsets[i + 1] += rows.offsets[i];
  rows.neighbours.resize(static_cast<size_t>(rows.offsets.back()));
#pragma omp parallel for num_threads(threads) schedule(static)
  for (int b = 0; b < blocks; ++b) {
    const int* from = gathered[static_cast<size_t>(b)].data();
    for (int at = b * kBlock; at < std::min(n, (b + 1) * kBlock); ++at) {
      const size_t i = order[static_cast<size_t>(at)];
      const auto length = rows.offsets[i + 1] - rows.offsets[i];
      std::copy_n(from, length, rows.neighbours.begin() + rows.offsets[i]);
      from += length;
    }
    std::vector<int>().swap(gathered[static_cast<size_t>(b)]);
  }
  return rows;
}

// A uniform grid of cubic cells over the points' bounding box, the points sorted by cell (by index
// within a cell), for knn_rows. Point i's k nearest others are looked for in the 3 x 3 x 3 cells
// around its own, then in the 5 x 5 x 5; they are its row when the k-th of them is nearer than the
// faces of that block, less a margin for rounding (a point outside the block is at least that
// far), else the caller asks the tree. The side is set from the points' density so that the k-th
// neighbour of a point of an evenly sampled surface lies within about 0.8 of a side: then nearly
// every row is settled by 27 cells of about 0.3 (k + 1) points each.
class CellGrid {
 public:
  CellGrid(const VertexMatrix& points, int k) : points_(points) {
    const int n = static_cast<int>(points.rows());
    if (n < 2 * (k + 1)) return;  // the tree, for a set about as small as a row
    lo_ = points.colwise().minCoeff().transpose();
    const Vec3 extent = points.colwise().maxCoeff().transpose() - lo_;
    if (!extent.allFinite() || !(extent.maxCoeff() > 0.0)) return;
    // A first side from an area guess (the two largest faces of the box, as a closed surface in
    // it would have), then one correction from the points per occupied cell it gives, assuming a
    // surface (points per cell growing as the side squared).
    Vec3 e = extent;
    std::sort(e.data(), e.data() + 3);
    const double target = kPointsPerCell * (k + 1);
    double side = std::sqrt(2.0 * e(2) * std::max(e(1), e(2) * 1e-3) * target / n);
    if (!set_side(side, extent, n)) return;
    const double occupied = static_cast<double>(count_occupied());
    side *= std::clamp(std::sqrt(target * occupied / n), 0.25, 4.0);
    if (!set_side(side, extent, n)) return;
    const double per_cell = static_cast<double>(n) / static_cast<double>(sort_points());
    if (per_cell > 8.0 * target) {  // too coarse (a capped grid): the tree does better
      order_.clear();
      return;
    }
    double largest = 0.0;
    for (int a = 0; a < 3; ++a)
      largest = std::max({largest, std::abs(lo_(a)), std::abs(lo_(a) + extent(a))});
    margin_ = 1e-6 * side_ + 16.0 * std::numeric_limits<double>::epsilon() * largest;
  }

  bool usable() const { return !order_.empty(); }
  /// Every point once, cell by cell.
  std::span<const std::uint32_t> order() const { return order_; }

  /// The k nearest others (PointSearch::knn_of) of the point at place `at` of order() when the
  /// block around its cell settles them; false otherwise (out is then unspecified).
  bool knn_of(int at, int k, std::vector<PointHit>& out, RowScratch& scratch) const {
    for (const int reach_cells : {1, 2})
      if (knn_in_block(at, k, reach_cells, out, scratch)) return true;
    return false;
  }

 private:
  // knn_of within the cells at most `r` cells away from the point's along each axis.
  bool knn_in_block(int at, int k, int r, std::vector<PointHit>& out, RowScratch& scratch) const {
    const double q[3] = {xs_[static_cast<size_t>(at)], ys_[static_cast<size_t>(at)],
                         zs_[static_cast<size_t>(at)]};
    const int c[3] = {cell_of(q[0], 0), cell_of(q[1], 1), cell_of(q[2], 2)};
    // Distance to the nearest face of the block that has cells beyond it.
    double reach = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (c[a] > r) reach = std::min(reach, q[a] - (lo_(a) + (c[a] - r) * side_));
      if (c[a] + r + 1 < dims_[a]) reach = std::min(reach, lo_(a) + (c[a] + r + 1) * side_ - q[a]);
    }
    reach -= margin_;
    if (!(reach > 0.0)) return false;
    const double reach2 = reach * reach;
    // The points of the block nearer than a guess t of the k-th distance (the last row's, made
    // larger): when k of them are, they hold the row and the rest need no sorting; else again
    // with t = reach. Nothing at reach or beyond can settle the row.
    const double guess = kGuess * scratch.last_kth;
    size_t found = 0;
    for (const double t : {std::min(guess, reach2), reach2}) {
      if (!(t > 0.0)) continue;
      found = collect(q, c, r, t, scratch);
      if (found >= static_cast<size_t>(k)) break;
      if (t == reach2) return false;
    }
    if (found < static_cast<size_t>(k)) return false;
    std::sort(scratch.keys.begin(), scratch.keys.begin() + static_cast<std::ptrdiff_t>(found));
    out.resize(static_cast<size_t>(k));
    for (size_t h = 0; h < out.size(); ++h)
      out[h] = {static_cast<int>(static_cast<std::uint32_t>(scratch.keys[h])),
                std::bit_cast<double>(static_cast<std::uint64_t>(scratch.keys[h] >> 32))};
    scratch.last_kth = out.back().distance2;
    return out.back().distance2 < reach2;
  }

  // Points per occupied cell aimed at, per point of a row (k + 1): see the class comment.
  static constexpr double kPointsPerCell = 0.3;
  // The first bound on a row's squared k-th distance: this times the last row's.
  static constexpr double kGuess = 1.3;
  // At most this many cells per point (the count array is 4 bytes a cell).
  static constexpr double kMaxCellsPerPoint = 16.0;

  // The points of the cells at most r cells away from cell c along each axis at squared distance
  // in (0, t] of q (the point itself and its copies left out), as keys in scratch.keys; returns
  // how many.
  size_t collect(const double q[3], const int c[3], int r, double t, RowScratch& scratch) const {
    const double qx = q[0], qy = q[1], qz = q[2];
    size_t found = 0;
    const int x0 = std::max(c[0] - r, 0), x1 = std::min(c[0] + r, dims_[0] - 1);
    for (int z = std::max(c[2] - r, 0); z <= std::min(c[2] + r, dims_[2] - 1); ++z)
      for (int y = std::max(c[1] - r, 0); y <= std::min(c[1] + r, dims_[1] - 1); ++y) {
        const std::int64_t row = (static_cast<std::int64_t>(z) * dims_[1] + y) * dims_[0];
        const std::uint32_t b = start_[static_cast<size_t>(row + x0)];
        const std::uint32_t e = start_[static_cast<size_t>(row + x1 + 1)];
        if (scratch.d2.size() < e - b) scratch.d2.resize(e - b);
        if (scratch.keys.size() < found + (e - b)) scratch.keys.resize(2 * (found + (e - b)));
        double* d2 = scratch.d2.data();
        const double *x = xs_.data() + b, *y_ = ys_.data() + b, *z_ = zs_.data() + b;
        const std::uint32_t span = e - b;
        for (std::uint32_t s = 0; s < span; ++s) {
          // As nanoflann's L2_Simple_Adaptor sums it, so that both paths rank alike.
          const double dx = qx - x[s], dy = qy - y_[s], dz = qz - z_[s];
          d2[s] = dx * dx + dy * dy + dz * dz;
        }
        NeighbourKey* key = scratch.keys.data() + found;
        for (std::uint32_t s = 0; s < span; ++s) {
          *key = (static_cast<NeighbourKey>(std::bit_cast<std::uint64_t>(d2[s])) << 32) |
                 order_[b + s];
          key += (d2[s] > 0.0) & (d2[s] <= t);
        }
        found = static_cast<size_t>(key - scratch.keys.data());
      }
    return found;
  }

  bool set_side(double side, const Vec3& extent, int n) {
    if (!(side > 0.0) || !std::isfinite(side)) return false;
    const double cap = kMaxCellsPerPoint * n + 4096.0;
    for (;;) {
      double cells = 1.0;
      for (int a = 0; a < 3; ++a) cells *= std::floor(extent(a) / side) + 1.0;
      if (cells <= cap) break;
      side *= std::cbrt(cells / cap) * 1.01;
    }
    side_ = side;
    inverse_ = 1.0 / side;
    for (int a = 0; a < 3; ++a) dims_[a] = static_cast<int>(std::floor(extent(a) / side)) + 1;
    return true;
  }
  int cell_of(double x, int a) const {
    return std::clamp(static_cast<int>((x - lo_(a)) * inverse_), 0, dims_[a] - 1);
  }
  std::int64_t cell_of_point(int i) const {
    return (static_cast<std::int64_t>(cell_of(points_(i, 2), 2)) * dims_[1] +
            cell_of(points_(i, 1), 1)) *
               dims_[0] +
           cell_of(points_(i, 0), 0);
  }
  size_t num_cells() const {
    return static_cast<size_t>(dims_[0]) * static_cast<size_t>(dims_[1]) *
           static_cast<size_t>(dims_[2]);
  }
  // Occupied cells (start_ left holding each cell's count).
  std::int64_t count_occupied() {
    start_.assign(num_cells() + 1, 0);
    const int n = static_cast<int>(points_.rows());
    for (int i = 0; i < n; ++i) ++start_[static_cast<size_t>(cell_of_point(i)) + 1];
    std::int64_t occupied = 0;
    for (size_t c = 1; c < start_.size(); ++c) occupied += start_[c] > 0;
    return occupied;
  }
  // The counting sort: start_[c] .. start_[c + 1] are cell c's points, by index. Returns the
  // occupied cells.
  std::int64_t sort_points() {
    const std::int64_t occupied = count_occupied();
    for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    const int n = static_cast<int>(points_.rows());
    order_.resize(static_cast<size_t>(n));
    xs_.resize(static_cast<size_t>(n));
    ys_.resize(static_cast<size_t>(n));
    zs_.resize(static_cast<size_t>(n));
    std::vector<std::uint32_t> cursor(start_.begin(), start_.end() - 1);
    for (int i = 0; i < n; ++i) {
      const std::uint32_t at = cursor[static_cast<size_t>(cell_of_point(i))]++;
      order_[at] = static_cast<std::uint32_t>(i);
      xs_[at] = points_(i, 0);
      ys_[at] = points_(i, 1);
      zs_[at] = points_(i, 2);
    }
    return occupied;
  }

  const VertexMatrix& points_;
  Vec3 lo_ = Vec3::Zero();
  double side_ = 0.0, inverse_ = 0.0, margin_ = 0.0;
  int dims_[3] = {1, 1, 1};
  std::vector<std::uint32_t> start_;  // num_cells() + 1
  std::vector<std::uint32_t> order_;  // point indices by cell
  std::vector<double> xs_, ys_, zs_;  // their coordinates, in that order
};
}  // namespace

struct PointSearch::Tree {
  MatrixAdaptor adaptor;
  KdTree tree;
  explicit Tree(const VertexMatrix& points)
      : adaptor{&points}, tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    tree.buildIndex();
  }
};

PointSearch::PointSearch(const VertexMatrix& points) : points_(&points) {}

PointSearch::~PointSearch() = default;

const PointSearch::Tree& PointSearch::tree() const {
  std::call_once(tree_built_, [this] { tree_ = std::make_unique<Tree>(*points_); });
  return *tree_;
}

std::span<const std::uint32_t> PointSearch::leaf_order() const {
  return tree().tree.vAcc;
}

void PointSearch::knn(const Vec3& q, int k, std::vector<PointHit>& out) const {
  out.clear();
  const int want = std::min(k, num_points());
  if (want <= 0) return;
  out.resize(static_cast<size_t>(want));
  NearestHits found(out.data(), out.size());
  tree().tree.findNeighbors(found, q.data(), nanoflann::SearchParams());
  out.resize(found.size());
  sort_hits(out);  // ties in distance by index
}

void PointSearch::ball(const Vec3& q, double r, std::vector<PointHit>& out) const {
  out.clear();
  if (!(r >= 0.0)) return;
  ball_squared(q, r * r, out);
}

void PointSearch::ball_squared(const Vec3& q, double r2, std::vector<PointHit>& out) const {
  out.clear();
  std::vector<std::pair<std::uint32_t, double>> found;
  nanoflann::SearchParams params;
  params.sorted = false;
  // nanoflann's radius test is d2 < radius: the next double above r2 keeps points at r2.
  tree().tree.radiusSearch(q.data(), std::nextafter(r2, HUGE_VAL), found, params);
  out.reserve(found.size());
  for (const auto& [i, d2] : found) out.push_back({static_cast<int>(i), d2});
  sort_hits(out);
}

void PointSearch::knn_of(int i, int k, std::vector<PointHit>& out) const {
  out.clear();
  if (k <= 0) return;
  const Vec3 p = points_->row(i).transpose();
  const auto is_other = [](const PointHit& h) { return h.distance2 > 0.0; };
  // Ask for k + 2 (the point itself, k others and the one after them) and more while points at
  // distance 0 (duplicates) fill the list, so that k others and the next remain when the set has
  // them.
  int ask = k + 2;
  for (;;) {
    knn(p, ask, out);
    const auto first = std::find_if(out.begin(), out.end(), is_other);
    const int others = static_cast<int>(out.end() - first);
    if (others > k) {
      const double kth = first[k - 1].distance2;
      if (first[k].distance2 == kth) {
        // The next is as far as the k-th: the search kept some of the points at that distance,
        // the ball of it holds them all, by index.
        ball_squared(p, kth, out);
        out.erase(std::remove_if(out.begin(), out.end(), std::not_fn(is_other)), out.end());
      } else {
        out.erase(out.begin(), first);
      }
      out.resize(static_cast<size_t>(k));
      return;
    }
    if (ask >= num_points()) {
      out.erase(out.begin(), first);
      return;
    }
    ask = std::min(num_points(), 2 * ask);
  }
}

void PointSearch::ball_of(int i, double r, std::vector<PointHit>& out) const {
  ball(points_->row(i).transpose(), r, out);
  out.erase(std::remove_if(out.begin(), out.end(),
                           [](const PointHit& h) { return !(h.distance2 > 0.0); }),
            out.end());
}

double mean_spacing(const PointSearch& search, int threads) {
  const PointRows nearest = knn_rows(search, 1, threads);
  const VertexMatrix& p = search.points();
  double sum = 0.0;
  int counted = 0;
  for (int i = 0; i < search.num_points(); ++i) {
    if (nearest.offsets[static_cast<size_t>(i) + 1] == nearest.offsets[static_cast<size_t>(i)])
      continue;
    const int j = nearest.neighbours[static_cast<size_t>(nearest.offsets[static_cast<size_t>(i)])];
    sum += (p.row(i) - p.row(j)).norm();
    ++counted;
  }
  return counted > 0 ? sum / counted : 0.0;
}

PointRows knn_rows(const PointSearch& search, int k, int threads, std::int64_t* grid_rows) {
  if (grid_rows != nullptr) *grid_rows = 0;
  if (k <= 0 || search.num_points() == 0) {
    PointRows rows;
    rows.offsets.assign(static_cast<size_t>(search.num_points()) + 1, 0);
    return rows;
  }
  const CellGrid grid(search.points(), k);
  if (!grid.usable())
    return gather_rows(
        search.leaf_order(), threads,
        [&](int i, int, std::vector<PointHit>& hits, RowScratch&) { search.knn_of(i, k, hits); });
  std::atomic<std::int64_t> by_tree{0};
  PointRows rows = gather_rows(
      grid.order(), threads, [&](int i, int at, std::vector<PointHit>& hits, RowScratch& scratch) {
        if (grid.knn_of(at, k, hits, scratch)) return;
        search.knn_of(i, k, hits);
        by_tree.fetch_add(1, std::memory_order_relaxed);
      });
  if (grid_rows != nullptr) *grid_rows = search.num_points() - by_tree.load();
  return rows;
}

PointRows first_of_rows(const PointRows& rows, int k) {
  PointRows first;
  first.offsets = rows.offsets;
  for (size_t i = 1; i < first.offsets.size(); ++i)
    first.offsets[i] =
        first.offsets[i - 1] + std::min<std::int64_t>(k, rows.offsets[i] - rows.offsets[i - 1]);
  first.neighbours.resize(static_cast<size_t>(first.offsets.back()));
  for (size_t i = 1; i < first.offsets.size(); ++i)
    std::copy_n(rows.neighbours.begin() + rows.offsets[i - 1],
                first.offsets[i] - first.offsets[i - 1],
                first.neighbours.begin() + first.offsets[i - 1]);
  return first;
}

PointRows ball_rows(const PointSearch& search, double r, int threads) {
  return gather_rows(
      search.leaf_order(), threads,
      [&](int i, int, std::vector<PointHit>& hits, RowScratch&) { search.ball_of(i, r, hits); });
}

}  // namespace curvbench
