// The point-cloud families; see point_families.h.
#include "meshgen/point_families.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "meshgen/ellipsoid_mesh.h"
#include "meshgen/random.h"
#include "surfaces/ellipsoid.h"
#include "surfaces/gaussian_bump.h"
#include "surfaces/sphere.h"
#include "surfaces/torus.h"

namespace curvbench {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBlueDistance = 0.7;      // Poisson-disk distance, in units of h
constexpr double kAnisotropy = 4.0;        // the anisotropic sampling's x stretch
constexpr double kStripeSpacing = 2.0;     // scan lines 2h apart...
constexpr double kStripeHalfWidth = 0.02;  // ...and 2h/50 = 0.04 h wide (half width 0.02 h)

// A surface with the rectangle of its natural parameterization (Surface::position).
struct ParameterizedSurface {
  SurfacePtr surface;
  double u0, u1, v0, v1;
};

ParameterizedSurface surface_of(const std::string& name) {
  if (name == "torus") return {make_torus(1.0, 0.3), 0.0, 2 * kPi, 0.0, 2 * kPi};
  if (name == "sphere") return {make_sphere(1.0), 0.0, 2 * kPi, -kPi / 2, kPi / 2};
  if (name == "ellipsoid")
    return {make_ellipsoid(kEllipsoidAxes[0], kEllipsoidAxes[1], kEllipsoidAxes[2]), 0.0, 2 * kPi,
            -kPi / 2, kPi / 2};
  if (name == "bump") return {make_gaussian_bump(), 0.0, 1.0, 0.0, 1.0};
  throw UsageError("unknown point-cloud surface '" + name +
                   "' (valid: torus, sphere, ellipsoid, bump)");
}

// x_u x x_v by central differences (the sampling density only; exact quantities come from
// Surface::evaluate at the sampled point).
Vec3 area_normal(const ParameterizedSurface& s, double u, double v) {
  const double d = 1e-6;
  const Vec3 xu = (s.surface->position(u + d, v) - s.surface->position(u - d, v)) / (2 * d);
  const Vec3 xv = (s.surface->position(u, v + d) - s.surface->position(u, v - d)) / (2 * d);
  return xu.cross(xv);
}

// Midpoint quadrature of the area element J (and of the stretched area element of the
// anisotropic metric, |cof(M) n| J with M = diag(4, 1, 1)), and J's maximum on the grid.
struct AreaFacts {
  double area = 0.0, stretched_area = 0.0, max_element = 0.0;
};

AreaFacts area_facts(const ParameterizedSurface& s) {
  const int m = 400;
  const double du = (s.u1 - s.u0) / m, dv = (s.v1 - s.v0) / m;
  AreaFacts f;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const Vec3 a = area_normal(s, s.u0 + (i + 0.5) * du, s.v0 + (j + 0.5) * dv);
      const double J = a.norm();
      f.area += J * du * dv;
      if (J > 0.0) {
        const double nx = a.x() / J;
        const double stretch = std::sqrt(nx * nx + kAnisotropy * kAnisotropy * (1.0 - nx * nx));
        f.stretched_area += stretch * J * du * dv;
      }
      f.max_element = std::max(f.max_element, J);
    }
  return f;
}

// Points uniform by area, one at a time from a seeded stream: (u, v) uniform on the rectangle,
// kept with probability J / J_max (J_max from the grid, raised 5% to bound the true maximum).
class UniformByArea {
 public:
  UniformByArea(const ParameterizedSurface& s, double max_element, std::uint64_t seed)
      : s_(s), bound_(1.05 * max_element), rng_(seed) {}
  Vec3 next() {
    for (;;) {
      const double u = rng_.uniform(s_.u0, s_.u1), v = rng_.uniform(s_.v0, s_.v1);
      if (rng_.uniform01() * bound_ < area_normal(s_, u, v).norm())
        return s_.surface->position(u, v);
    }
  }

 private:
  const ParameterizedSurface& s_;
  double bound_;
  Rng rng_;
};

// Dart throwing: a candidate is kept unless a kept point lies within `distance` of it in the
// metric (kx dx, dy, dz). A hash grid of cells of that size finds the candidates' neighbours.
class PoissonDisk {
 public:
  PoissonDisk(double distance, double kx) : d_(distance), kx_(kx) {}
  bool try_add(const Vec3& p) {
    const Vec3 q(kx_ * p.x(), p.y(), p.z());
    const std::array<std::int64_t, 3> c = cell(q);
    for (std::int64_t i = -1; i <= 1; ++i)
      for (std::int64_t j = -1; j <= 1; ++j)
        for (std::int64_t k = -1; k <= 1; ++k) {
          const auto it = grid_.find(key({c[0] + i, c[1] + j, c[2] + k}));
          if (it == grid_.end()) continue;
          for (const Vec3& o : it->second)
            if ((o - q).squaredNorm() < d_ * d_) return false;
        }
    grid_[key(c)].push_back(q);
    return true;
  }

 private:
  std::array<std::int64_t, 3> cell(const Vec3& q) const {
    return {static_cast<std::int64_t>(std::floor(q.x() / d_)),
            static_cast<std::int64_t>(std::floor(q.y() / d_)),
            static_cast<std::int64_t>(std::floor(q.z() / d_))};
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    // 21 bits per coordinate: the cells of these surfaces stay far inside +-2^20.
    const auto part = [](std::int64_t x) { return static_cast<std::uint64_t>(x + (1 << 20)); };
    return part(c[0]) << 42 | part(c[1]) << 21 | part(c[2]);
  }
  double d_, kx_;
  std::unordered_map<std::uint64_t, std::vector<Vec3>> grid_;
};

std::pair<std::string, std::string> split_family(const std::string& family) {
  const std::string prefix = "points-";
  const size_t dash = family.find('-', prefix.size());
  if (family.rfind(prefix, 0) != 0 || dash == std::string::npos)
    throw UsageError("not a point-cloud family: '" + family +
                     "' (expected points-<surface>-<sampling>)");
  return {family.substr(prefix.size(), dash - prefix.size()), family.substr(dash + 1)};
}

}  // namespace

int point_family_size(int level) {
  return 1000 << (2 * (level - 1));
}

double point_family_area(const std::string& family) {
  return area_facts(surface_of(split_family(family).first)).area;
}

GeneratedMesh generate_point_family(const MeshSpec& spec) {
  const auto [surface_name, sampling] = split_family(spec.family);
  const ParameterizedSurface s = surface_of(surface_name);
  const AreaFacts facts = area_facts(s);
  const int n = point_family_size(spec.level);
  const double h = std::sqrt(facts.area / n);
  UniformByArea candidates(s, facts.max_element, derive_seed(spec.seed, 2000 + spec.level));
  VertexMatrix V(n, 3);
  // Dart throwing stops far below saturation (a disk packing fraction of 0.38 against random
  // sequential adsorption's 0.547); the cap only turns a logic error into an error.
  const long long max_candidates = 400LL * n;
  long long drawn = 0;
  const auto draw = [&] {
    if (++drawn > max_candidates)
      throw std::logic_error("point family " + spec.family + ": the sampler drew " +
                             std::to_string(max_candidates) + " candidates without reaching " +
                             std::to_string(n) + " points");
    return candidates.next();
  };
  std::string how;
  if (sampling == "uniform") {
    for (int i = 0; i < n; ++i) V.row(i) = draw().transpose();
    how = "uniform by area";
  } else if (sampling == "blue" || sampling == "anisotropic") {
    const bool stretched = sampling == "anisotropic";
    const double kx = stretched ? kAnisotropy : 1.0;
    const double area = stretched ? facts.stretched_area : facts.area;
    PoissonDisk disk(kBlueDistance * std::sqrt(area / n), kx);
    for (int i = 0; i < n;) {
      const Vec3 p = draw();
      if (disk.try_add(p)) V.row(i++) = p.transpose();
    }
    how = stretched ? "Poisson disk in the metric (4 dx, dy, dz): 4x denser along x"
                    : "Poisson disk, distance 0.7 h";
  } else if (sampling == "stripes") {
    const double gap = kStripeSpacing * h, half_width = kStripeHalfWidth * h;
    for (int i = 0; i < n;) {
      const Vec3 p = draw();
      const double off = p.x() / gap - std::round(p.x() / gap);
      if (std::abs(off) * gap <= half_width) V.row(i++) = p.transpose();
    }
    how = "scan lines x = 2h j, 0.04 h wide";
  } else {
    throw UsageError("unknown point sampling '" + sampling + "' in " + spec.family +
                     " (valid: uniform, blue, anisotropic, stripes)");
  }
  GeneratedMesh gm;
  gm.mesh = Mesh(V, FaceMatrix(0, 3), spec.family);
  gm.exact_points = std::move(V);
  gm.surface = s.surface;
  gm.family = spec.family;
  gm.level = spec.level;
  gm.spacing = h;
  char buf[240];
  std::snprintf(buf, sizeof buf, "%s: %d points of the %s, %s, h = sqrt(A/n) = %.6g, seed=%llu",
                spec.family.c_str(), n, surface_name.c_str(), how.c_str(), h,
                static_cast<unsigned long long>(spec.seed));
  gm.description = buf;
  return gm;
}

}  // namespace curvbench
