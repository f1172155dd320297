// The Schwarz lantern families `lantern` and `lantern-squeezed` (meshgen/lantern.h): vertices on
// the cylinder, exact quantities against finite differences, the sign convention, determinism,
// level sizes, and the defining difference: the lantern's face normals and area converge to the
// cylinder's, the squeezed lantern's do not, while its positions do.
#include "meshgen/lantern.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "meshgen/generate.h"
#include "surfaces/cylinder.h"
#include "tests/meshgen/identical_matrices.h"
#include "tests/surfaces/surface_test_util.h"

namespace curvbench {
namespace {

constexpr const char* kFamilies[] = {"lantern", "lantern-squeezed"};

GeneratedMesh lantern_family_mesh(const std::string& family, int level) {
  return generate_mesh(MeshSpec{family, level});
}

Vec3 corner(const Mesh& m, int f, int k) {
  return m.position(m.face_vertex(f, k));
}

// What the faces say about the surface: the largest |n_f - n| between a face's normal and the
// exact normal at its centroid, the largest distance of a centroid from the cylinder, and the
// mesh's area over the cylinder's (2 pi r h = 4 pi).
struct FaceFacts {
  double normal_error = 0.0, centroid_distance = 0.0, area_ratio = 0.0;
};

FaceFacts face_facts(const GeneratedMesh& g) {
  FaceFacts r;
  double area = 0.0;
  for (int f = 0; f < g.mesh.num_faces(); ++f) {
    const Vec3 a = corner(g.mesh, f, 0), b = corner(g.mesh, f, 1), c = corner(g.mesh, f, 2);
    const Vec3 cross = (b - a).cross(c - a);
    const Vec3 centroid = (a + b + c) / 3.0;
    const Vec3 n = g.surface->evaluate(centroid).normal;
    r.normal_error = std::max(r.normal_error, (cross.normalized() - n).norm());
    r.centroid_distance =
        std::max(r.centroid_distance, 1.0 - std::hypot(centroid.x(), centroid.y()));
    area += 0.5 * cross.norm();
  }
  r.area_ratio = area / (4.0 * std::numbers::pi);
  return r;
}

TEST(Lantern, LevelSizes) {
  for (bool squeezed : {false, true}) {
    int previous = 0;
    for (int level = 1; level <= 4; ++level) {
      const LanternSize s = lantern_size(squeezed, level);
      // lantern: sectors double, slices grow with them; squeezed: with their square.
      if (squeezed) {
        EXPECT_EQ(4 * s.slices, s.sectors * s.sectors);
      } else {
        EXPECT_EQ(s.sectors, 16 << (level - 1));
        EXPECT_EQ(2 * s.slices, s.sectors);
      }
      const GeneratedMesh g = lantern_family_mesh(kFamilies[squeezed], level);
      EXPECT_EQ(g.mesh.num_vertices(), (s.slices + 1) * s.sectors);
      EXPECT_EQ(g.mesh.num_faces(), 2 * s.slices * s.sectors);
      EXPECT_GT(g.mesh.num_vertices(), 2 * previous);
      EXPECT_LT(g.mesh.num_vertices(), 20000);
      previous = g.mesh.num_vertices();
    }
  }
  EXPECT_EQ(max_mesh_level("lantern"), 4);
  EXPECT_EQ(max_mesh_level("lantern-squeezed"), 4);
  EXPECT_THROW(lantern_family_mesh("lantern", 5), UsageError);
  EXPECT_THROW(lantern_mesh({2, 4}), UsageError);
  EXPECT_THROW(lantern_mesh({8, 0}), UsageError);
}

TEST(Lantern, OnTheCylinderOrientedOutwardOpenAtBothEnds) {
  for (const char* family : kFamilies) {
    for (int level = 1; level <= 3; ++level) {
      const GeneratedMesh g = lantern_family_mesh(family, level);
      SCOPED_TRACE(std::string(family) + " level " + std::to_string(level));
      const Mesh& m = g.mesh;
      EXPECT_EQ(g.family, family);
      EXPECT_EQ(g.level, level);
      ASSERT_EQ(g.surface->name(), "cylinder");
      EXPECT_EQ(g.exact_points, m.vertices());
      double worst = 0.0;
      for (int v = 0; v < m.num_vertices(); ++v) {
        const Vec3 p = m.position(v);
        worst = std::max(worst, std::abs(std::hypot(p.x(), p.y()) - 1.0));
        EXPECT_LE(std::abs(p.z()), 1.0 + 1e-15);
      }
      EXPECT_LT(worst, 1e-15);
      EXPECT_TRUE(m.is_consistently_oriented());
      int inward = 0;
      for (int f = 0; f < m.num_faces(); ++f) {
        const Vec3 a = corner(m, f, 0), b = corner(m, f, 1), c = corner(m, f, 2);
        const Vec3 centroid = (a + b + c) / 3.0;
        if ((b - a).cross(c - a).dot(Vec3(centroid.x(), centroid.y(), 0.0)) <= 0) ++inward;
      }
      EXPECT_EQ(inward, 0);
      // Two boundary circles of n vertices each (the rings z = -1 and z = 1); valence 6 inside.
      const int n = lantern_size(std::string(family) == "lantern-squeezed", level).sectors;
      EXPECT_EQ(m.num_boundary_vertices(), 2 * n);
      EXPECT_EQ(m.num_boundary_edges(), 2 * n);
      for (int v = 0; v < m.num_vertices(); ++v)
        EXPECT_EQ(m.is_boundary_vertex(v), std::abs(std::abs(m.position(v).z()) - 1.0) < 1e-12);
      const MeshQuality q = mesh_quality(m);
      EXPECT_EQ(q.min_valence, 6);
      EXPECT_EQ(q.max_valence, 6);
    }
  }
}

// Exact quantities at the vertices against finite differences of the parameterization
// (u = angle, v = height), and the sign convention: outward radial normal, k1 = 0 >= k2 = -1,
// H = -1/2, K = 0, d1 along the axis, orthogonal to n.
TEST(Lantern, ExactQuantitiesAndSignConvention) {
  for (const char* family : kFamilies) {
    const GeneratedMesh g = lantern_family_mesh(family, 2);
    for (int v = 0; v < g.mesh.num_vertices(); v += 7) {
      const Vec3 p = g.exact_points.row(v).transpose();
      const SurfacePoint e = g.surface->evaluate(p);
      const std::string where = std::string(family) + " vertex " + std::to_string(v);
      const test::Reference ref = test::fd_reference(*g.surface, std::atan2(p.y(), p.x()), p.z());
      EXPECT_TRUE(test::expect_matches_reference(e, ref, 1e-6, 1e-2, where.c_str()));
      test::expect_frame_conventions(e, where.c_str());
      EXPECT_GT(e.normal.dot(Vec3(p.x(), p.y(), 0.0)), 0.99);
      EXPECT_EQ(e.k1, 0.0);
      EXPECT_EQ(e.k2, -1.0);
      EXPECT_EQ(e.H, -0.5);
      EXPECT_EQ(e.K, 0.0);
      EXPECT_EQ(std::abs(e.d1.z()), 1.0);
      EXPECT_EQ(e.d1.dot(e.normal), 0.0);
    }
  }
}

TEST(Lantern, Deterministic) {
  for (const char* family : kFamilies) {
    const GeneratedMesh a = lantern_family_mesh(family, 3), b = lantern_family_mesh(family, 3);
    EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
    EXPECT_TRUE(test::identical(a.mesh.faces(), b.mesh.faces()));
    EXPECT_EQ(a.description, b.description);
  }
}

// `lantern`: slices ~ sectors, the faces' tilt ~ pi^2 m / (4 n^2) halves per level, so the face
// normals converge (first order) and so does the area.
TEST(Lantern, FaceNormalsAndAreaConverge) {
  FaceFacts previous;
  for (int level = 1; level <= 4; ++level) {
    const FaceFacts f = face_facts(lantern_family_mesh("lantern", level));
    SCOPED_TRACE(level);
    if (level > 1) {
      EXPECT_LT(f.normal_error, 0.55 * previous.normal_error);
      EXPECT_LT(f.centroid_distance, 0.3 * previous.centroid_distance);
      EXPECT_LT(std::abs(f.area_ratio - 1.0), 0.3 * std::abs(previous.area_ratio - 1.0));
    }
    previous = f;
  }
  EXPECT_LT(previous.normal_error, 0.0105);  // the tilt pi^2/(8 n) at n = 128
  EXPECT_LT(std::abs(previous.area_ratio - 1.0), 1e-3);
}

// `lantern-squeezed`: slices ~ sectors^2. The positions converge (second order in 1/n, n growing
// by sqrt(2) per level) but every level's faces are tilted by about 0.55 rad: the face normals do
// not converge, and the area tends to about 1.175 times the cylinder's.
TEST(Lantern, SqueezedPositionsConvergeFaceNormalsAndAreaDoNot) {
  FaceFacts first, previous;
  for (int level = 1; level <= 4; ++level) {
    const FaceFacts f = face_facts(lantern_family_mesh("lantern-squeezed", level));
    SCOPED_TRACE(level);
    EXPECT_GT(f.normal_error, 0.5);
    EXPECT_GT(f.area_ratio, 1.15);
    if (level == 1) first = f;
    if (level > 1) {
      EXPECT_LT(f.centroid_distance, 0.55 * previous.centroid_distance);
      EXPECT_GE(f.area_ratio, previous.area_ratio);
    }
    previous = f;
  }
  EXPECT_GT(previous.normal_error, 0.95 * first.normal_error);  // no better at level 4
  EXPECT_LT(previous.centroid_distance, 3e-3);
}

}  // namespace
}  // namespace curvbench
