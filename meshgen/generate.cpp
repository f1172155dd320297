#include "meshgen/generate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.h"
#include "meshgen/bump_grid.h"
#include "meshgen/bump_irregular.h"
#include "meshgen/noise.h"
#include "meshgen/torus_isosurface.h"
#include "meshgen/torus_structured.h"
#include "meshgen/torus_unstructured.h"

namespace curvbench {

namespace {

struct FamilyInfo {
  const char* name;
  int max_level;
};

constexpr FamilyInfo kFamilies[] = {
    {"torus-structured", 6},    {"torus-jittered", 6},         {"torus-iso", 5},
    {"torus-iso-projected", 5}, {"bump-48", max_bump_level()}, {"bump-irregular", max_bump_level()},
    {"torus-unstructured", 4},
};
constexpr int kMaxNoiseOrder = 4;

std::string family_list() {
  std::string s;
  for (const auto& f : kFamilies) s += (s.empty() ? "" : ", ") + std::string(f.name);
  return s;
}

}  // namespace

std::vector<std::string> mesh_families() {
  std::vector<std::string> names;
  for (const auto& f : kFamilies) names.emplace_back(f.name);
  return names;
}

int max_mesh_level(const std::string& family) {
  for (const auto& f : kFamilies)
    if (family == f.name) return f.max_level;
  throw UsageError("unknown mesh family '" + family + "' (valid: " + family_list() + ")");
}

GeneratedMesh generate_mesh(const MeshSpec& spec) {
  const int max_level = max_mesh_level(spec.family);
  if (spec.level < 1 || spec.level > max_level)
    throw UsageError("mesh level " + std::to_string(spec.level) + " out of range for " +
                     spec.family + " (valid: 1.." + std::to_string(max_level) + ")");
  if (spec.noise_order < 0 || spec.noise_order > kMaxNoiseOrder)
    throw UsageError("noise order " + std::to_string(spec.noise_order) +
                     " out of range (valid: 0 = none, 1.." + std::to_string(kMaxNoiseOrder) + ")");
  if (spec.jitter && spec.family != "torus-structured")
    throw UsageError("jitter applies only to the torus-structured family, not " + spec.family);

  GeneratedMesh gm;
  if (spec.family == "torus-structured") {
    gm = torus_structured(spec.level, spec.jitter, spec.seed);
  } else if (spec.family == "torus-jittered") {
    gm = torus_structured(spec.level, true, spec.seed);
    gm.family = spec.family;
  } else if (spec.family == "torus-iso" || spec.family == "torus-iso-projected") {
    gm = torus_isosurface(isosurface_grid_points(spec.level), spec.family == "torus-iso-projected");
    gm.family = spec.family;
    gm.level = spec.level;
  } else if (spec.family == "torus-unstructured") {
    gm = torus_unstructured(spec.level, spec.seed);
  } else if (spec.family == "bump-48") {
    gm = bump_48(spec.level);
  } else {  // bump-irregular (the family was validated above)
    gm = bump_irregular(spec.level, spec.seed);
  }
  if (spec.noise_order > 0) gm = add_normal_noise(gm, spec.noise_order, spec.seed);
  return gm;
}

MeshQuality mesh_quality(const Mesh& mesh) {
  MeshQuality q;
  double min_angle = std::numeric_limits<double>::infinity(), max_angle = 0.0;
  std::vector<std::vector<int>> nbrs(mesh.num_vertices());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.face_vertex(f, k), b = mesh.face_vertex(f, (k + 1) % 3),
                c = mesh.face_vertex(f, (k + 2) % 3);
      nbrs[a].push_back(b);
      nbrs[a].push_back(c);
      const Vec3 e1 = mesh.position(b) - mesh.position(a);
      const Vec3 e2 = mesh.position(c) - mesh.position(a);
      const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
      min_angle = std::min(min_angle, angle);
      max_angle = std::max(max_angle, angle);
    }
  }
  const double deg = 180.0 / std::numbers::pi;
  q.min_angle_deg = mesh.num_faces() > 0 ? min_angle * deg : 0.0;
  q.max_angle_deg = max_angle * deg;
  int vmin[2] = {std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
  int vmax[2] = {0, 0};
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    std::sort(nbrs[v].begin(), nbrs[v].end());
    const int valence =
        static_cast<int>(std::unique(nbrs[v].begin(), nbrs[v].end()) - nbrs[v].begin());
    const int b = mesh.is_boundary_vertex(v) ? 1 : 0;
    vmin[b] = std::min(vmin[b], valence);
    vmax[b] = std::max(vmax[b], valence);
  }
  q.min_valence = vmax[0] > 0 ? vmin[0] : 0;
  q.max_valence = vmax[0];
  q.min_boundary_valence = vmax[1] > 0 ? vmin[1] : 0;
  q.max_boundary_valence = vmax[1];
  return q;
}

}  // namespace curvbench
