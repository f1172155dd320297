// Neighbour search in a point set without connectivity: a k-d tree (nanoflann) over the rows of
// a VertexMatrix, k nearest neighbours and radius balls, and the point set's mean spacing; the
// k-nearest rows of every point at once (knn_rows) through a uniform grid of cells where that
// settles them, the tree elsewhere.
//
// Results are deterministic: the tree is built by one thread from the points alone, every list
// is sorted by distance, then by index, and a k-nearest list breaks ties at its last distance by
// index. Distances are computed the same way on every path, so the grid and the tree give the
// same rows.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <utility>
#include <vector>

#include "core/types.h"

namespace curvbench {

/// One neighbour: its index and squared distance to the query.
struct PointHit {
  int index = -1;
  double distance2 = 0.0;
};

class PointSearch {
 public:
  /// The search over the rows of `points` (which must outlive it). The tree is built on first use
  /// (by one thread, whichever asks first), so that rows the grid settles alone never pay for it.
  explicit PointSearch(const VertexMatrix& points);
  ~PointSearch();
  PointSearch(const PointSearch&) = delete;
  PointSearch& operator=(const PointSearch&) = delete;

  int num_points() const { return static_cast<int>(points_->rows()); }
  const VertexMatrix& points() const { return *points_; }
  /// Every point once, in the order of the tree's leaves: consecutive points lie close together
  /// (the row gathers below query in this order, for the caches).
  std::span<const std::uint32_t> leaf_order() const;

  /// The k points nearest to q (fewer if the set has fewer), sorted by distance then index.
  void knn(const Vec3& q, int k, std::vector<PointHit>& out) const;
  /// Every point within distance r of q (inclusive), sorted by distance then index.
  void ball(const Vec3& q, double r, std::vector<PointHit>& out) const;

  /// The k nearest points to point i other than i and other than any point at its very position
  /// (a duplicate is never its copy's neighbour), sorted by distance then index; of the points
  /// tied at the k-th distance, those of lowest index. So the first k of knn_of(i, k') for any
  /// k' >= k are knn_of(i, k).
  void knn_of(int i, int k, std::vector<PointHit>& out) const;
  /// The points within distance r of point i, i and its duplicates excluded.
  void ball_of(int i, double r, std::vector<PointHit>& out) const;

 private:
  /// Every point within squared distance r2 of q (inclusive), sorted by distance then index.
  void ball_squared(const Vec3& q, double r2, std::vector<PointHit>& out) const;
  struct Tree;
  const Tree& tree() const;
  const VertexMatrix* points_;
  mutable std::once_flag tree_built_;
  mutable std::unique_ptr<Tree> tree_;
};

/// The mean spacing s of a point set: the mean over the points of the distance to the nearest
/// other point at a different position (duplicates are skipped). 0 for fewer than two distinct
/// positions. Computed with `threads` threads, summed in point order. `radius=2.5s` of the
/// neighbourhood option is 2.5 times this.
double mean_spacing(const PointSearch& search, int threads);

/// Neighbour rows in compressed form: row i = neighbours[offsets[i] .. offsets[i+1]).
struct PointRows {
  std::vector<std::int64_t> offsets{0};
  std::vector<int> neighbours;
};

/// The k-nearest-neighbour rows of every point: row i is knn_of(i, k), for any number of
/// `threads`. Found through a grid of cells about k-th-neighbour distance wide: a point's row is
/// taken from the 27 cells around it when its k-th neighbour is nearer than any point outside
/// them can be, else from the tree (points in sparse places, too few points, a set whose extent
/// would need too many cells). `grid_rows`, if given, receives how many rows the grid settled.
PointRows knn_rows(const PointSearch& search, int k, int threads,
                   std::int64_t* grid_rows = nullptr);
/// The first k of each row: of k' >= k nearest rows (knn_rows), the k nearest rows.
PointRows first_of_rows(const PointRows& rows, int k);
/// The radius-r ball rows of every point (ball_of).
PointRows ball_rows(const PointSearch& search, double r, int threads);

}  // namespace curvbench
