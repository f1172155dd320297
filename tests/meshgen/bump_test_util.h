// Checks shared by the Gaussian-bump mesh tests: a mesh of the square [0,1]^2 lifted onto the
// bump, exact quantities against finite differences, the Delaunay property in the plane.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "meshgen/generated_mesh.h"
#include "tests/surfaces/surface_test_util.h"

namespace curvbench::testing {

/// Consistently oriented disc over exactly [0,1]^2 (ccw faces in xy of total area 1), with the
/// vertices of the square's sides as its boundary, every vertex on the bump, exact points equal
/// to the vertices.
inline void expect_square_bump_mesh(const GeneratedMesh& g) {
  const Mesh& m = g.mesh;
  EXPECT_EQ(g.surface->name(), "bump");
  EXPECT_EQ(m.euler_characteristic(), 1);
  EXPECT_EQ(m.num_nonmanifold_edges(), 0);
  EXPECT_EQ(m.num_isolated_vertices(), 0);
  EXPECT_TRUE(m.is_consistently_oriented());
  EXPECT_EQ(g.exact_points, m.vertices());
  double area = 0.0, min_area = 1.0;
  for (int f = 0; f < m.num_faces(); ++f) {
    const Vec3 a = m.position(m.face_vertex(f, 0)), b = m.position(m.face_vertex(f, 1)),
               c = m.position(m.face_vertex(f, 2));
    const double xy = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    area += xy;
    min_area = std::min(min_area, xy);
  }
  EXPECT_GT(min_area, 0.0);  // ccw in xy: normals up
  EXPECT_NEAR(area, 1.0, 1e-12);
  for (int v = 0; v < m.num_vertices(); ++v) {
    const Vec3 p = m.position(v);
    ASSERT_TRUE(p.x() >= 0.0 && p.x() <= 1.0 && p.y() >= 0.0 && p.y() <= 1.0) << v;
    ASSERT_EQ(p.z(), g.surface->position(p.x(), p.y()).z()) << v;
    const bool on_square = p.x() == 0.0 || p.x() == 1.0 || p.y() == 0.0 || p.y() == 1.0;
    ASSERT_EQ(on_square, m.is_boundary_vertex(v)) << v;
  }
}

/// The exact quantities at every `step`-th vertex at least 0.01 inside the square against finite
/// differences of the bump's parameterization, and the conventions of surface.h; returns the
/// number of vertices compared.
inline int expect_bump_exact_matches_fd(const GeneratedMesh& g, int step) {
  int compared = 0;
  for (int v = 0; v < g.mesh.num_vertices(); v += step) {
    const Vec3 p = g.mesh.position(v);
    if (p.x() < 1e-2 || p.x() > 1 - 1e-2 || p.y() < 1e-2 || p.y() > 1 - 1e-2) continue;
    const SurfacePoint e = g.surface->evaluate(p);
    test::expect_frame_conventions(e, g.family.c_str());
    test::expect_matches_reference(e, test::fd_reference(*g.surface, p.x(), p.y()), 1e-6, 1e-2,
                                   g.family.c_str());
    EXPECT_GT(e.normal.z(), 0.0);  // upward
    ++compared;
  }
  return compared;
}

/// Interior edges whose two opposite angles in the xy plane sum to more than pi (0 for a
/// Delaunay triangulation).
inline int delaunay_violations(const Mesh& m) {
  int violations = 0;
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = m.face_neighbor(f, k);
      if (g < 0) continue;
      const int a = m.face_vertex(f, k), b = m.face_vertex(f, (k + 1) % 3);
      const int c = m.face_vertex(f, (k + 2) % 3);
      int d = -1;
      for (int l = 0; l < 3; ++l)
        if (m.face_vertex(g, l) != a && m.face_vertex(g, l) != b) d = m.face_vertex(g, l);
      auto angle_at = [&m](int apex, int p, int q) {
        const Vec2 u = (m.position(p) - m.position(apex)).head<2>();
        const Vec2 w = (m.position(q) - m.position(apex)).head<2>();
        return std::atan2(std::abs(u.x() * w.y() - u.y() * w.x()), u.dot(w));
      };
      if (angle_at(c, a, b) + angle_at(d, a, b) > std::numbers::pi + 1e-9) ++violations;
    }
  return violations;
}

/// Planar edge lengths (xy) and the x of their midpoints, each edge once.
inline void planar_edges(const Mesh& m, std::vector<double>& length, std::vector<double>& x) {
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.face_vertex(f, k), b = m.face_vertex(f, (k + 1) % 3);
      if (a > b && m.face_neighbor(f, k) >= 0) continue;  // interior edges from one side
      const Vec3 p = m.position(a), q = m.position(b);
      length.push_back(std::hypot(p.x() - q.x(), p.y() - q.y()));
      x.push_back(0.5 * (p.x() + q.x()));
    }
}

}  // namespace curvbench::testing
