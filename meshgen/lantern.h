// The Schwarz lantern of the cylinder of radius 1 and height 2 (z in [-1, 1], open at both
// ends; docs/mesh_families.md): m slices of n sectors, i.e. m + 1 rings of n vertices, ring j at
// height -1 + 2j/m with vertex i at angle (i + j/2) 2 pi/n (odd rings turned by pi/n), every
// vertex on the cylinder; each band between two rings is 2n triangles, oriented outward.
//
// A triangle with two corners on one ring and its apex on the next lies on a plane tilted
// against the cylinder by about (1 - cos(pi/n)) / (2/m) ~ pi^2 m / (4 n^2) radians:
//   `lantern`          n = 16 2^(L-1), m = n/2: the tilt goes to 0 like 1/n, so the mesh's
//                      positions, face normals and area converge to the cylinder's.
//   `lantern-squeezed` n = 14, 20, 28, 40 (about sqrt(2) per level), m = n^2/4: positions
//                      converge (the chords stay 1 - cos(pi/n) ~ 5/n^2 from the cylinder) but
//                      the tilt stays near atan(pi^2/16) = 0.55 rad, so the face normals and
//                      the area (about 1.17 times the cylinder's) do not converge.
// Exact points: the vertices (on the cylinder to roundoff). Surface: make_cylinder(1).
#pragma once

#include "meshgen/generate.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

struct LanternSize {
  int sectors = 0;  ///< n: vertices per ring
  int slices = 0;   ///< m: bands between rings (m + 1 rings)
};

/// The sizes of level 1..4 (not checked) of `lantern` (squeezed = false) or `lantern-squeezed`.
LanternSize lantern_size(bool squeezed, int level);

/// The lantern of n sectors and m slices (n >= 3, m >= 1).
GeneratedMesh lantern_mesh(LanternSize size);

/// The family generators of CURVBENCH_MESH_FAMILIES (generate.cpp).
GeneratedMesh generate_lantern(const MeshSpec& spec);
GeneratedMesh generate_lantern_squeezed(const MeshSpec& spec);

}  // namespace curvbench
