// Every estimator on a mesh shaped like the meshes people have (issue 16): a closed genus-3 block
// with small through-holes (rings wrap around them), creases, and marching-cubes needles and caps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/errors.h"
#include "mesh/mesh_checks.h"
#include "methods/estimator.h"
#include "real_mesh_util.h"

namespace curvbench {
namespace {

TEST(RealMeshes, EveryMethodAnswersEverywhereOnAHoleyBlockWithNeedles) {
  const Mesh mesh = testing::cheese_block(16);
  // The preconditions of the promise: closed, manifold, oriented, no degenerate face; and the
  // features that made methods fail: genus 3 (V - E + F = -4), needles below 1 degree.
  const MeshChecks checks = check_mesh(mesh);
  ASSERT_EQ(checks.boundary_edges, 0);
  ASSERT_EQ(checks.nonmanifold_edges + checks.nonmanifold_vertices, 0);
  ASSERT_EQ(checks.zero_area_faces, 0);
  ASSERT_EQ(checks.inconsistent_edges, 0);
  ASSERT_EQ(checks.components, 1);
  ASSERT_EQ(mesh.euler_characteristic(), -4);
  ASSERT_GT(mesh.signed_volume(), 0.0);
  int needles = 0;
  for (int f = 0; f < mesh.num_faces(); ++f)
    needles += testing::smallest_angle_degrees(mesh, f) < 1.0;
  ASSERT_GT(needles, 0);
  // Rings of the default sizes that wrap around a hole or pinch: what LSCM used to fail on.
  for (double ring : {1.5, 2.0, 2.5}) ASSERT_GT(testing::rings_cut(mesh, ring), 0) << ring;

  int methods = 0;
  for (const std::string& name : estimator_names())
    for (int degree = 2; degree <= 4; ++degree) {
      EstimatorOptions o;
      o.degree = degree;
      std::unique_ptr<Estimator> est;
      try {
        est = make_estimator(name, o);
      } catch (const UsageError&) {
        continue;  // a degree the method does not support (Xu: 2 only)
      }
      ++methods;
      int counts[5] = {0, 0, 0, 0, 0};
      const auto res = estimate_mesh(mesh, *est);
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        const VertexEstimate& q = res[static_cast<size_t>(v)];
        ++counts[static_cast<int>(q.status)];
        EXPECT_TRUE(q.status != VertexStatus::failed && q.status != VertexStatus::excluded)
            << est->label() << " vertex " << v << ": " << to_string(q.status);
        EXPECT_TRUE(q.normal.allFinite() && std::isfinite(q.k1) && std::isfinite(q.k2) &&
                    std::isfinite(q.H) && std::isfinite(q.K) && q.d1.allFinite() &&
                    q.d2.allFinite())
            << est->label() << " vertex " << v;
        EXPECT_NEAR(q.normal.norm(), 1.0, 1e-12) << est->label() << " vertex " << v;
      }
      std::printf("%-12s ok %4d degree_reduced %4d disk_cut %4d failed %d excluded %d\n",
                  est->label().c_str(), counts[0], counts[1], counts[4], counts[2], counts[3]);
    }
  EXPECT_GE(methods, 18);  // lhf, lop, jet, lscm, lscm-fast, lscm-cg at 2-4; xu-2
}

}  // namespace
}  // namespace curvbench
