// Every estimator on a mesh shaped like the meshes people have: a closed genus-3 block
// with small through-holes (rings wrap around them), creases, and marching-cubes needles and caps.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

  // Every registered method: each fit at each of its degrees in 2..4, each operator once.
  int methods = 0;
  for (const MethodInfo& info : method_table()) {
    const std::vector<int> degrees =
        info.is_fit() ? std::vector<int>{2, 3, 4} : std::vector<int>{0};
    for (int degree : degrees) {
      if (info.is_fit() && (degree < info.min_degree || degree > info.max_degree)) continue;
      EstimatorOptions o;
      o.degree = degree;
      const std::unique_ptr<Estimator> est = make_estimator(info.name, o);
      ++methods;
      const ComputedQuantities computes = est->computes();
      std::array<int, kVertexStatusCount> counts{};
      const auto res = estimate_mesh(mesh, *est);
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        const VertexEstimate& q = res[static_cast<size_t>(v)];
        ++counts.at(static_cast<size_t>(q.status));
        EXPECT_TRUE(q.status != VertexStatus::failed && q.status != VertexStatus::excluded)
            << est->label() << " vertex " << v << ": " << to_string(q.status);
        // What the method computes is finite, what it does not is NaN (estimator.h).
        const auto expect = [&](bool computed, bool finite, const char* what) {
          EXPECT_EQ(finite, computed) << est->label() << " vertex " << v << ": " << what;
        };
        expect(computes.normal, q.normal.allFinite(), "normal");
        expect(computes.principal, std::isfinite(q.k1) && std::isfinite(q.k2), "k1, k2");
        expect(computes.mean, std::isfinite(q.H), "H");
        expect(computes.gaussian, std::isfinite(q.K), "K");
        expect(computes.directions, q.d1.allFinite() && q.d2.allFinite(), "d1, d2");
        if (computes.normal) {
          EXPECT_NEAR(q.normal.norm(), 1.0, 1e-12) << est->label() << " vertex " << v;
        }
      }
      std::printf("%-14s", est->label().c_str());
      for (int s = 0; s < kVertexStatusCount; ++s)
        std::printf(" %s %d", to_string(static_cast<VertexStatus>(s)),
                    counts[static_cast<size_t>(s)]);
      std::printf("\n");
    }
  }
  EXPECT_GE(methods, 25);  // 6 fits at degrees 2-4, Xu-2, 6 operators
}

}  // namespace
}  // namespace curvbench
