// k-d tree neighbour search over a point set; see point_search.h.
#include "points/point_search.h"

#include <omp.h>

#include <algorithm>
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

// The rows of every point, query(i, hits) giving point i's. The points are queried in the tree's
// leaf order (PointSearch::leaf_order), so that consecutive queries walk the same nodes and
// points, in fixed blocks of that order, each gathered by one thread into its own buffer and then
// copied to its points' places: the same rows for any number of threads.
template <class Query>
PointRows gather_rows(const PointSearch& search, int threads, Query&& query) {
  const int n = search.num_points();
  const std::span<const std::uint32_t> order = search.leaf_order();
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
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < blocks; ++b) {
      try {
        auto& out = gathered[static_cast<size_t>(b)];
        for (int at = b * kBlock; at < std::min(n, (b + 1) * kBlock); ++at) {
          const int i = static_cast<int>(order[static_cast<size_t>(at)]);
          query(i, hits);
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

}  // namespace

struct PointSearch::Tree {
  MatrixAdaptor adaptor;
  KdTree tree;
  explicit Tree(const VertexMatrix& points)
      : adaptor{&points}, tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    tree.buildIndex();
  }
};

PointSearch::PointSearch(const VertexMatrix& points)
    : points_(&points), tree_(std::make_unique<Tree>(points)) {}

PointSearch::~PointSearch() = default;

std::span<const std::uint32_t> PointSearch::leaf_order() const {
  return tree_->tree.vAcc;
}

void PointSearch::knn(const Vec3& q, int k, std::vector<PointHit>& out) const {
  out.clear();
  const int want = std::min(k, num_points());
  if (want <= 0) return;
  out.resize(static_cast<size_t>(want));
  NearestHits found(out.data(), out.size());
  tree_->tree.findNeighbors(found, q.data(), nanoflann::SearchParams());
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
  tree_->tree.radiusSearch(q.data(), std::nextafter(r2, HUGE_VAL), found, params);
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

PointRows knn_rows(const PointSearch& search, int k, int threads) {
  return gather_rows(search, threads,
                     [&](int i, std::vector<PointHit>& hits) { search.knn_of(i, k, hits); });
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
  return gather_rows(search, threads,
                     [&](int i, std::vector<PointHit>& hits) { search.ball_of(i, r, hits); });
}

}  // namespace curvbench
