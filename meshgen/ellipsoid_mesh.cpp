// The Delaunay-refined ellipsoid; see ellipsoid_mesh.h.
#include "meshgen/ellipsoid_mesh.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/errors.h"
#include "meshgen/delaunay_surface_mesh.h"
#include "meshgen/generation_cache.h"
#include "surfaces/ellipsoid.h"

namespace curvbench {
namespace {

// Surface Delaunay ball radius bound per level: halved per level, level 4 below 25000 vertices.
constexpr double kRadius[] = {0.124, 0.062, 0.031, 0.0155};
constexpr int kMaxLevel = 4;

double ellipsoid_function(double x, double y, double z) {
  const double u = x / kEllipsoidAxes[0], v = y / kEllipsoidAxes[1], w = z / kEllipsoidAxes[2];
  return u * u + v * v + w * w - 1.0;
}

// Longitude and latitude-like angle of the point.
std::array<double, 2> ellipsoid_angles(const Vec3& p) {
  return {std::atan2(p.y(), p.x()), std::atan2(p.z(), std::hypot(p.x(), p.y()))};
}

}  // namespace

GeneratedMesh ellipsoid_mesh(int level, std::uint64_t seed) {
  if (level < 1 || level > kMaxLevel)
    throw UsageError("ellipsoid: level " + std::to_string(level) + " out of range [1, " +
                     std::to_string(kMaxLevel) + "]");
  const double rho = kRadius[level - 1];
  ImplicitMeshing spec;
  spec.implicit = ellipsoid_function;
  spec.bounding_radius = 2.0;
  spec.radius_bound = rho;
  spec.surface = make_ellipsoid(kEllipsoidAxes[0], kEllipsoidAxes[1], kEllipsoidAxes[2]);
  spec.angles = ellipsoid_angles;
  spec.seed = seed;
  spec.name = "ellipsoid";
  spec.level = level;
  spec.surface_words = "semi-axes 1, 0.8, 0.6";
  spec.projected_to = "the ellipsoid";
  return delaunay_surface_mesh(spec);
}

GeneratedMesh generate_ellipsoid(const MeshSpec& spec) {
  return generate_once("ellipsoid", spec.level, spec.seed, ellipsoid_mesh);
}

}  // namespace curvbench
