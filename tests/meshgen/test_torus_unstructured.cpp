// Unstructured well-shaped torus meshes (meshgen/torus_unstructured.h; paper §5.1, Table 5).
// Levels 1 and 2 are checked here (levels 3 and 4 take seconds to minutes to mesh; their counts
// are reported in REPORT.md next to Table 4).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "core/errors.h"
#include "harness/model/paper_tables.h"
#include "meshgen/generate.h"
#include "meshgen/torus_unstructured.h"
#include "tests/meshgen/identical_matrices.h"
#include "tests/meshgen/inward_faces.h"
#include "torus_test_util.h"

namespace curvbench {
namespace {

using testing::torus_distance;
using testing::torus_outward;

class TorusUnstructured : public ::testing::TestWithParam<int> {};

TEST_P(TorusUnstructured, PaperCountsExactPositionsAnglesValences) {
  const int level = GetParam();
  const GeneratedMesh g = torus_unstructured(level);
  const Mesh& m = g.mesh;
  EXPECT_EQ(g.family, "torus-unstructured");
  // Vertex count within 3% of the paper's GAMBIT mesh (Table 5).
  const double paper = paper::kTable5[level - 1].vertices;
  EXPECT_LE(std::abs(m.num_vertices() - paper), 0.03 * paper) << m.num_vertices();
  // Closed genus-1 surface: V - E + F = 0 with E = 3F/2, so F = 2V.
  EXPECT_EQ(m.num_faces(), 2 * m.num_vertices());
  std::map<std::pair<int, int>, int> edge_use;
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.face_vertex(f, k), b = m.face_vertex(f, (k + 1) % 3);
      ++edge_use[{a, b}];  // directed: each once if consistently oriented
    }
  for (const auto& [e, n] : edge_use) {
    ASSERT_EQ(n, 1) << "directed edge used twice: inconsistent orientation";
    ASSERT_EQ(edge_use.count({e.second, e.first}), 1u) << "boundary edge";
  }
  // Every vertex on the torus to roundoff, and exact_points equal to the vertices.
  double worst = 0.0;
  for (int v = 0; v < m.num_vertices(); ++v) {
    worst = std::max(worst, torus_distance(m.position(v)));
    EXPECT_EQ(g.exact_points.row(v), m.vertices().row(v));
  }
  EXPECT_LT(worst, 1e-14);
  // Outward faces.
  EXPECT_EQ(testing::inward_faces(m, torus_outward), 0);
  // Well-shaped and unstructured: minimum angle >= 25 degrees, at least three valences.
  const MeshQuality q = mesh_quality(m);
  EXPECT_GE(q.min_angle_deg, 25.0);
  EXPECT_LT(q.min_valence, 6);
  EXPECT_GT(q.max_valence, 6);
}

INSTANTIATE_TEST_SUITE_P(Levels, TorusUnstructured, ::testing::Values(1, 2));

TEST(TorusUnstructuredFamily, ThroughGenerateMeshAndLevelChecks) {
  MeshSpec spec;
  spec.family = "torus-unstructured";
  spec.level = 1;
  const GeneratedMesh a = generate_mesh(spec);
  const GeneratedMesh b = torus_unstructured(1);
  EXPECT_TRUE(test::identical(a.mesh.vertices(), b.mesh.vertices()));
  EXPECT_TRUE(test::identical(a.mesh.faces(), b.mesh.faces()));
  EXPECT_EQ(max_mesh_level("torus-unstructured"), 4);
  EXPECT_THROW(torus_unstructured(0), UsageError);
  EXPECT_THROW(torus_unstructured(5), UsageError);
}

}  // namespace
}  // namespace curvbench
