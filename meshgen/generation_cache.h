// Once-per-process generation of the meshes whose mesher takes seconds (CGAL's Delaunay
// refinement of the torus: tens of seconds at level 4): each (family, level, seed) is generated
// once and kept; thread-safe, and a maker may itself ask for another family's mesh.
#pragma once

#include <cstdint>
#include <string>

#include "meshgen/generated_mesh.h"

namespace curvbench {

using MeshMaker = GeneratedMesh (*)(int level, std::uint64_t seed);

/// make(level, seed) the first time (family, level, seed) is asked for, the kept copy after.
const GeneratedMesh& generate_once(const std::string& family, int level, std::uint64_t seed,
                                   MeshMaker make);

}  // namespace curvbench
