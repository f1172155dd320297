#include "meshgen/anisotropic.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "meshgen/bump_grid.h"
#include "meshgen/bump_irregular.h"
#include "meshgen/torus_structured.h"
#include "surfaces/torus.h"

namespace curvbench {

namespace {

constexpr int kTargetCells = 256;             // n_a n_c at level 1 (that of bump-48)
constexpr double kAspectTolerance = 0.02;     // relative error of A' accepted at level 1
constexpr double kMaxSagOverRowHeight = 0.5;  // torus: sideways sag of a base / row height

struct StretchedGrid {
  int along = 0;        // n_a
  int across = 0;       // n_c
  double aspect = 0.0;  // A'
};

// Level-1 grid (anisotropic.h) for a domain with L_a / L_c = ratio: n_a >= min_along, n_c a
// multiple of across_step, A' within kAspectTolerance of `aspect`, n_a n_c nearest kTargetCells,
// and (L_a / n_a) A' <= max_step_aspect (no limit by default).
StretchedGrid level1_grid(double aspect, double ratio, int min_along, int across_step,
                          double along_length = 0.0,
                          double max_step_aspect = std::numeric_limits<double>::infinity()) {
  StretchedGrid best;
  double best_error = std::numeric_limits<double>::infinity(), best_size = best_error;
  for (int na = min_along; na <= 64 * kTargetCells; ++na) {
    const double ideal = aspect * na * 2.0 / (std::sqrt(3.0) * ratio) / across_step;
    for (const double k : {std::floor(ideal), std::ceil(ideal)}) {
      const int nc = across_step * std::max(1, static_cast<int>(k));
      const double actual = ratio * nc / na * std::sqrt(3.0) / 2.0;
      if (along_length / na * actual > max_step_aspect) continue;
      const double error = std::max(std::abs(actual / aspect - 1.0), kAspectTolerance);
      const double size = std::abs(std::log(static_cast<double>(na) * nc / kTargetCells));
      if (error < best_error || (error == best_error && size < best_size)) {
        best = {na, nc, actual};
        best_error = error;
        best_size = size;
      }
    }
  }
  return best;
}

StretchedGrid grid_at(StretchedGrid g, int level) {
  g.along <<= level - 1;
  g.across <<= level - 1;
  return g;
}

std::string format_aspect(double nominal, double actual) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "aspect A=%g (grid %.4f)", nominal, actual);
  return buf;
}

}  // namespace

GeneratedMesh generate_torus_anisotropic(const MeshSpec& spec) {
  const double aspect = spec.shape.aspect.value_or(kDefaultAspect);
  auto torus = std::make_shared<const Torus>();
  const double R = torus->major_radius(), r = torus->minor_radius();
  const double c = std::sqrt(R * R - r * r);
  const double W = 2.0 * std::numbers::pi * r / c;
  // The coarsest level keeps the sideways sag of a base, du^2/8, within half a row's height
  // du sqrt(3) / (2 A'): du A' <= 2 sqrt(3) (anisotropic.h).
  const StretchedGrid g =
      grid_at(level1_grid(aspect, 2.0 * std::numbers::pi / W, 3, 2, 2.0 * std::numbers::pi,
                          kMaxSagOverRowHeight * 4.0 * std::sqrt(3.0)),
              spec.level);
  const int nu = g.along, nw = g.across;
  const double du = 2.0 * std::numbers::pi / nu, dw = W / nw;
  const double k = std::sqrt((R + r) / (R - r));
  VertexMatrix V(static_cast<Eigen::Index>(nu) * nw, 3);
  for (int j = 0; j < nw; ++j) {
    // v(w) = 2 atan(k tan(w c / 2r)), through atan2: v passes pi where w c / 2r = pi/2.
    const double theta = j * dw * c / (2.0 * r);
    const double v = 2.0 * std::atan2(k * std::sin(theta), std::cos(theta));
    for (int i = 0; i < nu; ++i)
      V.row(static_cast<Eigen::Index>(j) * nu + i) =
          torus->position((i + 0.5 * (j % 2)) * du, v).transpose();
  }
  GeneratedMesh out;
  out.exact_points = V;
  out.mesh = Mesh(std::move(V), staggered_torus_faces(nu, nw), spec.family);
  out.surface = std::move(torus);
  out.family = spec.family;
  out.level = spec.level;
  out.description = "torus-anisotropic level " + std::to_string(spec.level) +
                    ": torus R=1 r=0.3, staggered grid in conformal coordinates (u, w), n_u=" +
                    std::to_string(nu) + " n_w=" + std::to_string(nw) + ", stretched along u, " +
                    format_aspect(aspect, g.aspect);
  return out;
}

GeneratedMesh generate_bump_anisotropic(const MeshSpec& spec) {
  const double aspect = spec.shape.aspect.value_or(kDefaultAspect);
  const StretchedGrid g = grid_at(level1_grid(aspect, 1.0, 1, 1), spec.level);
  const int nx = g.along, ny = g.across;
  PlanarPoints xy((ny / 2 + 1) * (nx + 1) + (ny + 1) / 2 * (nx + 2), 2);
  Eigen::Index n = 0;
  for (int j = 0; j <= ny; ++j) {
    const double y = j == ny ? 1.0 : static_cast<double>(j) / ny;
    if (j % 2 == 0) {
      for (int i = 0; i <= nx; ++i) xy.row(n++) << (i == nx ? 1.0 : static_cast<double>(i) / nx), y;
    } else {
      xy.row(n++) << 0.0, y;
      for (int i = 0; i < nx; ++i) xy.row(n++) << (i + 0.5) / nx, y;
      xy.row(n++) << 1.0, y;
    }
  }
  // Delaunay of the lattice made equilateral (x / A'): the stretched equilateral triangles.
  PlanarPoints scaled = xy;
  scaled.col(0) /= g.aspect;
  FaceMatrix F = delaunay_triangulation(scaled);
  if (F.rows() != static_cast<Eigen::Index>(ny) * (2 * nx + 1))
    throw std::logic_error("bump-anisotropic: Delaunay triangulation has " +
                           std::to_string(F.rows()) + " faces, expected n_y (2 n_x + 1)");
  return lift_onto_bump(
      xy, std::move(F), spec.family, spec.level,
      "bump-anisotropic level " + std::to_string(spec.level) +
          ": Gaussian bump a=81/16 on [0,1]^2, staggered rows n_x=" + std::to_string(nx) +
          " n_y=" + std::to_string(ny) + ", stretched along x, CGAL Delaunay, " +
          format_aspect(aspect, g.aspect));
}

}  // namespace curvbench
