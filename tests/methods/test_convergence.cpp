// Convergence smoke tests on the generated meshes (meshgen/generate.h): Proposition 2 of the
// paper, normals O(h^d) and mean curvature O(h^{d-1}) for degree-d fitting.
// rate = log(e_first / e_last) / log(h_first / h_last) over the levels used, h = mean edge length.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "meshgen/generate.h"
#include "methods/estimator.h"

namespace curvbench {
namespace {

struct Rates {
  double normal = 0, H = 0;
};

// Normal L2 = sqrt(mean |n~ - n|^2), H L2 = ||H~ - H||_2 / ||H||_2 (docs/algorithms.md §12).
Rates convergence_rates(const std::string& family, int first, int last, const std::string& method) {
  double n0 = 0, h0 = 0, hh0 = 0, n1 = 0, h1 = 0, hh1 = 0;
  for (int level = first; level <= last; level += last - first) {
    MeshSpec spec;
    spec.family = family;
    spec.level = level;
    const GeneratedMesh gm = generate_mesh(spec);
    const auto res = estimate_mesh(gm.mesh, *make_estimator(method, EstimatorOptions{}));
    double sn = 0, sh = 0, shh = 0;
    for (int i = 0; i < gm.mesh.num_vertices(); ++i) {
      const VertexEstimate& r = res[static_cast<size_t>(i)];
      EXPECT_EQ(r.status, VertexStatus::ok) << family << " " << method << " v " << i;
      const SurfacePoint sp = gm.surface->evaluate(gm.exact_points.row(i).transpose());
      sn += (r.normal - sp.normal).squaredNorm();
      sh += (r.H - sp.H) * (r.H - sp.H);
      shh += sp.H * sp.H;
    }
    const double en = std::sqrt(sn / gm.mesh.num_vertices());
    const double eh = std::sqrt(sh / shh);
    std::printf("%-16s %-6s level %d: h %.4g  normal L2 %.3e  H L2 %.3e\n", family.c_str(),
                method.c_str(), level, gm.mesh.mean_edge_length(), en, eh);
    if (level == first) {
      n0 = en, h0 = eh, hh0 = gm.mesh.mean_edge_length();
    } else {
      n1 = en, h1 = eh, hh1 = gm.mesh.mean_edge_length();
    }
  }
  const double lh = std::log(hh0 / hh1);
  return {std::log(n0 / n1) / lh, std::log(h0 / h1) / lh};
}

TEST(Convergence, TorusStructured) {
  const Rates r2 = convergence_rates("torus-structured", 1, 3, "lhf-2");
  EXPECT_GE(r2.normal, 1.7);
  EXPECT_GE(r2.H, 0.9);
  const Rates r4 = convergence_rates("torus-structured", 1, 3, "lhf-4");
  EXPECT_GE(r4.normal, 3.5);
}

// The bump's coarsest level (N = 16) is pre-asymptotic for degree 4 (its level 1 -> 2 normal
// rate is 3.0, then 3.9), so the bump uses levels 2..4 (1089 .. 16641 vertices).
TEST(Convergence, Bump48) {
  const Rates r2 = convergence_rates("bump-48", 2, 4, "lhf-2");
  EXPECT_GE(r2.normal, 1.7);
  EXPECT_GE(r2.H, 0.9);
  const Rates r4 = convergence_rates("bump-48", 2, 4, "lhf-4");
  EXPECT_GE(r4.normal, 3.5);
}

TEST(Convergence, BumpIrregular) {
  const Rates r2 = convergence_rates("bump-irregular", 2, 4, "lhf-2");
  EXPECT_GE(r2.normal, 1.7);
  EXPECT_GE(r2.H, 0.9);
  const Rates r4 = convergence_rates("bump-irregular", 2, 4, "lhf-4");
  EXPECT_GE(r4.normal, 3.5);
}

}  // namespace
}  // namespace curvbench
