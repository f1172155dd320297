// Closed meshes with creases known by construction, for the crease tests (mesh/creases.h) and the
// noise estimate's (harness/model/noise_estimate.h): each comes with the sharp edges it was built
// with, so a test compares sets instead of counting.
//   meshed_cube(n)              [-1,1]^3, each face an n x n grid of split squares; the 12 edges
//                               of the cube are sharp (90 degrees), nothing else
//   capped_cylinder(m, k, c)    radius 1, z in [-1,1]; m sectors, k slices, caps of c rings; the
//                               two rim circles are sharp (90 degrees); the side turns by 360/m
//                               degrees between slices, the caps are flat
//   fandisk_like_part()         a prism y in [-1,1] over a profile in x in [-1,1]: a flat top
//                               (z = 1), a ramp down to z = 0.5 (slope -2.5, x in [-0.4, -0.2])
//                               and a smooth arc z = 0.5 + 0.5 sin(pi (x + 0.2) / 2.4) back up
//                               to z = 1, on a flat bottom; sharp: the ramp's top (68.2 degrees,
//                               convex) and foot (101.3, concave), the top's edges on the sides
//                               (90, and 92.4 where the arc ends), the bottom's (90), and the
//                               outlines of both end caps (90); the arc turns by at most 4.8
//                               degrees between strips
//   with_isotropic_noise(m, s)  every vertex moved by s h N(0, 1) along each axis (h the mean
//                               edge length), seeded: std::mt19937_64 (its sequence is fixed by
//                               the standard) and Box-Muller
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <random>
#include <vector>

#include "mesh/mesh.h"

namespace curvbench::crease_test {

struct CreasedMesh {
  Mesh mesh;
  std::vector<std::array<int, 2>> sharp_edges;  ///< {a, b}, a < b, sorted
  std::vector<int> crease_vertices;             ///< the sharp edges' endpoints, sorted
};

class Builder {
 public:
  int vertex(const Vec3& p) {
    points_.push_back(p);
    return static_cast<int>(points_.size()) - 1;
  }
  // Triangle a, b, c, reversed if its normal points against `outward`.
  void triangle(int a, int b, int c, const Vec3& outward) {
    const Vec3 n =
        (points_[size_t(b)] - points_[size_t(a)]).cross(points_[size_t(c)] - points_[size_t(a)]);
    if (n.dot(outward) < 0) std::swap(b, c);
    faces_.push_back({a, b, c});
  }
  // Quad a, b, c, d (in order around it) as the triangles a b c and a c d.
  void quad(int a, int b, int c, int d, const Vec3& outward) {
    triangle(a, b, c, outward);
    triangle(a, c, d, outward);
  }
  void sharp(int a, int b) { sharp_.push_back({std::min(a, b), std::max(a, b)}); }
  const Vec3& point(int v) const { return points_[size_t(v)]; }

  CreasedMesh build() {
    VertexMatrix V(static_cast<Eigen::Index>(points_.size()), 3);
    for (size_t i = 0; i < points_.size(); ++i) V.row(static_cast<Eigen::Index>(i)) = points_[i];
    FaceMatrix F(static_cast<Eigen::Index>(faces_.size()), 3);
    for (size_t f = 0; f < faces_.size(); ++f)
      F.row(static_cast<Eigen::Index>(f)) << faces_[f][0], faces_[f][1], faces_[f][2];
    CreasedMesh out{Mesh(V, F), sharp_, {}};
    std::sort(out.sharp_edges.begin(), out.sharp_edges.end());
    out.sharp_edges.erase(std::unique(out.sharp_edges.begin(), out.sharp_edges.end()),
                          out.sharp_edges.end());
    for (const auto& e : out.sharp_edges) {
      out.crease_vertices.push_back(e[0]);
      out.crease_vertices.push_back(e[1]);
    }
    std::sort(out.crease_vertices.begin(), out.crease_vertices.end());
    out.crease_vertices.erase(std::unique(out.crease_vertices.begin(), out.crease_vertices.end()),
                              out.crease_vertices.end());
    return out;
  }

 private:
  std::vector<Vec3> points_;
  std::vector<std::array<int, 3>> faces_;
  std::vector<std::array<int, 2>> sharp_;
};

inline CreasedMesh meshed_cube(int n) {
  Builder b;
  std::map<std::array<int, 3>, int> index;  // grid point (0..n)^3 -> vertex
  auto at = [&](std::array<int, 3> g) {
    auto [it, added] = index.try_emplace(g, 0);
    if (added)
      it->second =
          b.vertex(Vec3(-1.0 + 2.0 * g[0] / n, -1.0 + 2.0 * g[1] / n, -1.0 + 2.0 * g[2] / n));
    return it->second;
  };
  for (int a = 0; a < 3; ++a)
    for (int side : {0, n}) {
      const int u = (a + 1) % 3, w = (a + 2) % 3;
      Vec3 outward = Vec3::Zero();
      outward[a] = side == 0 ? -1.0 : 1.0;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          std::array<int, 3> g00{}, g10{}, g11{}, g01{};
          for (auto* g : {&g00, &g10, &g11, &g01}) (*g)[size_t(a)] = side;
          g00[size_t(u)] = i, g00[size_t(w)] = j;
          g10[size_t(u)] = i + 1, g10[size_t(w)] = j;
          g11[size_t(u)] = i + 1, g11[size_t(w)] = j + 1;
          g01[size_t(u)] = i, g01[size_t(w)] = j + 1;
          b.quad(at(g00), at(g10), at(g11), at(g01), outward);
        }
    }
  // The 12 edges of the cube: along axis a, the other two coordinates at 0 or n.
  for (int a = 0; a < 3; ++a)
    for (int s : {0, n})
      for (int t : {0, n})
        for (int i = 0; i < n; ++i) {
          std::array<int, 3> p{}, q{};
          p[size_t(a)] = i, q[size_t(a)] = i + 1;
          p[size_t((a + 1) % 3)] = q[size_t((a + 1) % 3)] = s;
          p[size_t((a + 2) % 3)] = q[size_t((a + 2) % 3)] = t;
          b.sharp(at(p), at(q));
        }
  return b.build();
}

inline CreasedMesh capped_cylinder(int m, int k, int c) {
  Builder b;
  const double pi = std::numbers::pi;
  auto ring_point = [&](double r, int i, double z) {
    const double t = 2.0 * pi * i / m;
    return Vec3(r * std::cos(t), r * std::sin(t), z);
  };
  // side[j][i]: the side's rings, j = 0 (z = -1) .. k (z = 1).
  std::vector<std::vector<int>> side(size_t(k + 1));
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i < m; ++i)
      side[size_t(j)].push_back(b.vertex(ring_point(1.0, i, -1.0 + 2.0 * j / k)));
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < m; ++i) {
      const int i1 = (i + 1) % m;
      const Vec3 out = ring_point(1.0, i, 0.0) + ring_point(1.0, i1, 0.0);
      b.quad(side[size_t(j)][size_t(i)], side[size_t(j)][size_t(i1)],
             side[size_t(j + 1)][size_t(i1)], side[size_t(j + 1)][size_t(i)], out);
    }
  for (int cap : {0, k}) {
    const double z = cap == 0 ? -1.0 : 1.0;
    const Vec3 out(0, 0, z);
    const int centre = b.vertex(Vec3(0, 0, z));
    std::vector<int> inner;  // ring l = 1 .. c-1 of radius l / c, then the side's ring
    for (int l = 1; l <= c; ++l) {
      std::vector<int> ring;
      for (int i = 0; i < m; ++i)
        ring.push_back(l == c ? side[size_t(cap)][size_t(i)]
                              : b.vertex(ring_point(double(l) / c, i, z)));
      for (int i = 0; i < m; ++i) {
        const int i1 = (i + 1) % m;
        if (l == 1)
          b.triangle(centre, ring[size_t(i)], ring[size_t(i1)], out);
        else
          b.quad(inner[size_t(i)], ring[size_t(i)], ring[size_t(i1)], inner[size_t(i1)], out);
      }
      inner = ring;
    }
    for (int i = 0; i < m; ++i)
      b.sharp(side[size_t(cap)][size_t(i)], side[size_t(cap)][size_t((i + 1) % m)]);
  }
  return b.build();
}

// The profile's height over x in [-1, 1] (see the file comment), sampled at x = -1 + 0.1 i.
inline double fandisk_profile(double x) {
  if (x <= -0.4 + 1e-12) return 1.0;
  if (x <= -0.2 + 1e-12) return 1.0 - 2.5 * (x + 0.4);
  return 0.5 + 0.5 * std::sin(std::numbers::pi * (x + 0.2) / 2.4);
}

inline CreasedMesh fandisk_like_part() {
  constexpr int nx = 20, ny = 20;
  constexpr int kRampTop = 6, kRampFoot = 8;  // the profile's corners: x = -0.4 and -0.2
  Builder b;
  std::vector<std::vector<int>> top(nx + 1), bottom(nx + 1);  // [i][j]
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) {
      const double x = -1.0 + 0.1 * i, y = -1.0 + 0.1 * j;
      top[size_t(i)].push_back(b.vertex(Vec3(x, y, fandisk_profile(x))));
      bottom[size_t(i)].push_back(b.vertex(Vec3(x, y, 0.0)));
    }
  auto T = [&](int i, int j) { return top[size_t(i)][size_t(j)]; };
  auto B = [&](int i, int j) { return bottom[size_t(i)][size_t(j)]; };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      b.quad(T(i, j), T(i + 1, j), T(i + 1, j + 1), T(i, j + 1), Vec3(0, 0, 1));
      b.quad(B(i, j), B(i + 1, j), B(i + 1, j + 1), B(i, j + 1), Vec3(0, 0, -1));
    }
  for (int j = 0; j < ny; ++j) {  // the sides x = -1 and x = 1, one strip high
    b.quad(B(0, j), B(0, j + 1), T(0, j + 1), T(0, j), Vec3(-1, 0, 0));
    b.quad(B(nx, j), B(nx, j + 1), T(nx, j + 1), T(nx, j), Vec3(1, 0, 0));
  }
  for (int i = 0; i < nx; ++i) {  // the end caps y = -1 and y = 1, one strip per column
    b.quad(B(i, 0), B(i + 1, 0), T(i + 1, 0), T(i, 0), Vec3(0, -1, 0));
    b.quad(B(i, ny), B(i + 1, ny), T(i + 1, ny), T(i, ny), Vec3(0, 1, 0));
  }
  for (int j = 0; j < ny; ++j) {
    for (int i : {0, kRampTop, kRampFoot, nx}) b.sharp(T(i, j), T(i, j + 1));
    for (int i : {0, nx}) b.sharp(B(i, j), B(i, j + 1));
  }
  for (int j : {0, ny}) {
    for (int i = 0; i < nx; ++i) {
      b.sharp(T(i, j), T(i + 1, j));
      b.sharp(B(i, j), B(i + 1, j));
    }
    b.sharp(B(0, j), T(0, j));
    b.sharp(B(nx, j), T(nx, j));
  }
  return b.build();
}

inline Mesh with_isotropic_noise(const Mesh& mesh, double sigma_over_h, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  auto uniform = [&] { return (static_cast<double>(engine() >> 11) + 0.5) * 0x1p-53; };
  const double sigma = sigma_over_h * mesh.mean_edge_length();
  VertexMatrix V = mesh.vertices();
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    for (int d = 0; d < 3; ++d)
      V(v, d) += sigma * std::sqrt(-2.0 * std::log(uniform())) *
                 std::cos(2.0 * std::numbers::pi * uniform());
  return Mesh(V, mesh.faces());
}

}  // namespace curvbench::crease_test
