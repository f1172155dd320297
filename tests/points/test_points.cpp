// Neighbour search and oriented normals of point sets (points/).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <random>
#include <tuple>
#include <vector>

#include "points/point_normals.h"
#include "points/point_search.h"

namespace curvbench {
namespace {

// (N+1)^2 grid of spacing h in the plane z = c, as rows.
VertexMatrix grid(int N, double h, double z = 0.0) {
  VertexMatrix V((N + 1) * (N + 1), 3);
  for (int j = 0; j <= N; ++j)
    for (int i = 0; i <= N; ++i) V.row(j * (N + 1) + i) << i * h, j * h, z;
  return V;
}

// Fibonacci points of the sphere of radius a about c.
VertexMatrix sphere(int n, double a, const Vec3& c) {
  VertexMatrix V(n, 3);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, rho = std::sqrt(1.0 - z * z);
    V.row(i) =
        (c + a * Vec3(rho * std::cos(golden * i), rho * std::sin(golden * i), z)).transpose();
  }
  return V;
}

// The orientation's tree by lazy Prim, written plainly: every edge from the tree to a point not
// in it goes into a priority queue as (weight, point, parent), the least popped first; the
// order the indexed heap of orient_normals promises. Returns the normals with each component's
// signs propagated (before its global sign) and the component of each point.
struct PrimOracle {
  VertexMatrix normals;
  std::vector<int> component;
  int components = 0;
};

PrimOracle lazy_prim(const PointRows& rows, VertexMatrix normals) {
  const int n = static_cast<int>(normals.rows());
  std::vector<std::vector<int>> graph(static_cast<size_t>(n));
  for (int u = 0; u < n; ++u)
    for (auto j = rows.offsets[static_cast<size_t>(u)];
         j < rows.offsets[static_cast<size_t>(u) + 1]; ++j) {
      const int v = rows.neighbours[static_cast<size_t>(j)];
      graph[static_cast<size_t>(u)].push_back(v);
      graph[static_cast<size_t>(v)].push_back(u);
    }
  using Edge = std::tuple<double, int, int>;  // weight, point, parent
  std::priority_queue<Edge, std::vector<Edge>, std::greater<Edge>> queue;
  PrimOracle out{std::move(normals), std::vector<int>(static_cast<size_t>(n), -1), 0};
  VertexMatrix& N = out.normals;
  for (int seed = 0; seed < n; ++seed) {
    if (out.component[static_cast<size_t>(seed)] >= 0) continue;
    queue.emplace(0.0, seed, seed);
    while (!queue.empty()) {
      const auto [weight, v, parent] = queue.top();
      queue.pop();
      if (out.component[static_cast<size_t>(v)] >= 0) continue;
      out.component[static_cast<size_t>(v)] = out.components;
      if (N.row(v).dot(N.row(parent)) < 0.0) N.row(v) *= -1.0;
      for (const int w : graph[static_cast<size_t>(v)])
        if (out.component[static_cast<size_t>(w)] < 0)
          queue.emplace(1.0 - std::abs(N.row(v).dot(N.row(w))), w, v);
    }
    ++out.components;
  }
  return out;
}

// orient_normals against the oracle: the same components, and in each the same normals bit for
// bit up to the component's one global sign; the degenerate flags kept, and a component's
// points all decided or all not. Returns the number of exact ties among the edge weights (so a
// case can show it exercises them).
int expect_orientation_matches_oracle(const VertexMatrix& points, const PointRows& rows,
                                      const VertexMatrix& unoriented,
                                      const std::vector<unsigned char>& degenerate) {
  VertexMatrix normals = unoriented;
  int components = -1;
  const std::vector<unsigned char> undetermined =
      orient_normals(points, rows, normals, degenerate, &components);
  const PrimOracle oracle = lazy_prim(rows, unoriented);
  EXPECT_EQ(components, oracle.components);
  std::vector<double> sign(static_cast<size_t>(oracle.components), 0.0);
  std::vector<int> decided(static_cast<size_t>(oracle.components), -1);
  for (int i = 0; i < points.rows(); ++i) {
    const auto c = static_cast<size_t>(oracle.component[static_cast<size_t>(i)]);
    if (sign[c] == 0.0) sign[c] = normals.row(i).dot(oracle.normals.row(i)) > 0.0 ? 1.0 : -1.0;
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(normals(i, d)),
                std::bit_cast<std::uint64_t>(sign[c] * oracle.normals(i, d)))
          << "point " << i << " axis " << d;
    if (degenerate[static_cast<size_t>(i)]) {
      EXPECT_EQ(undetermined[static_cast<size_t>(i)], 1) << i;
    } else {
      if (decided[c] < 0) decided[c] = undetermined[static_cast<size_t>(i)];
      EXPECT_EQ(undetermined[static_cast<size_t>(i)], decided[c]) << i;
    }
  }
  int ties = 0;
  std::vector<double> weights;
  for (int u = 0; u < points.rows(); ++u)
    for (auto j = rows.offsets[static_cast<size_t>(u)];
         j < rows.offsets[static_cast<size_t>(u) + 1]; ++j)
      weights.push_back(1.0 - std::abs(unoriented.row(u).dot(
                                  unoriented.row(rows.neighbours[static_cast<size_t>(j)]))));
  std::sort(weights.begin(), weights.end());
  for (size_t k = 1; k < weights.size(); ++k) ties += weights[k] == weights[k - 1];
  return ties;
}

// Area-uniform points of the torus R = 1, r = 0.4 (rejection on the area element).
VertexMatrix torus_points(int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), unit(0.0, 1.0);
  VertexMatrix V(n, 3);
  for (int i = 0; i < n;) {
    const double u = angle(rng), v = angle(rng);
    if (unit(rng) * 1.4 > 1.0 + 0.4 * std::cos(v)) continue;
    const double rho = 1.0 + 0.4 * std::cos(v);
    V.row(i++) << rho * std::cos(u), rho * std::sin(u), 0.4 * std::sin(v);
  }
  return V;
}

// Unit normals drawn (seeded) from the 26 directions of {-1, 0, 1}^3: their weights take a few
// values, so most edges tie, and unlike a surface's normals each sign hangs on the tree's path.
VertexMatrix lattice_normals(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> digit(-1, 1);
  VertexMatrix N(n, 3);
  for (int i = 0; i < n; ++i) {
    Vec3 d = Vec3::Zero();
    while (d.isZero()) d = Vec3(digit(rng), digit(rng), digit(rng));
    N.row(i) = d.normalized().transpose();
  }
  return N;
}

// The 16-NN rows of V with its PCA normals, then with lattice normals: orient_normals against
// the oracle. Returns the exact ties among the lattice normals' weights.
int expect_orientation_of_points_matches_oracle(const VertexMatrix& V) {
  const PointRows rows = knn_rows(PointSearch(V), kNormalNeighbours, 2);
  std::vector<unsigned char> degenerate;
  const VertexMatrix normals = pca_normals(V, rows, 2, degenerate);
  expect_orientation_matches_oracle(V, rows, normals, degenerate);
  return expect_orientation_matches_oracle(V, rows, lattice_normals(static_cast<int>(V.rows()), 5),
                                           degenerate);
}

TEST(PointSearch, KnnIsSortedByDistanceThenIndexAndSkipsDuplicates) {
  VertexMatrix V = grid(4, 1.0);
  V.conservativeResize(V.rows() + 1, 3);
  V.row(V.rows() - 1) = V.row(12);  // a copy of the centre (2, 2)
  const PointSearch search(V);
  std::vector<PointHit> hits;
  search.knn_of(12, 4, hits);
  ASSERT_EQ(hits.size(), 4u);
  // The four at distance 1, by index: (2,1)=7, (1,2)=11, (3,2)=13, (2,3)=17; no copy.
  EXPECT_EQ(hits[0].index, 7);
  EXPECT_EQ(hits[1].index, 11);
  EXPECT_EQ(hits[2].index, 13);
  EXPECT_EQ(hits[3].index, 17);
  for (const PointHit& h : hits) EXPECT_DOUBLE_EQ(h.distance2, 1.0);
  search.knn_of(12, 8, hits);
  EXPECT_DOUBLE_EQ(hits[4].distance2, 2.0);  // then the diagonals
}

TEST(PointSearch, BallIsInclusiveAndKnnAsksNoMoreThanTheSet) {
  const VertexMatrix V = grid(4, 1.0);
  const PointSearch search(V);
  std::vector<PointHit> hits;
  search.ball_of(12, 1.0, hits);
  EXPECT_EQ(hits.size(), 4u);  // distance exactly 1 is inside
  search.ball_of(12, std::sqrt(2.0), hits);
  EXPECT_EQ(hits.size(), 8u);
  search.knn_of(0, 100, hits);
  EXPECT_EQ(hits.size(), 24u);  // every other point
}

TEST(PointSearch, MeanSpacingOfAGridIsItsStepAndRowsDoNotDependOnThreads) {
  const VertexMatrix V = grid(60, 0.25);
  const PointSearch search(V);
  EXPECT_DOUBLE_EQ(mean_spacing(search, 2), 0.25);
  const PointRows a = knn_rows(search, 9, 1), b = knn_rows(search, 9, 2);
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.neighbours, b.neighbours);
}

TEST(PointSearch, TiesAtTheLastDistanceGoToTheLowestIndexSoShorterRowsArePrefixes) {
  // Around the centre (2, 2) of a 5x5 grid the four diagonals tie at distance sqrt 2: six
  // nearest are the four at distance 1 and the diagonals of lowest index, (1,1)=6 and (3,1)=8.
  const VertexMatrix V = grid(4, 1.0);
  const PointSearch search(V);
  std::vector<PointHit> hits;
  search.knn_of(12, 6, hits);
  ASSERT_EQ(hits.size(), 6u);
  EXPECT_EQ(hits[4].index, 6);
  EXPECT_EQ(hits[5].index, 8);
  // On a grid every row ends in a tie; the first k of longer rows are the k-rows all the same.
  const VertexMatrix W = grid(30, 0.1);
  const PointSearch big(W);
  for (const int k : {1, 5, 6, 7, 12}) {
    const PointRows direct = knn_rows(big, k, 2);
    const PointRows first = first_of_rows(knn_rows(big, 16, 1), k);
    EXPECT_EQ(direct.offsets, first.offsets) << k;
    EXPECT_EQ(direct.neighbours, first.neighbours) << k;
  }
}

// Row i of knn_rows against the tree's knn_of(i, k), index by index, and the share of rows the
// grid settled (the rest went to the tree).
double check_rows_against_tree(const VertexMatrix& V, int k, const char* what) {
  const PointSearch search(V);
  std::int64_t by_grid = 0;
  const PointRows rows = knn_rows(search, k, 2, &by_grid);
  std::vector<PointHit> hits;
  int mismatches = 0;
  for (int i = 0; i < V.rows(); ++i) {
    search.knn_of(i, k, hits);
    std::vector<int> expected;
    for (const PointHit& h : hits) expected.push_back(h.index);
    const std::vector<int> got(rows.neighbours.begin() + rows.offsets[static_cast<size_t>(i)],
                               rows.neighbours.begin() + rows.offsets[static_cast<size_t>(i) + 1]);
    if (got != expected && ++mismatches <= 3) ADD_FAILURE() << what << ": row " << i << " differs";
  }
  EXPECT_EQ(mismatches, 0) << what;
  return static_cast<double>(by_grid) / static_cast<double>(V.rows());
}

TEST(PointSearch, GridRowsAreTheTreesRowsOnEvenUnevenTiedAndFarFlungSets) {
  // Evenly sampled: the grid settles nearly every row.
  const VertexMatrix torus = torus_points(20000, 7);
  for (const int k : {1, 12, 16, 30})
    EXPECT_GT(check_rows_against_tree(torus, k, "torus"), 0.95) << k;
  // A grid of points: ties at the k-th distance everywhere, settled by index as the tree does.
  EXPECT_GT(check_rows_against_tree(grid(120, 0.01, 0.5), 12, "plane grid"), 0.9);
  // Copies (never a copy's neighbour), far from the origin (rounding near the cell faces).
  VertexMatrix copies = torus_points(6000, 8);
  copies.conservativeResize(8000, 3);
  for (int i = 6000; i < 8000; ++i) copies.row(i) = copies.row(3 * (i - 6000));
  copies.rowwise() += Vec3(1e6, -2e5, 3e4).transpose();
  check_rows_against_tree(copies, 16, "copies far out");
  // Uneven: dense lines 0.1 apart plus a sparse cloud and one far outlier; the tree takes what the
  // grid cannot settle.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  VertexMatrix uneven(5001, 3);
  for (int i = 0; i < 4000; ++i) uneven.row(i) << unit(rng), 0.1 * (i % 10), 1e-3 * unit(rng);
  for (int i = 4000; i < 5000; ++i) uneven.row(i) << unit(rng), unit(rng), unit(rng);
  uneven.row(5000) << 50.0, 50.0, 50.0;
  check_rows_against_tree(uneven, 16, "uneven");
  // As small as a row, and fewer points than k: every other point, nearest first.
  check_rows_against_tree(torus_points(20, 3), 16, "tiny");
  check_rows_against_tree(torus_points(40, 3), 16, "small");
}

TEST(PointNormals, ClosedSetsPointOutwardEachComponentOnItsOwn) {
  // Two spheres far apart: two components, each outward.
  const VertexMatrix a = sphere(800, 1.0, Vec3(0, 0, 0)), b = sphere(500, 0.5, Vec3(10, 0, 0));
  VertexMatrix V(a.rows() + b.rows(), 3);
  V << a, b;
  const PointSearch search(V);
  const PointNormals pn = oriented_pca_normals(search, 2);
  EXPECT_EQ(pn.components, 2);
  for (int i = 0; i < V.rows(); ++i) {
    const Vec3 c = i < a.rows() ? Vec3(0, 0, 0) : Vec3(10, 0, 0);
    EXPECT_GT(pn.normals.row(i).dot(V.row(i) - c.transpose()),
              0.9 * (V.row(i) - c.transpose()).norm())
        << i;
    EXPECT_EQ(pn.undetermined[static_cast<size_t>(i)], 0) << i;
  }
}

TEST(PointNormals, OpenPatchesPointUpward) {
  // A height field z = 0.3 (x^2 - y^2) over [-1, 1]^2: upward normals.
  VertexMatrix V = grid(30, 2.0 / 30);
  for (int i = 0; i < V.rows(); ++i) {
    V(i, 0) -= 1.0;
    V(i, 1) -= 1.0;
    V(i, 2) = 0.3 * (V(i, 0) * V(i, 0) - V(i, 1) * V(i, 1));
  }
  const PointNormals pn = oriented_pca_normals(PointSearch(V), 1);
  for (int i = 0; i < V.rows(); ++i) {
    EXPECT_GT(pn.normals(i, 2), 0.0) << i;
    EXPECT_EQ(pn.undetermined[static_cast<size_t>(i)], 0);
  }
}

TEST(PointNormals, AVerticalSheetAndACollinearSetAreUndetermined) {
  // The plane x = 0: the mean normal is horizontal, neither rule decides.
  VertexMatrix V = grid(10, 0.1);
  V.col(2) = V.col(0);
  V.col(0).setZero();
  PointNormals pn = oriented_pca_normals(PointSearch(V), 1);
  for (const unsigned char u : pn.undetermined) EXPECT_EQ(u, 1);
  VertexMatrix line(20, 3);
  for (int i = 0; i < 20; ++i) line.row(i) << i, 2 * i, 0.5 * i;
  pn = oriented_pca_normals(PointSearch(line), 1);
  for (const unsigned char u : pn.undetermined) EXPECT_EQ(u, 1);
}

TEST(PointNormals, OrientationIsPrimsTreeOnRandomTorusPoints) {
  expect_orientation_of_points_matches_oracle(torus_points(3000, 7));
}

TEST(PointNormals, OrientationIsPrimsTreeOnStructuredGridsOfExactTies) {
  // A flat grid (its PCA normals all the plane's) and a structured torus grid (ties by its
  // symmetry); with lattice normals most weights tie, so the tree is the ties' order (least
  // point, then least parent).
  EXPECT_GT(expect_orientation_of_points_matches_oracle(grid(40, 0.05, 0.3)), 20000);
  const int nu = 60, nv = 24;
  VertexMatrix T(nu * nv, 3);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2.0 * M_PI * i / nu, v = 2.0 * M_PI * j / nv, rho = 1.0 + 0.4 * std::cos(v);
      T.row(j * nu + i) << rho * std::cos(u), rho * std::sin(u), 0.4 * std::sin(v);
    }
  EXPECT_GT(expect_orientation_of_points_matches_oracle(T), 20000);
}

TEST(PointNormals, OrientationIsPrimsTreeOnTwoBlobsDuplicatesAndATinySet) {
  const VertexMatrix a = torus_points(1200, 3), b = sphere(700, 0.5, Vec3(10, 0, 0));
  VertexMatrix blobs(a.rows() + b.rows(), 3);
  blobs << b, a;
  expect_orientation_of_points_matches_oracle(blobs);
  VertexMatrix copies = torus_points(1500, 5);
  copies.conservativeResize(2000, 3);
  for (int i = 1500; i < 2000; ++i) copies.row(i) = copies.row((i * 7) % 1500);
  expect_orientation_of_points_matches_oracle(copies);
  expect_orientation_of_points_matches_oracle(torus_points(9, 11));  // rows of 8 < k
}

TEST(PointNormals, OrientationIsPrimsTreeOnRowsThatAreNotNearestNeighbours) {
  // Rows of 0 to 4 random others (few mutual edges, several components), random unit normals
  // and lattice ones.
  const int n = 3000;
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> other(0, n - 1), length(0, 4);
  std::normal_distribution<double> gauss;
  PointRows rows;
  for (int i = 0; i < n; ++i) {
    const int m = length(rng);
    for (int j = 0; j < m; ++j) rows.neighbours.push_back(other(rng));
    rows.offsets.push_back(static_cast<std::int64_t>(rows.neighbours.size()));
  }
  VertexMatrix points(n, 3), normals(n, 3);
  for (int i = 0; i < n; ++i) {
    const Vec3 p(gauss(rng), gauss(rng), gauss(rng)), q(gauss(rng), gauss(rng), gauss(rng));
    points.row(i) = p.transpose();
    normals.row(i) = q.normalized().transpose();
  }
  const std::vector<unsigned char> none(static_cast<size_t>(n), 0);
  expect_orientation_matches_oracle(points, rows, normals, none);
  expect_orientation_matches_oracle(points, rows, lattice_normals(n, 9), none);
}

}  // namespace
}  // namespace curvbench
