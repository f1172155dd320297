// k-ring and half-ring neighbourhoods (paper §4.1; docs/algorithms.md §1.1-1.2).
//
//   F_1     = faces incident on v;                V_r = vertices of F_r
//   F_k     = union of F(w) over w in V_{k-1}     (k >= 2 integer)
//   F_{k+½} = F_k plus every face sharing an edge with a face of F_k
//
// The collector owns scratch buffers sized to the mesh and reuses them, so collecting a ring
// allocates nothing once the buffers have grown to their working size. Use one collector per
// thread. Results are deterministic (discovery order depends only on the mesh).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "mesh/mesh.h"

namespace curvbench {

/// Number of monomial coefficients of a bivariate polynomial of degree d: (d+1)(d+2)/2.
constexpr int num_coefficients(int degree) {
  return (degree + 1) * (degree + 2) / 2;
}

/// Default ring (d+1)/2 for a degree-d fit (paper §5.1, Table 2): 1, 1.5, 2, 2.5, ...
constexpr double default_ring(int degree) {
  return 0.5 * (degree + 1);
}

/// Minimum number of neighbours (centre excluded) before the ring stops growing:
/// round(1.5 * n(d)) = 5, 9, 15, 23, 32, 42 for d = 1..6 (docs/algorithms.md §1.2, [C2]).
constexpr int min_neighbours(int degree) {
  return (3 * num_coefficients(degree) + 1) / 2;
}

class RingCollector {
 public:
  explicit RingCollector(const Mesh& mesh);

  /// Collects the r-ring of v, r in {1, 1.5, 2, 2.5, ...}. Throws UsageError otherwise.
  /// Afterwards neighbours() holds V_r without v, faces() holds F_r.
  void collect(int v, double ring);

  /// Collects the integer k-ring of v (k >= 1): the same sets V_k, F_k as collect(v, k), without
  /// the half steps in between (cheaper); the discovery order differs. Throws UsageError for
  /// k < 1.
  void collect_integer(int v, int k);
  /// Collects ring r0 and grows it by half rings while fewer than min_neighbours neighbours are
  /// found, until max_ring is reached or the ring stops growing (the component is exhausted).
  /// Returns the ring actually collected.
  double collect_at_least(int v, double r0, int min_neighbours, double max_ring);

  /// Grows the current ring by one half ring. Returns false if nothing new was added.
  bool grow();

  /// Current ring size (after collect/grow).
  double ring() const { return 0.5 * half_steps_; }
  int center() const { return center_; }
  /// Ring vertices, centre excluded, in discovery order.
  std::span<const int> neighbours() const { return {verts_.data() + 1, verts_.size() - 1}; }
  /// Ring faces F_r in discovery order.
  std::span<const int> faces() const { return faces_; }

 private:
  void begin(int v);
  bool integer_step();
  bool half_step();
  bool add_face(int f);

  const Mesh* mesh_;
  std::vector<std::uint32_t> vert_stamp_;
  std::vector<std::uint32_t> face_stamp_;
  std::uint32_t stamp_ = 0;
  std::vector<int> verts_;  // verts_[0] = centre
  std::vector<int> faces_;
  int center_ = -1;
  int half_steps_ = 0;      // ring = half_steps_ / 2
  size_t layer_begin_ = 0;  // vertices V_k \ V_{k-1} of the last integer step: [begin, end)
  size_t layer_end_ = 0;
  size_t face_layer_begin_ = 0;  // faces added by the last integer step: [begin, end)
  size_t face_layer_end_ = 0;
};

}  // namespace curvbench
