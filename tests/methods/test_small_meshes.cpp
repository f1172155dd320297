// Small closed meshes where an estimator used to give up on a whole vertex although part of the
// answer exists (tests/methods/small_mesh_util.h): Meyer's valence-4 vertices on the flat faces
// of a cube (H = K = 0, directions undetermined: status partial), every method on the tetrahedron
// and the octahedron (the normal at least, or failed only where the method has no tangent plane),
// and a four-vertex component beside a sphere (only its vertices may fail, for that cause).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "mesh/mesh_checks.h"
#include "method_test_util.h"
#include "methods/estimator.h"
#include "small_mesh_util.h"

namespace curvbench {
namespace {

// Each registered method (fits at their default degree 2, operators once) with its estimates.
template <class F>
void for_every_method(const Mesh& mesh, F&& check) {
  for (const MethodInfo& info : method_table()) {
    const auto est = make_estimator(info.name, {});
    check(*est, estimate_mesh(mesh, *est));
  }
}

std::array<int, kVertexStatusCount> status_counts(const std::vector<VertexEstimate>& res) {
  std::array<int, kVertexStatusCount> c{};
  for (const VertexEstimate& q : res) ++c[static_cast<size_t>(q.status)];
  return c;
}

void print(const Estimator& est, const char* mesh, const std::vector<VertexEstimate>& res) {
  const auto c = status_counts(res);
  std::printf("%-22s %-13s", mesh, est.label().c_str());
  for (int s = 0; s < kVertexStatusCount; ++s)
    if (c[static_cast<size_t>(s)] > 0)
      std::printf(" %s %d", to_string(static_cast<VertexStatus>(s)), c[static_cast<size_t>(s)]);
  std::printf("\n");
}

// The cube as built (axis-aligned: the edge directions exact) and turned by a rotation (rounding
// in every coordinate): the partial status must not depend on the mesh's placement.
Mesh rotated(const Mesh& mesh) {
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(-1.1, Vec3(0, 1, 0)))
          .toRotationMatrix();
  VertexMatrix V = mesh.vertices() * R.transpose();
  return Mesh(V, mesh.faces(), "rotated");
}

TEST(SmallMeshes, MeyerGivesZeroCurvatureAtValenceFourVerticesOfAFlatFace) {
  std::vector<bool> centre;
  const Mesh axis_aligned = testing::cube_with_square_centres(4, &centre);
  ASSERT_EQ(axis_aligned.euler_characteristic(), 2);
  for (const Mesh& cube : {axis_aligned, rotated(axis_aligned)}) {
    const auto est = make_estimator("meyer", {});
    const auto res = estimate_mesh(cube, *est);
    int centres = 0;
    for (int v = 0; v < cube.num_vertices(); ++v) {
      if (!centre[static_cast<size_t>(v)]) continue;
      ++centres;
      const VertexEstimate& q = res[static_cast<size_t>(v)];
      EXPECT_EQ(q.status, VertexStatus::partial) << v;
      EXPECT_NEAR(q.H, 0.0, 1e-12) << v;
      EXPECT_NEAR(q.K, 0.0, 1e-12) << v;
      EXPECT_NEAR(q.k1, 0.0, 1e-6) << v;  // sqrt of a rounding-level H^2 - K
      EXPECT_NEAR(q.normal.norm(), 1.0, 1e-12) << v;
      EXPECT_TRUE(std::isnan(q.d1.x()) && std::isnan(q.d2.x())) << v;
    }
    EXPECT_EQ(centres, 6 * 16);
    // No vertex of the cube is failed (the grid vertices have valence 8 or more).
    EXPECT_EQ(status_counts(res)[static_cast<size_t>(VertexStatus::failed)], 0);
  }
}

// Every vertex of these polyhedra lies in a component of fewer than 7 vertices, too few for a
// quadratic's 6 coefficients. Every estimate that is not failed has its normal within 60 degrees
// of the outward direction (no wrong normal with a good status). The height fits (LHF, LOP: their
// normal safeguard keeps a plane's rows), Xu's 1-ring fit and the operators (their vertex normal
// at least: quadric and Goldfeather give it with status partial where their fits are singular)
// answer every vertex; so do the LSCM fits, on the ring's projection where their map folds it
// (status reprojected), and CGAL's jet, whose PCA frame is arbitrary on the isotropic points of a
// whole regular polyhedron, falls back to the 1-ring's plane or the vertex normal alone
// (partial). No method fails a vertex there.
TEST(SmallMeshes, EveryMethodGivesAtLeastTheNormalOnATetrahedronAndAnOctahedron) {
  const std::pair<const char*, Mesh> meshes[] = {{"tetrahedron", testing::tetrahedron()},
                                                 {"octahedron", testing::octahedron()}};
  for (const auto& [name, mesh] : meshes) {
    for_every_method(mesh, [&](const Estimator& est, const std::vector<VertexEstimate>& res) {
      print(est, name, res);
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        const VertexEstimate& q = res[static_cast<size_t>(v)];
        EXPECT_NE(q.status, VertexStatus::failed) << est.label() << " vertex " << v;
        if (est.computes().normal) {
          EXPECT_GT(q.normal.dot(mesh.position(v).normalized()), 0.5) << est.label() << " " << v;
        }
      }
    });
  }
}

// Where the normal safeguard leaves no plane (the bottom vertex of an open octahedron: its
// neighbours' normals turn away and the remaining points lie on a line), the height fits refit
// without it: a unit normal, degree 1, not a failed vertex.
TEST(SmallMeshes, HeightFitsGiveTheNormalWhereTheSafeguardLeavesNoPlane) {
  const Mesh mesh = testing::open_octahedron();
  for (const char* method : {"lhf", "lop"}) {
    const auto res = estimate_mesh(mesh, *make_estimator(method, {}));
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      const VertexEstimate& q = res[static_cast<size_t>(v)];
      EXPECT_NE(q.status, VertexStatus::failed) << method << " " << v;
      EXPECT_NEAR(q.normal.norm(), 1.0, 1e-12) << method << " " << v;
    }
    EXPECT_EQ(res[5].degree, 1) << method;
  }
}

TEST(SmallMeshes, OnlyTheTinyComponentFailsAndItsCauseIsTheComponent) {
  const Mesh mesh = testing::with_tiny_tetrahedron(testing::icosphere(2, 1.0));
  const std::vector<VertexDefect> defects = vertex_defects(mesh);
  const int big = mesh.num_vertices() - 4;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    EXPECT_EQ(defects[static_cast<size_t>(v)],
              v < big ? VertexDefect::none : VertexDefect::small_component)
        << v;
  for_every_method(mesh, [&](const Estimator& est, const std::vector<VertexEstimate>& res) {
    print(est, "sphere + tetrahedron", res);
    for (int v = 0; v < big; ++v)
      EXPECT_EQ(res[static_cast<size_t>(v)].status, VertexStatus::ok) << est.label() << " " << v;
  });
}

}  // namespace
}  // namespace curvbench
