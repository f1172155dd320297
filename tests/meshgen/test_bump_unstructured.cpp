// bump-unstructured (meshgen/bump_unstructured.h): CGAL's Delaunay refinement of the square,
// lifted onto the bump; the irregular bump of the reading irregular-bump=delaunay-refined.
#include <gtest/gtest.h>

#include <cmath>

#include "bump_test_util.h"
#include "core/errors.h"
#include "meshgen/bump_unstructured.h"
#include "meshgen/generate.h"
#include "tests/meshgen/identical_matrices.h"

namespace curvbench {
namespace {

TEST(BumpUnstructured, SquareDelaunayThirtyDegreesAndTheGridBumpsCounts) {
  for (int level = 1; level <= 4; ++level) {
    const GeneratedMesh gm = bump_unstructured(level);
    const int N = 16 << (level - 1);
    EXPECT_EQ(gm.family, "bump-unstructured");
    EXPECT_EQ(gm.level, level);
    testing::expect_square_bump_mesh(gm);
    const Mesh& m = gm.mesh;
    // Within 3% of the grid bumps' (N+1)^2 vertices.
    const double grid = (N + 1.0) * (N + 1.0);
    EXPECT_LT(std::abs(m.num_vertices() / grid - 1.0), 0.03) << m.num_vertices();
    // The boundary is the grid bumps' 4N points: none added by the refinement.
    int boundary = 0;
    for (int v = 0; v < m.num_vertices(); ++v) boundary += m.is_boundary_vertex(v);
    EXPECT_EQ(boundary, 4 * N);
    // In the plane: Delaunay, smallest angle >= 30 degrees (the criterion), varying valences.
    EXPECT_EQ(testing::delaunay_violations(m), 0);
    VertexMatrix flat = m.vertices();
    flat.col(2).setZero();
    const MeshQuality q = mesh_quality(Mesh(flat, m.faces()));
    EXPECT_GE(q.min_angle_deg, 30.0 - 1e-9);
    EXPECT_LT(q.min_valence, 6);
    EXPECT_GT(q.max_valence, 6);
  }
}

TEST(BumpUnstructured, SameBytesWhateverWasMeshedBefore) {
  const GeneratedMesh a = bump_unstructured(2);
  const GeneratedMesh other = bump_unstructured(3);  // the heap's state changes in between
  const GeneratedMesh b = bump_unstructured(2);
  EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
  EXPECT_TRUE(test::identical(a.mesh.faces(), b.mesh.faces()));
  EXPECT_GT(other.mesh.num_vertices(), a.mesh.num_vertices());
}

TEST(BumpUnstructured, LevelsHalveHAndTheFamilyTableNamesIt) {
  double previous = 0.0;
  for (int level = 1; level <= 4; ++level) {
    MeshSpec spec;
    spec.family = "bump-unstructured";
    spec.level = level;
    const double h = generate_mesh(spec).mesh.mean_edge_length();
    if (level > 1) {
      EXPECT_NEAR(previous / h, 2.0, 0.1);
    }
    previous = h;
  }
  EXPECT_THROW(bump_unstructured(0), UsageError);
  EXPECT_THROW(bump_unstructured(max_bump_level() + 1), UsageError);
}

}  // namespace
}  // namespace curvbench
