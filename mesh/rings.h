// k-ring and half-ring neighbourhoods (paper §4.1; docs/algorithms.md §1.1-1.2).
//
//   F_1     = faces incident on v;                V_r = vertices of F_r
//   F_k     = union of F(w) over w in V_{k-1}     (k >= 2 integer)
//   F_{k+½} = F_k plus every face sharing an edge with a face of F_k
//
// The collector owns scratch buffers sized to the mesh and reuses them, so collecting a ring
// allocates nothing once the buffers have grown to their working size. Use one collector per
// thread. Results are deterministic (discovery order depends only on the mesh).
//
// A collector can also serve a neighbourhood gathered earlier (assign(), e.g. a row of
// mesh/neighbourhood_table.h) through the same neighbours(), faces() and ring().
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

/// The number of vertices (centre excluded) of the r-ring on a regular valence-6 triangulation:
/// 3k(k+1) for r = k, plus the 6k vertices across the k-ring's boundary edges for r = k + 1/2
/// (6, 12, 18, 30, 36 for r = 1, 1.5, 2, 2.5, 3). The point sets' default k is at least this
/// for the method's default ring (docs/point_sets.md).
constexpr int regular_ring_size(double ring) {
  const int k = static_cast<int>(ring);
  return 3 * k * (k + 1) + (ring > k ? 6 * k : 0);
}

/// The starting neighbourhood of a ring-based method (paper §4.1, docs/algorithms.md §1.2):
/// ring r0; when adaptive, grown by half rings while fewer than min_neighbours neighbours are
/// found, up to max_ring (the methods use min_neighbours(d) and 2 r0). Non-adaptive specs have
/// min_neighbours = 0 and max_ring = ring, so that equal neighbourhoods compare equal.
///
/// A point neighbourhood (no connectivity; docs/point_sets.md) is instead the k nearest other
/// points, or the other points within a radius (absolute, or a multiple of the point set's mean
/// spacing, points/point_search.h); its ring is 0 and it never grows.
struct NeighbourhoodSpec {
  enum class Points : std::uint8_t { none, knn, radius, radius_spacing };

  double ring = 1.0;
  bool adaptive = false;
  int min_neighbours = 0;
  double max_ring = 1.0;
  Points points = Points::none;
  double size = 0.0;  ///< k, the radius, or the multiple of the mean spacing

  static NeighbourhoodSpec fixed(double ring) { return {ring, false, 0, ring}; }
  static NeighbourhoodSpec at_least(double ring, int min_neighbours, double max_ring) {
    return {ring, true, min_neighbours, max_ring};
  }
  static NeighbourhoodSpec point_rule(Points rule, double size) {
    return {0.0, false, 0, 0.0, rule, size};
  }
  bool is_points() const { return points != Points::none; }
  bool operator==(const NeighbourhoodSpec&) const = default;
};

class RingCollector {
 public:
  explicit RingCollector(const Mesh& mesh);

  /// Collects the r-ring of v, r in {1, 1.5, 2, 2.5, ..., 1e6}. Throws UsageError otherwise.
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
  /// collect_at_least or collect, as the spec says. Returns the ring actually collected.
  double collect(int v, const NeighbourhoodSpec& spec);

  /// Serves a neighbourhood gathered earlier instead of collecting it: afterwards center() is v,
  /// ring() is `ring`, num_faces() is `num_faces`, and neighbours() and faces() return the given
  /// spans (which must outlive their use) until the next collect. `faces` may be empty when the
  /// caller never reads faces() (num_faces is |F_r| all the same). grow() first collects the same
  /// ring from scratch, so that growing gives what it gives after collect(v, ring); ring 0 is a
  /// point neighbourhood (NeighbourhoodSpec::is_points), which grow() leaves as it is (false).
  void assign(int v, double ring, std::span<const int> neighbours, std::span<const int> faces,
              size_t num_faces);

  /// Grows the current ring by one half ring. Returns false if nothing new was added.
  bool grow();

  /// Current ring size (after collect/grow/assign).
  double ring() const { return 0.5 * half_steps_; }
  int center() const { return center_; }
  /// Ring vertices, centre excluded, in discovery order.
  std::span<const int> neighbours() const {
    if (assigned_) return assigned_neighbours_;
    return {verts_.data() + 1, num_verts_ - 1};
  }
  /// Ring faces F_r in discovery order.
  std::span<const int> faces() const {
    if (assigned_) return assigned_faces_;
    return {faces_.data(), num_faces_};
  }
  /// |F_r| (also after assign() without the faces themselves).
  size_t num_faces() const { return assigned_ ? assigned_num_faces_ : num_faces_; }

 private:
  void begin(int v);
  bool integer_step();
  bool half_step();
  void reserve(size_t new_faces);
  void add_vertex(int w, std::uint32_t stamp);
  void add_face(int f, std::uint32_t stamp);

  const Mesh* mesh_;
  std::vector<std::uint32_t> vert_stamp_;
  std::vector<std::uint32_t> face_stamp_;
  std::uint32_t stamp_ = 0;
  // The ring in discovery order: verts_[0, num_verts_) (verts_[0] = centre) and
  // faces_[0, num_faces_). The buffers are longer (reserve()), so that an element can be written
  // before it is known to be new and kept by advancing the count: no branch on the stamps.
  std::vector<int> verts_;
  std::vector<int> faces_;
  size_t num_verts_ = 0;
  size_t num_faces_ = 0;
  int center_ = -1;
  int half_steps_ = 0;      // ring = half_steps_ / 2
  size_t layer_begin_ = 0;  // vertices V_k \ V_{k-1} of the last integer step: [begin, end)
  size_t layer_end_ = 0;
  size_t face_layer_begin_ = 0;  // faces added by the last integer step: [begin, end)
  size_t face_layer_end_ = 0;
  bool assigned_ = false;  // neighbours()/faces() come from assign(), not from the buffers
  std::span<const int> assigned_neighbours_;
  std::span<const int> assigned_faces_;
  size_t assigned_num_faces_ = 0;
};

}  // namespace curvbench
