// A generated test mesh together with the exact surface points its vertices stand for.
#pragma once

#include <cstdint>
#include <string>

#include "mesh/mesh.h"
#include "surfaces/surface.h"

namespace curvbench {

struct GeneratedMesh {
  Mesh mesh;
  /// n x 3: for each vertex, the exact point on `surface` it stands for. Exact normals and
  /// curvatures are surface->evaluate(exact_points.row(i)). For noise-free meshes this equals
  /// the vertex; for the raw isosurface it is the closest torus point; for controlled noise it
  /// is the unperturbed point.
  VertexMatrix exact_points;
  SurfacePtr surface;
  std::string family;       ///< e.g. "torus-iso"
  int level = 0;            ///< 1 = coarsest
  std::string description;  ///< one line: parameters, seed, noise
  /// A point set's nominal spacing sqrt(area / n) (meshgen/point_families.h); 0 for a mesh.
  double spacing = 0.0;
};

/// The size h of a generated mesh, the one that levels halve, rates are taken against and noise
/// is scaled by: the nominal spacing of a point set, else the mean edge length.
inline double mesh_size(const GeneratedMesh& gm) {
  return gm.spacing > 0.0 ? gm.spacing : gm.mesh.mean_edge_length();
}

}  // namespace curvbench
