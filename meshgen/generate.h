// The test-mesh families (docs/mesh_families.md, docs/algorithms.md §10): ONE table,
// CURVBENCH_MESH_FAMILIES in generate.cpp, gives each family's name, levels, generator, caption
// (REPORT.md), role in the paper and noise label (the results' `noise` column); generate_mesh()
// dispatches over it. noise_order k > 0 adds alpha h^k normal noise (noise.h) with the seed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "meshgen/generated_mesh.h"
#include "meshgen/noise.h"

namespace curvbench {

struct MeshSpec {
  std::string family;
  int level = 1;
  int noise_order = 0;  ///< 0: no noise; k >= 1: alpha h^k normal noise (§10.3)
  std::uint64_t seed = 1;
  bool jitter = false;          ///< torus-structured only
  NoiseModel noise_model = {};  ///< the distribution of alpha (noise.h)
};

/// Builds the mesh. Throws UsageError (naming the valid values) for an unknown family, a level
/// out of range, a noise order outside 0..4, or --jitter with a family other than
/// torus-structured.
GeneratedMesh generate_mesh(const MeshSpec& spec);

/// One line of the family table.
struct MeshFamilyInfo {
  std::string name;         ///< "torus-unstructured"
  int max_level = 1;        ///< levels 1..max_level
  std::string caption;      ///< how REPORT.md names it
  std::string paper_role;   ///< what it stands for in the paper (or "not in the paper")
  std::string noise_label;  ///< the results' noise column without controlled noise
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
/// exists, max_level < 1 or a null generator.
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
