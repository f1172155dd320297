// Normals of a point set without connectivity (docs/point_sets.md, option point-normals):
//
//   1. a normal per point from the point and its neighbour row: PCA (the eigenvector of the
//      smallest eigenvalue of their covariance about their centroid), or the jet (CGAL's jet
//      normal estimation: the degree-2 Monge_via_jet_fitting of CGAL::jet_estimate_normals, on
//      the same rows as PCA);
//   2. consistent signs: Hoppe et al. (1992) propagation over the minimum spanning tree of the
//      symmetrised neighbour graph with edge weight 1 - |n_i . n_j|, each connected component
//      on its own, from its lowest-index point; an edge flips the new point's normal where
//      n_i . n_j < 0;
//   3. one global sign per component (orientation_rule):
//        closed-like component (|mean of n| < kOpenMean): the sign that makes
//          sum n_i . (p_i - c) > 0 (c the component's centroid), i.e. outward, as the divergence
//          theorem gives 3 x volume; undecided where |that sum| < kClosedMargin sum |p_i - c|;
//        open component (a patch or height field facing one way): the sign that makes the mean
//          normal's z positive (upward); undecided where |mean z| < kUpMargin.
//      An undecided component's points, and points whose neighbours single out no plane
//      (collinear, fewer than two neighbours), are flagged `undetermined`.
// Or the normals the file gives (given_point_normals): normalised, their signs as given, no
// step 2 or 3; a zero or non-finite one is flagged `undetermined` (its PCA normal stands in).
#pragma once

#include <vector>

#include "core/types.h"
#include "points/point_search.h"

namespace curvbench {

struct PointNormals {
  VertexMatrix normals;                     ///< unit normals, one per point
  std::vector<unsigned char> undetermined;  ///< 1 where the sign (or the normal) is not decided
  int components = 0;  ///< connected components of the neighbour graph (0: not oriented over it)
};

/// The constants of the global rule (see above).
inline constexpr double kOpenMean = 0.5;
inline constexpr double kClosedMargin = 0.05;
inline constexpr double kUpMargin = 0.05;

/// Unoriented PCA normals from the rows (step 1); degenerate[i] = 1 where the points single out
/// no plane (the middle eigenvalue below 1e-12 times the largest, or fewer than two neighbours).
VertexMatrix pca_normals(const VertexMatrix& points, const PointRows& rows, int threads,
                         std::vector<unsigned char>& degenerate);

/// Steps 2 and 3 on `normals` in place; returns the undetermined flags (degenerate ones kept).
/// The result does not depend on the number of threads (this part runs on one).
std::vector<unsigned char> orient_normals(const VertexMatrix& points, const PointRows& rows,
                                          VertexMatrix& normals,
                                          std::vector<unsigned char> degenerate, int* components);

/// Unoriented jet normals from the rows (step 1): per point, CGAL's Monge_via_jet_fitting of
/// degree 2 (Monge degree 1: the normal only) through the point and its row, as
/// CGAL::jet_estimate_normals fits it. `degenerate` as pca_normals gives it (the jet needs a
/// plane too): those points, points with fewer than 6 points to fit and points whose fit is not
/// finite keep their PCA normal and are flagged. The result does not depend on `threads`.
VertexMatrix jet_normals(const VertexMatrix& points, const PointRows& rows, int threads,
                         std::vector<unsigned char>& degenerate);

/// Steps 1-3 with the k-nearest-neighbour rows (k = kNormalNeighbours), step 1 by PCA or by the
/// jet.
inline constexpr int kNormalNeighbours = 16;
PointNormals oriented_pca_normals(const PointSearch& search, int threads);
/// The same from knn_rows of kNormalNeighbours or more neighbours (their first
/// kNormalNeighbours: the same normals).
PointNormals oriented_pca_normals(const VertexMatrix& points, const PointRows& nearest,
                                  int threads);
PointNormals oriented_jet_normals(const PointSearch& search, int threads);
PointNormals oriented_jet_normals(const VertexMatrix& points, const PointRows& nearest,
                                  int threads);

/// The normals `given` with the points (one row per point, e.g. a file's nx ny nz): each
/// normalised, its sign kept; a zero or non-finite row gets the point's unoriented PCA normal
/// (from the first kNormalNeighbours of its row of `nearest`) and is flagged undetermined.
PointNormals given_point_normals(const VertexMatrix& points, const PointRows& nearest,
                                 const VertexMatrix& given, int threads);

}  // namespace curvbench
