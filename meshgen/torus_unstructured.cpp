#include "meshgen/torus_unstructured.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/errors.h"
#include "meshgen/delaunay_surface_mesh.h"
#include "meshgen/generation_cache.h"
#include "surfaces/torus.h"

namespace curvbench {
namespace {

constexpr double kR = 1.0, kr = 0.3;

double torus_function(double x, double y, double z) {
  const double q = std::sqrt(x * x + y * y) - kR;
  return q * q + z * z - kr * kr;
}

// The angle around the axis and the angle around the tube.
std::array<double, 2> torus_angles(const Vec3& p) {
  return {std::atan2(p.y(), p.x()),
          std::atan2(p.z(), std::sqrt(p.x() * p.x() + p.y() * p.y()) - kR)};
}

// Surface Delaunay ball radius bound per level, calibrated once (seed 1) so that the vertex
// counts fall within 3% of the paper's 1338, 5246, 21156, 85208.
constexpr double kRadius[] = {0.0826, 0.0397, 0.0197, 0.0098};
constexpr int kMaxLevel = 4;

GeneratedMesh generate(int level, std::uint64_t seed) {
  const double rho = kRadius[level - 1];
  ImplicitMeshing spec;
  spec.implicit = torus_function;
  spec.bounding_radius = 2.0;
  spec.radius_bound = rho;
  spec.surface = make_torus(kR, kr);
  spec.angles = torus_angles;
  spec.seed = seed;
  spec.name = "torus-unstructured";
  spec.level = level;
  spec.surface_words = "torus R=1 r=0.3";
  spec.projected_to = "the torus";
  return delaunay_surface_mesh(spec);
}

}  // namespace

int torus_unstructured_max_level() {
  return kMaxLevel;
}

GeneratedMesh torus_unstructured(int level, std::uint64_t seed) {
  if (level < 1 || level > kMaxLevel)
    throw UsageError("torus-unstructured: level " + std::to_string(level) + " out of range [1, " +
                     std::to_string(kMaxLevel) + "]");
  // Meshing level 4 takes tens of seconds: each (level, seed) is generated once per process.
  return generate_once("torus-unstructured", level, seed, generate);
}

}  // namespace curvbench
