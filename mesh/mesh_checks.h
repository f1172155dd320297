// Mesh defect counts for `curvbench info` (docs/robustness.md): degenerate and duplicate elements,
// non-manifold edges and vertices, components, orientation and boundary.
//
//   mesh  a Mesh (n vertices, m triangles)
//
// None of these is an error: the estimators run on such meshes, and a vertex where no estimate
// is possible gets status failed or excluded. Every function is O(n log n + m log m) at most,
// and none is run by read_mesh (only `info` needs them).
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"

namespace curvbench {

/// Relative tolerance of count_zero_area_faces: a face is "zero-area" when
/// |(b-a) x (c-a)| <= kZeroAreaTolerance * (longest edge)^2, i.e. collapsed to a segment or a
/// point up to rounding (exactly zero for coincident or exactly collinear corners).
inline constexpr double kZeroAreaTolerance = 1e-12;

/// Faces of (numerically) zero area, see kZeroAreaTolerance.
int count_zero_area_faces(const Mesh& mesh);

/// Vertices whose coordinates equal (==) those of a vertex with a smaller index: the number of
/// vertices that would disappear if equal positions were merged.
int count_duplicate_vertices(const Mesh& mesh);

/// Faces whose vertex set equals that of a face with a smaller index (either orientation).
int count_duplicate_faces(const Mesh& mesh);

/// Vertices whose incident faces, joined across manifold edges (two incident faces) that contain
/// the vertex, form more than one fan: a "bow tie" where two sheets touch at a vertex, and every
/// endpoint of a non-manifold edge. Isolated vertices are not counted.
int count_nonmanifold_vertices(const Mesh& mesh);

/// Per vertex: whether its incident faces form more than one fan (as count_nonmanifold_vertices).
std::vector<unsigned char> nonmanifold_vertex_flags(const Mesh& mesh);

/// Whether face f is (numerically) zero-area, see kZeroAreaTolerance.
bool is_zero_area_face(const Mesh& mesh, int f);

/// Connected components of the faces (two faces are connected when they share a vertex).
/// Isolated vertices are not components (see Mesh::num_isolated_vertices).
int count_components(const Mesh& mesh);

/// Connected components of the boundary edges (edges with one incident face): the number of
/// boundary loops on a manifold mesh; boundary loops touching at a vertex count once.
int count_boundary_loops(const Mesh& mesh);

/// The valence of every vertex (n entries): its number of distinct edge neighbours. O(m log m).
std::vector<int> vertex_valences(const Mesh& mesh);

/// Valence histogram: entry k is the number of vertices with exactly k distinct edge neighbours
/// (the valence of meshgen's mesh_quality; isolated vertices count at 0, boundary vertices too).
/// The vector ends at the largest valence (size max valence + 1; empty for a mesh without
/// vertices). O(m log m).
std::vector<int> valence_histogram(const Mesh& mesh);

/// All counts at once, with the ones Mesh already knows.
struct MeshChecks {
  int zero_area_faces = 0;
  int duplicate_vertices = 0;
  int duplicate_faces = 0;
  int isolated_vertices = 0;
  int nonmanifold_edges = 0;
  int nonmanifold_vertices = 0;
  int components = 0;
  int inconsistent_edges = 0;  ///< manifold edges traversed in the same direction by both faces
  int boundary_edges = 0;
  int boundary_loops = 0;
};

MeshChecks check_mesh(const Mesh& mesh);

/// A component with fewer vertices cannot give a quadratic fit its 6 coefficients and a centre.
inline constexpr int kSmallComponent = 7;

/// What, in the mesh alone, can keep an estimator from answering at a vertex: the first of
/// isolated (no face), small_component (fewer than kSmallComponent vertices in its component),
/// nonmanifold (its faces form several fans, or it ends a non-manifold edge), zero_area_star
/// (every incident face zero-area), boundary; none otherwise. `curvbench estimate` counts its
/// failed and excluded vertices by it, `curvbench info` lists the counts.
enum class VertexDefect : std::uint8_t {
  none,
  isolated,
  small_component,
  nonmanifold,
  zero_area_star,
  boundary
};
inline constexpr int kVertexDefectCount = 6;
const char* to_string(VertexDefect defect);

/// The defect of every vertex. O(n + m).
std::vector<VertexDefect> vertex_defects(const Mesh& mesh);

}  // namespace curvbench
