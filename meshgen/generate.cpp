#include "meshgen/generate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/text.h"
#include "meshgen/bump_grid.h"
#include "meshgen/bump_irregular.h"
#include "meshgen/bump_unstructured.h"
#include "meshgen/noise.h"
#include "meshgen/point_families.h"
#include "meshgen/torus_isosurface.h"
#include "meshgen/torus_structured.h"
#include "meshgen/torus_unstructured.h"
#include "meshgen/torus_unstructured_minval5.h"

// clang-format off
// X(name, max_level, generator, caption, paper_role, noise_label[, mesh options]): generator is
// a function `GeneratedMesh generator(const MeshSpec&)` (declared by the line; defined below or
// in the family's own file), called with a valid level and valid mesh options; the noise of
// MeshSpec is added afterwards. The mesh options are names of mesh_option_table() ("aspect").
#define CURVBENCH_MESH_FAMILIES(X)                                                                \
  X("torus-structured", 6, generate_torus_structured,                                             \
    "perfectly structured torus (identical stencils everywhere; not in the paper)",               \
    "not in the paper (extra rows; levels 5-6 for the scaling benchmark)", "none")                \
  X("torus-jittered", 6, generate_torus_jittered,                                                 \
    "jittered structured torus (seeded tangential jitter; not in the paper)",                     \
    "not in the paper (extra rows)", "none")                                                      \
  X("torus-iso", 5, generate_torus_iso,                                                           \
    "noisy torus (isosurface, unprojected)",                                                      \
    "the noisy torus of section 5.3 (Table 4's meshes, vertices as marching cubes put them)",     \
    "isosurface")                                                                                 \
  X("torus-iso-projected", 5, generate_torus_iso_projected,                                       \
    "poor-shaped torus (isosurface, projected)",                                                  \
    "the poor-shaped torus of section 5.1 (Table 4's meshes projected onto the torus)", "none")   \
  X("bump-48", max_bump_level(), generate_bump_48, "4-8 mesh",                                    \
    "the 4-8 mesh of the Gaussian bump, section 5.2", "none")                                     \
  X("bump-irregular", max_bump_level(), generate_bump_irregular, "irregular mesh",                \
    "the irregular mesh of the Gaussian bump, section 5.2", "none")                               \
  X("bump-unstructured", max_bump_level(), generate_bump_unstructured,                            \
    "irregular mesh, Delaunay-refined (a mesher's output in place of the jittered grid)",         \
    "the irregular mesh of the Gaussian bump, section 5.2, read as an unstructured mesher's "     \
    "output (an alternative to bump-irregular)", "none")                                          \
  X("torus-unstructured", 4, generate_torus_unstructured,                                         \
    "well-shaped torus (Delaunay-refined; the stand-in for the paper's GAMBIT meshes)",           \
    "the well-shaped torus of sections 5.1, 5.3 and Table 5", "none")                             \
  X("torus-unstructured-minval5", 4, generate_torus_unstructured_minval5,                         \
    "well-shaped torus without valence 3 or 4 (torus-unstructured after edge flips and "          \
    "relaxation)",                                                                                \
    "the well-shaped torus of sections 5.1 and 5.3, read as a mesh without vertices of "          \
    "valence 3 or 4 (an alternative to torus-unstructured)", "none")                             \
  X("torus-anisotropic", 4, generate_torus_anisotropic,                                           \
    "anisotropic torus (equilateral triangles stretched A times along the parallels; not in the " \
    "paper)",                                                                                     \
    "not in the paper (triangles of aspect ratio A, option aspect=A, default 4)", "none",         \
    "aspect")                                                                                     \
  X("bump-anisotropic", 4, generate_bump_anisotropic,                                             \
    "anisotropic bump mesh (equilateral triangles stretched A times along x; not in the paper)",  \
    "not in the paper (triangles of aspect ratio A, option aspect=A, default 4)", "none",         \
    "aspect")                                                                                     \
  X("bump-density", 4, generate_bump_density,                                                     \
    "graded bump mesh (edge length growing D times from x = 0 to x = 1, Delaunay; not in the "    \
    "paper)",                                                                                     \
    "not in the paper (edge length varying by a factor D, option density=D, default 8)", "none",  \
    "density")                                                                                     \
  X("lantern", 4, generate_lantern,                                                               \
    "Schwarz lantern of a cylinder (slices ~ sectors: normals and area converge)",                \
    "not in the paper (meshes that break estimators)", "none")                \
  X("lantern-squeezed", 4, generate_lantern_squeezed,                                             \
    "squeezed Schwarz lantern of a cylinder (slices ~ sectors^2: positions converge, face "       \
    "normals and area do not)",                                                                   \
    "not in the paper (meshes that break estimators)", "none")                \
  X("ellipsoid", 4, generate_ellipsoid,                                                           \
    "ellipsoid with semi-axes 1, 0.8, 0.6 (Delaunay-refined; four umbilics)",                     \
    "not in the paper (meshes that break estimators)", "none")
// clang-format on

namespace curvbench {

#define CURVBENCH_DECLARE_GENERATOR(name, max_level, generator, ...) \
  GeneratedMesh generator(const MeshSpec& spec);
CURVBENCH_MESH_FAMILIES(CURVBENCH_DECLARE_GENERATOR)
#undef CURVBENCH_DECLARE_GENERATOR

GeneratedMesh generate_torus_unstructured(const MeshSpec& spec) {
  return torus_unstructured(spec.level, spec.seed);
}

GeneratedMesh generate_torus_unstructured_minval5(const MeshSpec& spec) {
  return torus_unstructured_minval5(spec.level, spec.seed);
}

GeneratedMesh generate_torus_structured(const MeshSpec& spec) {
  return torus_structured(spec.level, spec.jitter, spec.seed);
}

GeneratedMesh generate_torus_jittered(const MeshSpec& spec) {
  GeneratedMesh gm = torus_structured(spec.level, true, spec.seed);
  gm.family = spec.family;
  return gm;
}

GeneratedMesh generate_torus_iso(const MeshSpec& spec) {
  GeneratedMesh gm = torus_isosurface(isosurface_grid_points(spec.level), false);
  gm.family = spec.family;
  gm.level = spec.level;
  return gm;
}

GeneratedMesh generate_torus_iso_projected(const MeshSpec& spec) {
  GeneratedMesh gm = torus_isosurface(isosurface_grid_points(spec.level), true);
  gm.family = spec.family;
  gm.level = spec.level;
  return gm;
}

GeneratedMesh generate_bump_48(const MeshSpec& spec) {
  return bump_48(spec.level);
}

GeneratedMesh generate_bump_irregular(const MeshSpec& spec) {
  return bump_irregular(spec.level, spec.seed);
}

GeneratedMesh generate_bump_unstructured(const MeshSpec& spec) {
  return bump_unstructured(spec.level);
}

namespace {

struct FamilyEntry {
  MeshFamilyInfo info;
  MeshGenerator generate;
};

// The family table: the lines of CURVBENCH_MESH_FAMILIES, then register_mesh_family() additions.
std::vector<FamilyEntry>& family_entries() {
#define CURVBENCH_FAMILY_ENTRY(name, max_level, generator, caption, role, noise, ...) \
  FamilyEntry{{name, max_level, caption, role, noise, {__VA_ARGS__}}, &generator},
  static std::vector<FamilyEntry> entries = [] {
    std::vector<FamilyEntry> table = {CURVBENCH_MESH_FAMILIES(CURVBENCH_FAMILY_ENTRY)};
    // The point-cloud families, points-<surface>-<sampling> (point_families.h): every surface
    // in every sampling.
    const std::pair<const char*, const char*> surfaces[] = {
        {"torus", "torus R = 1, r = 0.3"},
        {"sphere", "unit sphere"},
        {"ellipsoid", "ellipsoid with semi-axes 1, 0.8, 0.6"},
        {"bump", "Gaussian bump on [0,1]^2"}};
    const std::pair<const char*, const char*> samplings[] = {
        {"uniform", "uniform random points (by area)"},
        {"blue", "blue-noise points (Poisson disk, distance 0.7 h)"},
        {"anisotropic", "anisotropic points (4x denser along x)"},
        {"stripes", "scan-like stripes (lines 2h apart, points about h/2 apart along them)"}};
    for (const auto& [surface, surface_caption] : surfaces)
      for (const auto& [sampling, sampling_caption] : samplings) {
        MeshFamilyInfo info{
            std::string("points-") + surface + "-" + sampling, kMaxPointLevel,
            std::string(sampling_caption) + " on the " + surface_caption + ", no connectivity",
            "not in the paper (point sets: 1000 * 4^(L-1) points at level L)", "none"};
        info.point_set = true;
        table.push_back({std::move(info), &generate_point_family});
      }
    return table;
  }();
#undef CURVBENCH_FAMILY_ENTRY
  return entries;
}

const MeshOptionInfo* find_option(const std::string& name) {
  for (const MeshOptionInfo& o : mesh_option_table())
    if (o.name == name) return &o;
  return nullptr;
}

bool takes(const MeshFamilyInfo& family, const std::string& option) {
  return std::find(family.options.begin(), family.options.end(), option) != family.options.end();
}

const FamilyEntry* find_entry(const std::string& name) {
  for (const FamilyEntry& f : family_entries())
    if (f.info.name == name) return &f;
  return nullptr;
}

const FamilyEntry& find_family(const std::string& name) {
  if (const FamilyEntry* f = find_entry(name)) return *f;
  std::string valid;
  for (const FamilyEntry& f : family_entries()) valid += (valid.empty() ? "" : ", ") + f.info.name;
  throw UsageError("unknown mesh family '" + name + "' (valid: " + valid + ")");
}

}  // namespace

std::vector<MeshFamilyInfo> mesh_family_table() {
  std::vector<MeshFamilyInfo> out;
  for (const FamilyEntry& f : family_entries()) out.push_back(f.info);
  return out;
}

const MeshFamilyInfo& mesh_family(const std::string& name) {
  return find_family(name).info;
}

void register_mesh_family(const MeshFamilyInfo& info, MeshGenerator generator) {
  if (info.name.empty() || generator == nullptr || info.max_level < 1)
    throw UsageError("register_mesh_family: a family needs a name, levels and a generator");
  if (find_entry(info.name) != nullptr)
    throw UsageError("register_mesh_family: family '" + info.name + "' exists already");
  for (const std::string& o : info.options)
    if (find_option(o) == nullptr)
      throw UsageError("register_mesh_family: unknown mesh option '" + o + "'");
  family_entries().push_back({info, generator});
}

std::vector<std::string> mesh_families() {
  std::vector<std::string> names;
  for (const MeshFamilyInfo& f : mesh_family_table()) names.push_back(f.name);
  return names;
}

int max_mesh_level(const std::string& family) {
  return mesh_family(family).max_level;
}

std::string mesh_family_markdown() {
  std::string md = "| family | levels | in the paper | noise label |\n|---|---|---|---|\n";
  for (const MeshFamilyInfo& f : mesh_family_table())
    md += "| `" + f.name + "` | 1-" + std::to_string(f.max_level) + " | " + f.paper_role + " | " +
          f.noise_label + " |\n";
  return md;
}

const std::vector<MeshOptionInfo>& mesh_option_table() {
  static const std::vector<MeshOptionInfo> table = {
      {"aspect", "A", kDefaultAspect, 1.0, false,
       "torus-anisotropic, bump-anisotropic: aspect ratio A > 1 of the triangles (equilateral "
       "ones stretched A times along one parameter direction)",
       &MeshShape::aspect},
      {"density", "D", kDefaultDensity, 1.0, true,
       "bump-density: factor D >= 1 by which the edge length grows from one side of the domain "
       "to the other",
       &MeshShape::density},
  };
  return table;
}

void set_mesh_option(MeshShape& shape, const std::string& name, double value) {
  const MeshOptionInfo* o = find_option(name);
  if (o == nullptr) {
    std::string valid;
    for (const MeshOptionInfo& m : mesh_option_table())
      valid += (valid.empty() ? "" : ", ") + m.name;
    throw UsageError("unknown mesh option '" + name + "' (valid: " + valid + ")");
  }
  shape.*(o->field) = value;
}

void check_mesh_shape(const std::string& family, const MeshShape& shape) {
  for (const MeshOptionInfo& o : mesh_option_table()) {
    const std::optional<double>& v = shape.*(o.field);
    if (!v) continue;
    const MeshFamilyInfo& f = mesh_family(family);
    if (!takes(f, o.name)) {
      std::string which;
      for (const FamilyEntry& e : family_entries())
        if (takes(e.info, o.name)) which += (which.empty() ? "" : ", ") + e.info.name;
      throw UsageError(o.name + " " + format_g(*v) + " does not apply to " + family + " (only to " +
                       which + ")");
    }
    if (!std::isfinite(*v) || *v < o.lowest || (*v == o.lowest && !o.lowest_valid))
      throw UsageError(o.name + " " + format_g(*v) + " out of range: must be " +
                       (o.lowest_valid ? ">= " : "> ") + format_g(o.lowest));
  }
}

std::string mesh_label(const std::string& family, const MeshShape& shape) {
  const FamilyEntry* f = find_entry(family);
  std::string label = family;
  if (f == nullptr) return label;
  for (const MeshOptionInfo& o : mesh_option_table())
    if (takes(f->info, o.name))
      label += "-" + o.letter + format_g((shape.*(o.field)).value_or(o.default_value));
  return label;
}

std::string mesh_shape_key(const std::string& family, const MeshShape& shape) {
  const FamilyEntry* f = find_entry(family);
  std::string key;
  if (f == nullptr) return key;
  for (const MeshOptionInfo& o : mesh_option_table())
    if (takes(f->info, o.name)) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g", (shape.*(o.field)).value_or(o.default_value));
      key += ";" + o.name + "=" + buf;
    }
  return key;
}

GeneratedMesh generate_mesh(const MeshSpec& spec) {
  const FamilyEntry& family = find_family(spec.family);
  const int max_level = family.info.max_level;
  if (spec.level < 1 || spec.level > max_level)
    throw UsageError("mesh level " + std::to_string(spec.level) + " out of range for " +
                     spec.family + " (valid: 1.." + std::to_string(max_level) + ")");
  check_noise_order(spec.noise_order);
  if (spec.jitter && spec.family != "torus-structured")
    throw UsageError("jitter applies only to the torus-structured family, not " + spec.family);
  check_mesh_shape(spec.family, spec.shape);
  GeneratedMesh gm = family.generate(spec);
  if (spec.noise_order > 0) gm = add_noise(gm, spec.noise_order, spec.seed, spec.noise_model);
  return gm;
}

MeshQuality mesh_quality(const Mesh& mesh) {
  MeshQuality q;
  double min_angle = std::numeric_limits<double>::infinity(), max_angle = 0.0;
  int small = 0;
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
      small += angle < 10.0 * std::numbers::pi / 180.0 ? 1 : 0;
    }
  }
  const double deg = 180.0 / std::numbers::pi;
  q.min_angle_deg = mesh.num_faces() > 0 ? min_angle * deg : 0.0;
  q.max_angle_deg = max_angle * deg;
  q.small_angle_fraction = mesh.num_faces() > 0 ? small / (3.0 * mesh.num_faces()) : 0.0;
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
