// Anisotropic test meshes (docs/mesh_families.md): equilateral triangles stretched A times along
// one parameter direction (option aspect=A > 1, default kDefaultAspect = 4), vertices exactly on
// the surface. The stretch of a triangle is the ratio of the singular values of the affine map
// from an equilateral triangle onto it: A for every triangle of the parameter grid.
//
// Grid: staggered rows of points (row j shifted by half a column when j is odd), n_a columns
// along the stretch, n_c rows across it, over a parameter domain L_a x L_c. The triangles have
// base s = L_a / n_a along the rows and height t = L_c / n_c across, so their stretch is
// A' = s sqrt(3) / (2 t). Level 1 takes the (n_a, n_c) whose A' is within 2% of A and whose
// n_a n_c is nearest 256 (if no pair is within 2%, the pair with the nearest A'); level L
// multiplies both by 2^(L-1), so A' is the same at every level and h halves per level (level 4
// below 20000 vertices for the bump at A <= 16 and the torus at A <= 6). The description line
// gives n_a, n_c and A'.
//
// torus-anisotropic: the torus R = 1, r = 0.3 (surfaces/torus.h) in conformal coordinates
// (u, w): u the angle about the axis, w(v) = int_0^v r / (R + r cos t) dt
// = (2r/c) atan(sqrt((R-r)/(R+r)) tan(v/2)), c = sqrt(R^2 - r^2), over which the metric is
// (R + r cos v)^2 (du^2 + dw^2): a small triangle of the (u, w) plane keeps its angles on the
// torus, so the stretch is A' everywhere, inside and outside of the tube alike (uniform steps in
// v would vary it by (R + r)/(R - r)). w spans W = 2 pi r / c. Stretched along u (the parallels,
// the direction of k1), n_a = n_u >= 3 columns, n_c = n_w rows (even); the triangles are those
// of torus-structured (staggered_torus_faces), vertex (i, j) at u = (i + (j mod 2)/2) 2pi/n_u,
// w = j W/n_w. V = n_u n_w, F = 2V. On the torus a triangle is bent by O(h): a base of length
// du along a parallel sags sideways by about du^2/8 near the top and bottom of the tube (the
// parallels' geodesic curvature), so that of two neighbouring triangles there one is lower by that
// much and the other higher, against a row height du sqrt(3)/(2A'); where du A' > 4 sqrt(3) the
// faces turn over. Level 1 of the torus therefore also keeps du A' <= 2 sqrt(3) (the sag at most
// half a row's height, every triangle's stretch within about 2A'): A <= 6 keeps the grid
// nearest 256 points (A = 4: 14 x 20); A = 16 starts at 29 x 168 (4872 points, level 4 311808).
//
// bump-anisotropic: the Gaussian bump on [0,1]^2 (surfaces/gaussian_bump.h), stretched along x:
// n_a = n_x columns, n_c = n_y rows; even rows hold x = i/n_x (i = 0..n_x), odd rows x = 0,
// (i + 1/2)/n_x (i = 0..n_x-1) and 1; y = j/n_y. The triangles are the Delaunay triangulation
// (bump_irregular.h) of the points with x scaled by 1/A', i.e. the equilateral lattice, plus
// half triangles at the left and right sides; F = n_y (2 n_x + 1). In the plane the smallest
// angle is atan(sqrt(3)/A') (the base angles; for A' < sqrt(3) the half triangles'
// atan(A'/sqrt(3))).
#pragma once

#include "meshgen/generate.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

/// The torus-anisotropic mesh of spec.level (1..4) with aspect spec.shape.aspect.
GeneratedMesh generate_torus_anisotropic(const MeshSpec& spec);

/// The bump-anisotropic mesh of spec.level (1..4) with aspect spec.shape.aspect.
GeneratedMesh generate_bump_anisotropic(const MeshSpec& spec);

}  // namespace curvbench
