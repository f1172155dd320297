// torus-anisotropic and bump-anisotropic (meshgen/anisotropic.h): vertices on the surface, exact
// quantities against finite differences, the measured stretch of the triangles against the
// aspect option, angles, sizes per level, determinism.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "bump_test_util.h"
#include "meshgen/anisotropic.h"
#include "meshgen/generate.h"
#include "tests/meshgen/identical_matrices.h"
#include "tests/meshgen/inward_faces.h"
#include "tests/surfaces/surface_test_util.h"
#include "torus_test_util.h"

namespace curvbench {
namespace {

GeneratedMesh stretched_mesh(const std::string& family, int level, double aspect) {
  MeshSpec spec;
  spec.family = family;
  spec.level = level;
  spec.shape.aspect = aspect;
  return generate_mesh(spec);
}

struct Stretch {
  double ratio = 0;  // largest over smallest singular value of the map equilateral -> triangle
  Vec3 along;        // direction of the largest stretch (unit, sign arbitrary)
};

// The affine map from the unit equilateral triangle onto triangle (a, b, c), in the triangle's
// plane: its singular values do not depend on which vertex maps to which.
Stretch stretch(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 t1 = e1.normalized(), t2 = e1.cross(e2).cross(e1).normalized();
  Mat2 P, Q;
  P << t1.dot(e1), t1.dot(e2), t2.dot(e1), t2.dot(e2);
  Q << 1.0, 0.5, 0.0, std::sqrt(3.0) / 2.0;
  const Eigen::JacobiSVD<Mat2> svd(P * Q.inverse(), Eigen::ComputeFullU);
  const Vec2 s = svd.singularValues();
  return {s(0) / s(1), (svd.matrixU()(0, 0) * t1 + svd.matrixU()(1, 0) * t2).normalized()};
}

double quantile(std::vector<double> x, double q) {
  std::sort(x.begin(), x.end());
  return x[static_cast<size_t>(q * static_cast<double>(x.size() - 1))];
}

// Stretch ratios of the faces (positions flattened to z = 0 when `flat`) and |cos| between
// the direction of largest stretch and `axis(centroid)`.
template <class Axis>
void stretches(const Mesh& m, bool flat, Axis axis, std::vector<double>& ratio,
               std::vector<double>& alignment) {
  for (int f = 0; f < m.num_faces(); ++f) {
    Vec3 p[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = m.position(m.face_vertex(f, k));
      if (flat) p[k].z() = 0.0;
    }
    const Stretch s = stretch(p[0], p[1], p[2]);
    ratio.push_back(s.ratio);
    alignment.push_back(std::abs(s.along.dot(axis((p[0] + p[1] + p[2]) / 3.0))));
  }
}

Vec3 parallel(const Vec3& c) {
  return Vec3(-c.y(), c.x(), 0.0).normalized();
}

// The smallest angle of an equilateral triangle stretched A > 1 times along its base (its base
// angles), degrees.
double planar_min_angle_deg(double aspect) {
  return std::atan(std::sqrt(3.0) / aspect) * 180.0 / std::numbers::pi;
}

// Conformal coordinates (u, w) of a torus point, w in (-W/2, W/2] (anisotropic.h): the closed
// form w(v) = (2r/c) atan(sqrt((R-r)/(R+r)) tan(v/2)), c = sqrt(R^2 - r^2).
Vec2 conformal(const Vec3& p) {
  const double R = testing::kTorusR, r = testing::kTorusr, c = std::sqrt(R * R - r * r);
  const double v = std::atan2(p.z(), std::hypot(p.x(), p.y()) - R);
  const double w =
      2.0 * r / c * std::atan2(std::sqrt((R - r) / (R + r)) * std::sin(v / 2), std::cos(v / 2));
  return {std::atan2(p.y(), p.x()), w};
}

// The faces' stretch in the (u, w) plane (each face unwrapped next to its first vertex).
std::vector<double> conformal_stretches(const Mesh& m) {
  const double R = testing::kTorusR, r = testing::kTorusr;
  const double period[2] = {2 * std::numbers::pi,
                            2 * std::numbers::pi * r / std::sqrt(R * R - r * r)};
  std::vector<double> ratio, alignment;
  for (int f = 0; f < m.num_faces(); ++f) {
    Vec3 p[3];
    const Vec2 first = conformal(m.position(m.face_vertex(f, 0)));
    for (int k = 0; k < 3; ++k) {
      Vec2 q = conformal(m.position(m.face_vertex(f, k)));
      for (int d = 0; d < 2; ++d) q(d) += period[d] * std::round((first(d) - q(d)) / period[d]);
      p[k] = Vec3(q(0), q(1), 0.0);
    }
    const Stretch s = stretch(p[0], p[1], p[2]);
    ratio.push_back(s.ratio);
    alignment.push_back(std::abs(s.along.x()));
  }
  EXPECT_GT(quantile(alignment, 0.0), 1.0 - 1e-9);  // the long side along u
  return ratio;
}

// Faces whose normal points into the tube (against the torus normal at the centroid).
int inverted_faces(const Mesh& m) {
  return testing::inward_faces(m, testing::torus_outward);
}

TEST(TorusAnisotropic, ClosedOutwardAndOnTheTorus) {
  for (double aspect : {2.0, 4.0})
    for (int level = 1; level <= 3; ++level) {
      const GeneratedMesh g = stretched_mesh("torus-anisotropic", level, aspect);
      const Mesh& m = g.mesh;
      EXPECT_EQ(g.family, "torus-anisotropic");
      EXPECT_EQ(g.level, level);
      EXPECT_EQ(g.surface->name(), "torus");
      EXPECT_EQ(m.num_faces(), 2 * m.num_vertices());
      EXPECT_EQ(m.euler_characteristic(), 0);
      EXPECT_EQ(m.num_boundary_edges(), 0);
      EXPECT_EQ(m.num_nonmanifold_edges(), 0);
      EXPECT_TRUE(m.is_consistently_oriented());
      EXPECT_EQ(g.exact_points, m.vertices());
      double worst = 0.0;
      for (int v = 0; v < m.num_vertices(); ++v)
        worst = std::max(worst, testing::torus_distance(m.position(v)));
      EXPECT_LT(worst, 1e-15);
      EXPECT_EQ(inverted_faces(m), 0);
    }
}

TEST(TorusAnisotropic, ExactQuantitiesMatchFiniteDifferences) {
  const GeneratedMesh g = stretched_mesh("torus-anisotropic", 1, 16.0);
  const Mesh& m = g.mesh;
  int compared = 0;
  for (int v = 0; v < m.num_vertices(); v += 7) {
    const Vec3 p = m.position(v);
    const double u = std::atan2(p.y(), p.x());
    const double w = std::atan2(p.z(), std::hypot(p.x(), p.y()) - testing::kTorusR);
    const SurfacePoint e = g.surface->evaluate(p);
    test::expect_frame_conventions(e, "torus-anisotropic");
    compared += test::expect_matches_reference(e, test::fd_reference(*g.surface, u, w), 1e-6, 1e-2,
                                               "torus-anisotropic");
    EXPECT_LT(e.H, 0.0);  // outward normals: H < 0 everywhere on this torus
  }
  EXPECT_GT(compared, 100);
}

TEST(TorusAnisotropic, StretchIsTheAspectAlongTheParallels) {
  // In conformal coordinates every triangle is the grid's: stretch A' within 2% of A, along u.
  for (double aspect : {1.5, 4.0, 16.0})
    for (int level = 1; level <= (aspect < 6 ? 4 : 3); ++level) {
      SCOPED_TRACE("A=" + std::to_string(aspect) + " level " + std::to_string(level));
      const std::vector<double> ratio =
          conformal_stretches(stretched_mesh("torus-anisotropic", level, aspect).mesh);
      const double grid = quantile(ratio, 0.5);
      EXPECT_NEAR(grid / aspect, 1.0, 0.02);
      EXPECT_NEAR(quantile(ratio, 0.0) / grid, 1.0, 1e-9);
      EXPECT_NEAR(quantile(ratio, 1.0) / grid, 1.0, 1e-9);
    }
}

TEST(TorusAnisotropic, TheTrianglesOnTheTorusApproachTheGrid) {
  // On the torus the triangles are bent by O(h): their stretch tends to the grid's A' (measured,
  // A = 4: median 0.966, 0.991, 0.998, 0.9995 A' at levels 1-4), the same inside and outside the
  // tube (the conformal coordinates), and the smallest angle to the planar atan(sqrt(3)/A').
  const double aspect = 4.0;
  double previous_gap = 1.0;
  for (int level = 1; level <= 4; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    const Mesh m = stretched_mesh("torus-anisotropic", level, aspect).mesh;
    const double grid = quantile(conformal_stretches(m), 0.5);
    std::vector<double> ratio, alignment, inner, outer;
    stretches(m, false, parallel, ratio, alignment);
    for (int f = 0; f < m.num_faces(); ++f) {
      const Vec3 c = (m.position(m.face_vertex(f, 0)) + m.position(m.face_vertex(f, 1)) +
                      m.position(m.face_vertex(f, 2))) /
                     3.0;
      (std::hypot(c.x(), c.y()) < testing::kTorusR ? inner : outer)
          .push_back(ratio[static_cast<size_t>(f)]);
    }
    const double gap = std::abs(quantile(ratio, 0.5) / grid - 1.0);
    EXPECT_LT(gap, previous_gap);
    previous_gap = gap;
    if (level > 1) {
      EXPECT_NEAR(quantile(inner, 0.5) / quantile(outer, 0.5), 1.0, 0.01);
    }
    EXPECT_GT(quantile(alignment, 0.02), 0.99);
    EXPECT_EQ(inverted_faces(m), 0);
    EXPECT_EQ(mesh_quality(m).min_valence, 6);
    EXPECT_EQ(mesh_quality(m).max_valence, 6);
    if (level == 4) {
      EXPECT_LT(gap, 0.005);
      EXPECT_NEAR(quantile(ratio, 0.1) / grid, 1.0, 0.06);
      EXPECT_NEAR(quantile(ratio, 0.9) / grid, 1.0, 0.06);
      EXPECT_GT(mesh_quality(m).min_angle_deg, 0.95 * planar_min_angle_deg(grid));
    }
  }
}

TEST(TorusAnisotropic, NoLevelFoldsAndTheSagStaysWithinHalfARow) {
  // A base du along a parallel sags sideways by about du^2/8 near the top and bottom of the
  // tube, a row is du sqrt(3)/(2A') high: of two neighbouring triangles there one loses that
  // height, the other gains it, so the largest stretch is about A' / (1 - du A' / (4 sqrt(3))).
  // Level 1 keeps du A' <= 2 sqrt(3) (anisotropic.h): no face turns over, the largest stretch is
  // at most about 2A' (measured 1.42, 2.02, 2.01 A' at A = 4, 8, 16) and its excess over A' at
  // least halves per level, as du does. At A = 16 the grid nearest 256 points (7 x 40, du A' =
  // 14.1) had inverted faces on levels 1 and 2.
  for (double aspect : {4.0, 8.0, 16.0}) {
    double previous_excess = 0.0;
    for (int level = 1; level <= 3; ++level) {
      SCOPED_TRACE("A=" + std::to_string(aspect) + " level " + std::to_string(level));
      const Mesh m = stretched_mesh("torus-anisotropic", level, aspect).mesh;
      EXPECT_EQ(inverted_faces(m), 0);
      const double grid = quantile(conformal_stretches(m), 0.5);
      std::vector<double> ratio, alignment;
      stretches(m, false, parallel, ratio, alignment);
      const double excess = quantile(ratio, 1.0) / grid - 1.0;
      EXPECT_LT(excess, 1.05);
      if (level > 1) {
        EXPECT_LT(excess, previous_excess / 2.0);
      }
      previous_excess = excess;
    }
  }
  // A = 16, level 1: the fewest columns (n_u = 29) with du A' <= 2 sqrt(3); 28 would exceed it.
  const GeneratedMesh a16 = stretched_mesh("torus-anisotropic", 1, 16.0);
  EXPECT_NE(a16.description.find("n_u=29 n_w=168"), std::string::npos) << a16.description;
  const double grid = quantile(conformal_stretches(a16.mesh), 0.5);
  EXPECT_LE(2.0 * std::numbers::pi / 29.0 * grid, 2.0 * std::sqrt(3.0));
  EXPECT_GT(2.0 * std::numbers::pi / 28.0 * grid, 2.0 * std::sqrt(3.0));
}

TEST(TorusAnisotropic, LevelsHalveH) {
  // Level 4 stays below 20000 vertices where the grid nearest 256 points is fold-free (A <= 6);
  // A = 16 starts at 29 x 168 (anisotropic.h).
  for (double aspect : {4.0, 16.0}) {
    double previous_h = 0.0;
    int previous_v = 0;
    for (int level = 1; level <= (aspect < 6 ? 4 : 3); ++level) {
      const Mesh m = stretched_mesh("torus-anisotropic", level, aspect).mesh;
      if (level > 1) {
        EXPECT_EQ(m.num_vertices(), 4 * previous_v);
        EXPECT_NEAR(previous_h / m.mean_edge_length(), 2.0, 0.05);
      }
      previous_h = m.mean_edge_length();
      previous_v = m.num_vertices();
    }
    if (aspect < 6) {
      EXPECT_LT(previous_v, 20000);
      EXPECT_GT(previous_v, 10000);
    }
  }
  EXPECT_EQ(stretched_mesh("torus-anisotropic", 1, 16.0).mesh.num_vertices(), 29 * 168);
}

TEST(TorusAnisotropic, DeterministicAndTheAspectChangesTheMesh) {
  MeshSpec spec{"torus-anisotropic", 2};
  const GeneratedMesh a = generate_mesh(spec), b = generate_mesh(spec);
  EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
  EXPECT_TRUE(test::identical(a.mesh.faces(), b.mesh.faces()));
  spec.shape.aspect = kDefaultAspect;  // the default, given
  EXPECT_TRUE(test::identical(generate_mesh(spec).mesh.vertices(), a.mesh.vertices()));
  spec.shape.aspect = 16.0;
  const GeneratedMesh c = generate_mesh(spec);
  EXPECT_NE(c.description, a.description);
  EXPECT_FALSE(test::identical(c.mesh.vertices(), a.mesh.vertices()));
}

TEST(BumpAnisotropic, SquareDomainOnTheBumpExactQuantities) {
  for (double aspect : {4.0, 16.0})
    for (int level = 1; level <= 3; ++level) {
      const GeneratedMesh g = stretched_mesh("bump-anisotropic", level, aspect);
      EXPECT_EQ(g.family, "bump-anisotropic");
      EXPECT_EQ(g.level, level);
      testing::expect_square_bump_mesh(g);
      if (level == 2) {
        EXPECT_GT(testing::expect_bump_exact_matches_fd(g, 5), 100);
      }
    }
}

TEST(BumpAnisotropic, StretchIsTheAspectAlongX) {
  // In the domain the interior triangles are the grid's exactly (A' within 2% of A); the half
  // triangles at x = 0 and 1 (2 of the 2 n_x + 1 per row, n_x >= 4: below 23%) stretch
  // otherwise, so the quartiles exclude them. The smallest planar angle is the base angle
  // atan(sqrt(3)/A'), or for A' < sqrt(3) that of the half triangles, atan(A'/sqrt(3)).
  for (double aspect : {1.5, 4.0, 16.0})
    for (int level = 1; level <= 3; ++level) {
      const GeneratedMesh g = stretched_mesh("bump-anisotropic", level, aspect);
      std::vector<double> ratio, alignment;
      stretches(
          g.mesh, true, [](const Vec3&) { return Vec3(1, 0, 0); }, ratio, alignment);
      SCOPED_TRACE("A=" + std::to_string(aspect) + " level " + std::to_string(level));
      const double median = quantile(ratio, 0.5);
      EXPECT_NEAR(median / aspect, 1.0, 0.02);
      EXPECT_NEAR(quantile(ratio, 0.25) / median, 1.0, 1e-9);
      EXPECT_NEAR(quantile(ratio, 0.75) / median, 1.0, 1e-9);
      EXPECT_GT(quantile(alignment, 0.25), 1.0 - 1e-9);
      VertexMatrix flat = g.mesh.vertices();
      flat.col(2).setZero();
      const MeshQuality q = mesh_quality(Mesh(flat, g.mesh.faces()));
      EXPECT_NEAR(q.min_angle_deg,
                  std::min(planar_min_angle_deg(median), 90.0 - planar_min_angle_deg(median)),
                  1e-9);
      flat.col(0) /= median;  // the equilateral lattice: Delaunay
      EXPECT_EQ(testing::delaunay_violations(Mesh(flat, g.mesh.faces())), 0);
    }
}

TEST(BumpAnisotropic, LevelsHalveHAndStayCheap) {
  // The grid's spacings halve (the median planar edge); the mean edge length less so on the
  // coarse levels, where the short edges of the sides x = 0, 1 weigh more (3D mean ratios 1.82,
  // 1.92, 1.96 for A = 16).
  for (double aspect : {4.0, 16.0}) {
    double previous = 0.0;
    for (int level = 1; level <= 4; ++level) {
      const Mesh m = stretched_mesh("bump-anisotropic", level, aspect).mesh;
      std::vector<double> length, x;
      testing::planar_edges(m, length, x);
      const double median = quantile(length, 0.5);
      if (level > 1) {
        EXPECT_NEAR(previous / median, 2.0, 1e-9);
      }
      previous = median;
      if (level == 4) {
        EXPECT_LT(m.num_vertices(), 20000);
        EXPECT_GT(m.num_vertices(), 10000);
      }
    }
  }
}

TEST(BumpAnisotropic, Deterministic) {
  const GeneratedMesh a = stretched_mesh("bump-anisotropic", 2, 8.0),
                      b = stretched_mesh("bump-anisotropic", 2, 8.0);
  EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
  EXPECT_TRUE(test::identical(a.mesh.faces(), b.mesh.faces()));
}

}  // namespace
}  // namespace curvbench
