// Convergence rates of an estimator's normals and mean curvature on a generated mesh family, for
// the convergence tests (test_convergence.cpp, test_apss.cpp).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "meshgen/generate.h"
#include "methods/estimator.h"

namespace curvbench::testing {

struct ConvergenceRates {
  double normal = 0, H = 0;
};

/// Runs `method` (default options) on `family` at each of `levels` (ascending), expects every
/// vertex estimated, prints each level's errors, normal L2 = sqrt(mean |n~ - n|^2) and
/// H L2 = ||H~ - H||_2 / ||H||_2 over every vertex (docs/algorithms.md §12), and returns the
/// rates from the first level to the last: log(e_first / e_last) / log(h_first / h_last), h the
/// mean edge length.
inline ConvergenceRates convergence_rates(const std::string& family, const std::string& method,
                                          const std::vector<int>& levels) {
  double n0 = 0, h0 = 0, hh0 = 0, n1 = 0, h1 = 0, hh1 = 0;
  for (const int level : levels) {
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
    std::printf("%-18s %-6s level %d: h %.4g  normal L2 %.3e  H L2 %.3e\n", family.c_str(),
                method.c_str(), level, gm.mesh.mean_edge_length(), en, eh);
    if (level == levels.front()) n0 = en, h0 = eh, hh0 = gm.mesh.mean_edge_length();
    if (level == levels.back()) n1 = en, h1 = eh, hh1 = gm.mesh.mean_edge_length();
  }
  const double lh = std::log(hh0 / hh1);
  return {std::log(n0 / n1) / lh, std::log(h0 / h1) / lh};
}

}  // namespace curvbench::testing
