// The test-mesh families (docs/mesh_families.md, docs/algorithms.md §10): ONE table,
// CURVBENCH_MESH_FAMILIES in generate.cpp, gives each family's name, levels, generator, caption
// (REPORT.md), role in the paper and noise label (the results' `noise` column); generate_mesh()
// dispatches over it. noise_order k > 0 adds alpha h^k normal noise (noise.h) with the seed.
// The mesh options (MeshShape: aspect, density) have one table too, mesh_option_table(); a
// family names the ones it takes in its table line.
#pragma once

#include <compare>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "meshgen/generated_mesh.h"
#include "meshgen/noise.h"

namespace curvbench {

/// Default aspect ratio of torus-anisotropic and bump-anisotropic.
inline constexpr double kDefaultAspect = 4.0;
/// Default edge-length contrast of bump-density.
inline constexpr double kDefaultDensity = 8.0;

/// The mesh options of the families that take them (MeshFamilyInfo::options); unset = the
/// option's default. Given for a family that does not take it, an option is a UsageError.
struct MeshShape {
  std::optional<double> aspect;   ///< aspect ratio A > 1 (default kDefaultAspect)
  std::optional<double> density;  ///< edge-length contrast D >= 1 (default kDefaultDensity)
  auto operator<=>(const MeshShape&) const = default;
};

struct MeshSpec {
  std::string family;
  int level = 1;
  int noise_order = 0;  ///< 0: no noise; k >= 1: alpha h^k normal noise (§10.3)
  std::uint64_t seed = 1;
  bool jitter = false;          ///< torus-structured only
  NoiseModel noise_model = {};  ///< the distribution of alpha (noise.h)
  MeshShape shape = {};         ///< aspect, density: only for the families that take them
};

/// Builds the mesh. Throws UsageError (naming the valid values) for an unknown family, a level
/// out of range, a noise order outside 0..4, --jitter with a family other than
/// torus-structured, or a mesh option out of range or not taken by the family
/// (check_mesh_shape).
GeneratedMesh generate_mesh(const MeshSpec& spec);

/// One mesh option: the experiment key `name=V`, the flag `--name V`, Python's `name=V`.
struct MeshOptionInfo {
  std::string name;          ///< "aspect"
  std::string letter;        ///< "A": the results' family label, e.g. torus-anisotropic-A16
  double default_value = 0;  ///< used when the option is not given
  double lowest = 0;         ///< smallest valid value...
  bool lowest_valid = true;  ///< ...itself valid (>=) or not (>)
  std::string help;          ///< one line: what it sets, the families that take it
  std::optional<double> MeshShape::*field = nullptr;
};

/// Every mesh option, in table order.
const std::vector<MeshOptionInfo>& mesh_option_table();

/// Sets option `name` of `shape`. Throws UsageError naming the valid options for an unknown name
/// (the range is checked by check_mesh_shape).
void set_mesh_option(MeshShape& shape, const std::string& name, double value);

/// Throws UsageError, naming the option and its value, for a given option that `family` does not
/// take or that is out of range (e.g. "aspect 1 out of range: must be > 1"). An unknown family
/// with no option given passes (generate_mesh reports it).
void check_mesh_shape(const std::string& family, const MeshShape& shape);

/// How the results name the meshes of `family` with `shape`: the family name, then
/// -<letter><value> for each option the family takes, given or default (torus-anisotropic-A16,
/// bump-density-D8); the family name alone for the others.
std::string mesh_label(const std::string& family, const MeshShape& shape);

/// The options' part of a case key: ";name=value" (all digits) for each option the family takes,
/// given or default; empty for the others.
std::string mesh_shape_key(const std::string& family, const MeshShape& shape);

/// One line of the family table.
struct MeshFamilyInfo {
  std::string name;         ///< "torus-unstructured"
  int max_level = 1;        ///< levels 1..max_level
  std::string caption;      ///< how REPORT.md names it
  std::string paper_role;   ///< what it stands for in the paper (or "not in the paper")
  std::string noise_label;  ///< the results' noise column without controlled noise
  std::vector<std::string> options = {};  ///< the mesh options it takes ("aspect")
  /// A point-cloud family (meshgen/point_families.h): points without faces, sized by their
  /// nominal spacing; the face-based parts of the harness (noise estimate, creases) skip it.
  bool point_set = false;
};

/// Every family, in table order.
std::vector<MeshFamilyInfo> mesh_family_table();

/// The family called `name` (valid until the next register_mesh_family); throws UsageError
/// naming the valid ones.
const MeshFamilyInfo& mesh_family(const std::string& name);

/// A family's generator: the mesh of spec.level (checked to be 1..max_level) with its exact
/// points and surface, without noise (generate_mesh adds it).
using MeshGenerator = GeneratedMesh (*)(const MeshSpec& spec);

/// Adds a family after the built-in ones (docs/extending.md): from then on generate_mesh(), the
/// experiment files, the runner and the report know it. Call it before generating (not
/// thread-safe against concurrent lookups). Throws UsageError for an empty name, a name that
/// exists, max_level < 1, a null generator or an unknown mesh option.
void register_mesh_family(const MeshFamilyInfo& info, MeshGenerator generator);

/// The family names, in table order.
std::vector<std::string> mesh_families();

/// The family table as the Markdown table of docs/mesh_families.md (a test checks the doc).
std::string mesh_family_markdown();

/// Largest valid level of a family (levels start at 1). Throws UsageError for an unknown family.
int max_mesh_level(const std::string& family);

/// Triangle-shape and valence statistics. Valence = number of distinct edge neighbours.
struct MeshQuality {
  double min_angle_deg = 0.0;         ///< smallest triangle angle, degrees
  double max_angle_deg = 0.0;         ///< largest triangle angle, degrees
  double small_angle_fraction = 0.0;  ///< fraction of the triangle angles below 10 degrees
  int min_valence = 0;                ///< over interior (non-boundary) vertices
  int max_valence = 0;
  int min_boundary_valence = 0;  ///< over boundary vertices (0 if there are none)
  int max_boundary_valence = 0;
};
MeshQuality mesh_quality(const Mesh& mesh);

}  // namespace curvbench
