// Indexed triangle mesh with compressed vertex-to-face and face-to-face adjacency.
//
//   V  n x 3 double  vertex positions
//   F  m x 3 int     triangles, counter-clockwise seen from outside (closed) or from +z (open)
//
// Edge k of face f runs from F(f,k) to F(f,(k+1)%3). Construction validates the indices and
// builds all adjacency in O(m log m); the mesh is immutable afterwards and safe to share between
// threads.
#pragma once

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "core/types.h"

namespace curvbench {

class Mesh {
 public:
  Mesh() = default;

  /// Builds adjacency. Throws InputError if an index is out of range, if a face repeats a vertex,
  /// or if a coordinate is NaN or Inf. `source` names the origin (a file) in error messages.
  Mesh(VertexMatrix vertices, FaceMatrix faces, const std::string& source = "mesh");

  /// What the constructor's `source` named (a file's path, "mesh"): for error messages.
  const std::string& source() const { return source_; }

  /// Normals given with the points (a file's nx ny nz: .pwn, a 6-column .xyz, PLY, NOFF), as
  /// given: n x 3, not normalised, any row may be zero or non-finite; empty when none were given
  /// (docs/point_sets.md, option point-normals=file).
  const VertexMatrix& given_normals() const { return given_normals_; }
  bool has_given_normals() const { return given_normals_.rows() > 0; }
  /// Sets given_normals(); throws InputError naming source() unless `normals` has one row per
  /// vertex (or none: clears them).
  void set_given_normals(VertexMatrix normals);

  int num_vertices() const { return static_cast<int>(V_.rows()); }
  int num_faces() const { return static_cast<int>(F_.rows()); }
  int num_edges() const { return num_edges_; }

  const VertexMatrix& vertices() const { return V_; }
  const FaceMatrix& faces() const { return F_; }
  Vec3 position(int v) const { return V_.row(v).transpose(); }
  int face_vertex(int f, int k) const { return F_(f, k); }

  /// Faces incident on vertex v, in increasing face index.
  std::span<const int> vertex_faces(int v) const {
    return {vf_faces_.data() + vf_offsets_[v], vf_faces_.data() + vf_offsets_[v + 1]};
  }

  /// Face across edge k of face f; -1 when the edge is a boundary edge or non-manifold.
  int face_neighbor(int f, int k) const { return std::max(ff_[3 * f + k], -1); }
  /// True if edge k of face f has exactly one incident face.
  bool is_boundary_edge(int f, int k) const { return ff_[3 * f + k] == kBoundary; }
  /// True if edge k of face f has three or more incident faces.
  bool is_nonmanifold_edge(int f, int k) const { return ff_[3 * f + k] == kNonManifold; }

  /// True for a vertex on a boundary edge (an edge with exactly one incident face).
  bool is_boundary_vertex(int v) const { return boundary_vertex_[v] != 0; }
  bool has_boundary() const { return num_boundary_edges_ > 0; }
  int num_boundary_vertices() const { return num_boundary_vertices_; }
  int num_boundary_edges() const { return num_boundary_edges_; }
  /// Edges with three or more incident faces.
  int num_nonmanifold_edges() const { return num_nonmanifold_edges_; }
  /// Manifold interior edges traversed in the same direction by both faces.
  int num_inconsistent_edges() const { return num_inconsistent_edges_; }
  bool is_consistently_oriented() const { return num_inconsistent_edges_ == 0; }
  /// Vertices referenced by no face.
  int num_isolated_vertices() const { return num_isolated_vertices_; }

  /// V - E + F.
  int euler_characteristic() const { return num_vertices() - num_edges_ + num_faces(); }

  /// Mean length over the unique (undirected) edges. 0 for a mesh without faces.
  double mean_edge_length() const { return mean_edge_length_; }

  /// Signed volume enclosed (divergence theorem); > 0 for a closed outward-oriented surface.
  double signed_volume() const;

  /// Reverses the corner order of every face f with flip[f] != 0 (m entries), then rotates every
  /// face so that its smallest vertex index comes first (mesh/orientation.h), updating the
  /// adjacency in O(m) instead of rebuilding it: the result equals
  /// Mesh(vertices(), reoriented faces). Returns the number of faces whose row changed.
  int reorient_faces(const std::vector<unsigned char>& flip);

  /// Area-weighted vertex normals (docs/algorithms.md §2): normalised sum of the un-normalised face
  /// cross products (x2-x1)x(x3-x1). n x 3. A vertex without faces or with zero total area gets
  /// the zero vector.
  VertexMatrix area_weighted_normals() const;
  /// Row v of area_weighted_normals(): the cross products of v's faces summed in increasing face
  /// order (the order of the whole-mesh loop, so the bits agree), normalised.
  Vec3 area_weighted_normal(int v) const;

 private:
  static constexpr int kBoundary = -1;     // ff_ entry of a boundary edge
  static constexpr int kNonManifold = -2;  // ff_ entry of a non-manifold edge

  VertexMatrix V_;
  FaceMatrix F_;
  std::string source_;
  VertexMatrix given_normals_;
  std::vector<int> vf_offsets_{0};  // n+1
  std::vector<int> vf_faces_;       // sum of valences
  std::vector<int> ff_;             // 3m: neighbour face, kBoundary or kNonManifold
  std::vector<unsigned char> boundary_vertex_;
  int num_edges_ = 0;
  int num_boundary_edges_ = 0;
  int num_boundary_vertices_ = 0;
  int num_nonmanifold_edges_ = 0;
  int num_inconsistent_edges_ = 0;
  int num_isolated_vertices_ = 0;
  double mean_edge_length_ = 0.0;
};

}  // namespace curvbench
