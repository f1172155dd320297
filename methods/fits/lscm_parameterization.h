// Least-squares conformal maps (Levy et al. 2002) of a ring patch: the parameterization of
// LSCM-d (paper §4.2.3; docs/algorithms.md §8).
//
// Input: the mesh, the centre vertex p0, its ring neighbours V_r \ {p0} and the ring faces F_r
// (RingCollector::neighbours() and faces()). Ring vertex i is p0 for i = 0 and neighbours[i-1]
// for i >= 1; N = 1 + |neighbours|. Every face must use ring vertices only.
//
// Disk cut. The LSCM needs a topological disk (connected, consistently oriented, edge- and
// vertex-manifold, one boundary loop, V - E + F = 1). A ring that wraps around a hole or a thin
// handle of the mesh, or that covers a whole small closed component, is not one; it is then cut
// to a disk around p0 (RingPatch::build): starting from one face at p0, the ring faces are taken
// in discovery order (the star of p0 first, then outwards), and a face is accepted only if the
// patch stays a disk, i.e. if it meets the patch in exactly one boundary edge and brings a new
// vertex, or in exactly two boundary edges (filling a notch); a face rejected for now is retried
// after each acceptance. The patch vertices are then the ring vertices of the accepted faces.
//
// Output: uv (N rows), uv[i] = (u, v) of ring vertex i, normalised (docs/algorithms.md §6.2, §8):
// translated so that uv[0] = (0, 0), and v -> -v if the mapped patch is clockwise (total signed
// area of the mapped faces < 0). Normals and curvatures of a fit are invariant under similarities
// of (u, v), so no scaling or rotation is applied. A ring vertex left out by the disk cut gets a
// non-finite uv[i] (NaN), which the fitting driver drops (ring_fit_estimator.h); patch().cut()
// says whether that happened.
//
// Two implementations of the same energy E = sum_T |sum_k W_T,k U_k|^2 s_T, U_k = u_k + i v_k,
// W_T = (z3 - z2, z1 - z3, z2 - z1) with z_k the counter-clockwise local 2-D coordinates of T:
//   CgalLscmMap: CGAL::Surface_mesh + CGAL::Surface_mesh_parameterization::LSCM_parameterizer_3
//     with its default border parameterizer Two_vertices_parameterizer_3, as the paper did. CGAL's
//     energy has s_T = 1 (it does not divide by the area) and pins the two vertices extreme along
//     the longest axis of the patch's axis-aligned bounding box (so the map is not rotation
//     invariant). The normal equations are solved with Eigen's SimplicialLDLT (CGAL's default
//     when Eigen is available) or OpenNL's Jacobi-preconditioned conjugate gradients (the default
//     without Eigen; relative tolerance 1e-6).
//   LscmMap: in-house, dense. Default (docs/algorithms.md §8 [CH]): Levy's s_T = 1 / A_T, pins the
//     two patch vertices farthest apart at U = 0 and U = 1, then solves the Hermitian normal
//     equations of the complex least-squares problem (N - 2 complex unknowns, the same problem as
//     the real 2N-unknown form) by an in-place Cholesky factorisation. Buffers are reused, so a
//     call allocates nothing once they have grown. With LscmMapOptions{bounding_box, false} it
//     solves CGAL's problem (same pins, same energy): the two maps then agree up to a similarity.
// The LSCM minimiser depends on which two vertices are pinned (not only up to a similarity) unless
// the patch is developable; so the default LscmMap and CgalLscmMap differ slightly on curved
// patches. Both reproduce a planar patch up to a similarity.
//
// Both return false, and never throw, on: fewer than 3 vertices, a ring with no disk around p0
// (not even one face), coincident pins, a failed solve, or a non-finite / zero-area result.
#pragma once

#include <complex>
#include <memory>
#include <span>
#include <vector>

#include "core/types.h"
#include "mesh/mesh.h"

namespace curvbench {

/// A ring patch copied to local indices (0 = centre), with the topological-disk test and the
/// disk cut. Owns reusable buffers (one per thread).
class RingPatch {
 public:
  explicit RingPatch(const Mesh& mesh);

  /// Copies the ring (see the file comment for the vertex order) and, if it is not a topological
  /// disk, cuts it to one around the centre. Returns true iff the resulting patch has at least 3
  /// vertices and is a topological disk.
  bool build(int centre, std::span<const int> neighbours, std::span<const int> faces);

  int num_vertices() const { return static_cast<int>(positions_.size()); }
  int num_faces() const { return static_cast<int>(faces_.size() / 3); }
  const Vec3& position(int i) const { return positions_[static_cast<size_t>(i)]; }
  /// Local vertex k (0..2) of face f, in the mesh's orientation.
  int face_vertex(int f, int k) const { return faces_[static_cast<size_t>(3 * f + k)]; }

  /// True if the last build() had to cut the ring (some ring faces, maybe vertices, left out).
  bool cut() const { return cut_; }
  /// Number of ring vertices N = 1 + |neighbours| of the last build().
  int ring_size() const { return ring_size_; }
  /// Ring index (0 = centre, i = neighbours[i-1]) of patch vertex i; the identity unless cut().
  int ring_index(int i) const { return cut_ ? ring_index_[static_cast<size_t>(i)] : i; }
  /// Spreads a map of the patch vertices (num_vertices() rows) to the ring vertices
  /// (ring_size() rows); ring vertices outside the patch get NaN.
  void to_ring(std::span<const Vec2> patch_uv, std::vector<Vec2>& ring_uv) const;

 private:
  bool is_disk();
  bool cut_to_disk();

  const Mesh* mesh_;
  std::vector<int> local_;       // mesh vertex -> local index, -1 outside the current patch
  std::vector<int> face_local_;  // mesh face -> local index, -1 outside the current patch
  std::vector<int> globals_;
  std::vector<int> face_globals_;
  std::vector<Vec3> positions_;
  std::vector<int> faces_;  // 3 local indices per face
  // Halfedge h = 3f + k (is_disk): twin (-1 on the boundary); per vertex: number of outgoing
  // halfedges, one outgoing halfedge, the outgoing boundary halfedge (-1 if none) and the number
  // of outgoing boundary halfedges. Then reused for the connectivity search.
  std::vector<int> twin_;
  std::vector<int> valence_;
  std::vector<int> some_out_;
  std::vector<int> boundary_out_;
  std::vector<int> boundary_count_;
  // Disk cut: directed patch edges (dense n x n flags), accepted faces, retry list, and the ring
  // index of each patch vertex.
  bool cut_ = false;
  int ring_size_ = 0;
  std::vector<unsigned char> directed_;
  std::vector<unsigned char> in_patch_;
  std::vector<int> accepted_;
  std::vector<int> pending_;
  std::vector<int> ring_index_;
};

/// Signed area of the mapped patch: sum over faces of the 2-D cross product / 2.
double mapped_signed_area(const RingPatch& patch, std::span<const Vec2> uv);

/// Normalisation shared by both maps: uv[0] -> (0, 0), v -> -v if the mapped area is negative.
/// Returns false if a coordinate is not finite or the mapped area is 0.
bool normalise_patch_map(const RingPatch& patch, std::span<Vec2> uv);

enum class LscmPins {
  farthest_pair,  ///< the two patch vertices farthest apart in 3-D (docs/algorithms.md §8)
  bounding_box,   ///< CGAL Two_vertices_parameterizer_3: extremes along the longest bbox axis
};

struct LscmMapOptions {
  LscmPins pins = LscmPins::farthest_pair;
  /// true: Levy's energy, each triangle weighted by 1/A_T (docs/algorithms.md §8); false: CGAL's
  /// unnormalised energy. A_T is floored at 1e-6 times the mean patch face area so that
  /// degenerate (marching-cubes) triangles do not make the system singular.
  bool area_normalised = true;
};

/// In-house dense LSCM (see the file comment). One object per thread.
class LscmMap {
 public:
  explicit LscmMap(const Mesh& mesh, LscmMapOptions options = {});

  /// Maps the patch; uv is resized to N (NaN rows outside a cut patch). Returns false (uv
  /// unspecified) on failure.
  bool map(int centre, std::span<const int> neighbours, std::span<const int> faces,
           std::vector<Vec2>& uv);

  const RingPatch& patch() const { return patch_; }
  const LscmMapOptions& options() const { return options_; }

 private:
  LscmMapOptions options_;
  RingPatch patch_;
  std::vector<int> unknown_;  // local vertex -> unknown index, -1 for a pin
  std::vector<std::complex<double>> matrix_;
  std::vector<std::complex<double>> rhs_;
  std::vector<Vec2> patch_uv_;  // per patch vertex, before to_ring()
};

enum class CgalLscmSolver {
  eigen_ldlt,  ///< Eigen::SimplicialLDLT (CGAL's default with Eigen)
  opennl_cg,   ///< OpenNL Jacobi-preconditioned conjugate gradients (CGAL's default without)
};

/// CGAL's LSCM_parameterizer_3 (see the file comment). One object per thread; CGAL allocates
/// inside every call (that is the reference's cost).
class CgalLscmMap {
 public:
  explicit CgalLscmMap(const Mesh& mesh, CgalLscmSolver solver = CgalLscmSolver::eigen_ldlt);
  ~CgalLscmMap();
  CgalLscmMap(const CgalLscmMap&) = delete;
  CgalLscmMap& operator=(const CgalLscmMap&) = delete;

  /// Maps the patch; uv is resized to N (NaN rows outside a cut patch). Returns false (uv
  /// unspecified) on failure.
  bool map(int centre, std::span<const int> neighbours, std::span<const int> faces,
           std::vector<Vec2>& uv);

  const RingPatch& patch() const { return patch_; }

 private:
  struct Impl;
  RingPatch patch_;
  CgalLscmSolver solver_;
  std::unique_ptr<Impl> impl_;
  std::vector<Vec2> patch_uv_;  // per patch vertex, before to_ring()
};

}  // namespace curvbench
