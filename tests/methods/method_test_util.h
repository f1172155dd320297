// Test meshes and exact quantities for the method tests (built here, independent of meshgen).
#pragma once

#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "core/types.h"
#include "mesh/mesh.h"
#include "meshgen/random.h"
#include "methods/estimator.h"

namespace curvbench::testing {

/// The same bits (NaN included; +0 and -0 differ).
inline bool same_bits(double x, double y) {
  return std::memcmp(&x, &y, sizeof(double)) == 0;
}
inline bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}

/// Every field of the two estimates has the same bits (NaN included).
inline bool bitwise_equal(const VertexEstimate& a, const VertexEstimate& b) {
  return same_bits(a.normal, b.normal) && same_bits(a.d1, b.d1) && same_bits(a.d2, b.d2) &&
         same_bits(a.k1, b.k1) && same_bits(a.k2, b.k2) && same_bits(a.H, b.H) &&
         same_bits(a.K, b.K) && a.degree == b.degree && a.points == b.points &&
         same_bits(a.ring, b.ring) && a.status == b.status;
}

/// (N+1) x (N+1) grid of the square [0, N h]^2, vertex (i, j) at index j (N+1) + i.
///   four_eight = false: every square split along (i,j)-(i+1,j+1): interior valence 6.
///   four_eight = true : split along (i,j)-(i+1,j+1) if i+j is even, else along the other
///                       diagonal: interior valences 8 (i+j even) and 4 (i+j odd).
/// Interior vertices are jittered by U(-jitter h, jitter h) in x and y; then the map takes the
/// planar point (x, y) to 3-D. Triangles are counter-clockwise in (x, y).
inline Mesh grid_mesh(int N, double h, bool four_eight, double jitter, std::uint64_t seed,
                      const std::function<Vec3(double, double)>& map) {
  Rng rng(seed);
  VertexMatrix V((N + 1) * (N + 1), 3);
  for (int j = 0; j <= N; ++j) {
    for (int i = 0; i <= N; ++i) {
      double x = i * h;
      double y = j * h;
      if (jitter > 0 && i > 0 && j > 0 && i < N && j < N) {
        x += rng.uniform(-jitter * h, jitter * h);
        y += rng.uniform(-jitter * h, jitter * h);
      }
      V.row(j * (N + 1) + i) = map(x, y).transpose();
    }
  }
  FaceMatrix F(2 * N * N, 3);
  int f = 0;
  auto id = [N](int i, int j) { return j * (N + 1) + i; };
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (!four_eight || (i + j) % 2 == 0) {
        F.row(f++) << a, b, c;
        F.row(f++) << a, c, d;
      } else {
        F.row(f++) << a, b, d;
        F.row(f++) << b, c, d;
      }
    }
  }
  return Mesh(V, F, "grid");
}

/// Icosahedron subdivided `level` times (midpoint split), projected onto the sphere of radius a
/// centred at the origin; faces counter-clockwise seen from outside. 10 * 4^level + 2 vertices.
inline Mesh icosphere(int level, double a) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> P = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> T = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (Vec3& p : P) p.normalize();
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      P.push_back((P[static_cast<size_t>(i)] + P[static_cast<size_t>(j)]).normalized());
      const int id = static_cast<int>(P.size()) - 1;
      mid.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& tri : T) {
      const int ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                ca = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    T = std::move(next);
  }
  VertexMatrix V(static_cast<Eigen::Index>(P.size()), 3);
  for (size_t i = 0; i < P.size(); ++i) V.row(static_cast<Eigen::Index>(i)) = a * P[i].transpose();
  FaceMatrix F(static_cast<Eigen::Index>(T.size()), 3);
  for (size_t f = 0; f < T.size(); ++f) {
    std::array<int, 3> tri = T[f];
    const Vec3 n = (P[static_cast<size_t>(tri[1])] - P[static_cast<size_t>(tri[0])])
                       .cross(P[static_cast<size_t>(tri[2])] - P[static_cast<size_t>(tri[0])]);
    if (n.dot(P[static_cast<size_t>(tri[0])]) < 0) std::swap(tri[1], tri[2]);
    F.row(static_cast<Eigen::Index>(f)) << tri[0], tri[1], tri[2];
  }
  return Mesh(V, F, "icosphere");
}

/// Exact quantities of the graph surface X(x, y) = R (x, y, P(x, y)) at a point where P has
/// gradient g and Hessian Hs (classical Monge-patch formulas; directions by the eigenvectors of
/// the non-symmetric Weingarten matrix W = G^-1 B, an independent route from the code's).
struct MongeExact {
  Vec3 normal;
  double k1, k2, H, K;
  Vec3 d1, d2;
};

inline MongeExact monge_exact(const Mat3& R, const Vec2& g, const Mat2& Hs) {
  MongeExact e;
  const double W = std::sqrt(1.0 + g.squaredNorm());
  e.normal = R * Vec3(-g.x(), -g.y(), 1.0) / W;
  const Mat2 G = Mat2::Identity() + g * g.transpose();
  const Mat2 B = Hs / W;
  const Mat2 Wm = G.inverse() * B;
  e.H = 0.5 * Wm.trace();
  e.K = Wm.determinant();
  const double disc = std::sqrt(std::max(0.0, e.H * e.H - e.K));
  e.k1 = e.H + disc;
  e.k2 = e.H - disc;
  // Eigenvector of Wm for k: (Wm - k I) d = 0.
  auto dir = [&](double k) {
    const Mat2 M = Wm - k * Mat2::Identity();
    Vec2 d = M.row(0).norm() > M.row(1).norm() ? Vec2(-M(0, 1), M(0, 0)) : Vec2(-M(1, 1), M(1, 0));
    const Vec3 t = R * Vec3(d.x(), d.y(), g.dot(d));  // J d with J = R [e1 e2; g^T]
    return Vec3(t.normalized());
  };
  e.d1 = dir(e.k1);
  e.d2 = dir(e.k2);
  return e;
}

/// Rotation from three angles (z-y-z).
inline Mat3 rotation(double a, double b, double c) {
  return (Eigen::AngleAxisd(a, Vec3::UnitZ()) * Eigen::AngleAxisd(b, Vec3::UnitY()) *
          Eigen::AngleAxisd(c, Vec3::UnitZ()))
      .toRotationMatrix();
}

/// Distance between unit directions up to sign.
inline double direction_error(const Vec3& a, const Vec3& b) {
  return std::min((a - b).norm(), (a + b).norm());
}

}  // namespace curvbench::testing
