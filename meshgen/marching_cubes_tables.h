// Case tables of marching cubes with face-consistent resolution of ambiguous faces
// (docs/algorithms.md §10.1(a); used by meshgen/marching_cubes.h).
//
// Cube numbering (Bourke / Lorensen-Cline):
//   corner c = 0..7 at offset kCornerOffset[c] = (dx, dy, dz):
//     0 (0,0,0)  1 (1,0,0)  2 (1,1,0)  3 (0,1,0)  4 (0,0,1)  5 (1,0,1)  6 (1,1,1)  7 (0,1,1)
//   edge e = 0..11 joins corners kEdgeCorner[e] = {a, b} with a the lower grid index:
//     0 (0,1) 1 (1,2) 2 (3,2) 3 (0,3) 4 (4,5) 5 (5,6) 6 (7,6) 7 (4,7) 8 (0,4) 9 (1,5) 10 (2,6)
//     11 (3,7)
//   face q = 0..5 (-z, +z, -y, +y, -x, +x) with its corners in cyclic order kFaceCorner[q].
// Case index: bit c set iff corner c is inside (f < 0).
//
// The tables are not the classic 256-case list (whose complementary-symmetric entries leave holes
// at ambiguous faces). They are generated once, on first use, from a per-face rule:
//   * a face with 1 or 3 inside corners: one segment cutting off the odd corner;
//   * a face with 2 adjacent inside corners: one segment between its two cut edges;
//   * an ambiguous face (2 diagonal inside corners): two segments, cutting off either the two
//     inside corners or the two outside corners. Bit q of the decision mask selects "the outside
//     (f >= 0) corners are connected across face q", i.e. the inside corners are cut off.
// Each segment is directed so that the polygon it bounds is counter-clockwise seen from the
// outside (increasing f); segments are chained into closed polygons through the cut edges, and
// each polygon is triangulated without any chord joining two cut edges of one cube face, so that
// two cells sharing a face never create the same edge twice. A polygon for which no such
// triangulation exists (it crosses two or more ambiguous faces twice: 8-, 9- and 12-gons of a few
// multiply ambiguous cases) is listed as "centered": the caller adds one vertex inside it and
// fans around that vertex (as Chernyaev's MC33 does). Two cells that share a face compute the
// same segments on it (with opposite directions) as long as they use the same decision for it;
// the result is then a closed, consistently oriented 2-manifold.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace curvbench::mc {

inline constexpr std::array<std::array<int, 3>, 8> kCornerOffset = {
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};

inline constexpr std::array<std::array<int, 2>, 12> kEdgeCorner = {{{0, 1},
                                                                    {1, 2},
                                                                    {3, 2},
                                                                    {0, 3},
                                                                    {4, 5},
                                                                    {5, 6},
                                                                    {7, 6},
                                                                    {4, 7},
                                                                    {0, 4},
                                                                    {1, 5},
                                                                    {2, 6},
                                                                    {3, 7}}};

/// Corners of each face in cyclic order (-z, +z, -y, +y, -x, +x).
inline constexpr std::array<std::array<int, 4>, 6> kFaceCorner = {
    {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}}};

/// Generated case tables (see the file comment). Immutable after construction.
class CaseTables {
 public:
  /// Triangles of case `cube_case` (0..255) under the decision mask `decisions` (6 bits; only
  /// the bits of ambiguous_faces(cube_case) are used): 3 cube edges per triangle, counter-
  /// clockwise seen from outside.
  std::span<const std::int8_t> triangles(int cube_case, int decisions) const {
    const int key = 64 * cube_case + (decisions & ambiguous_[cube_case]);
    return {edges_.data() + offset_[key], edges_.data() + offset_[key + 1]};
  }
  /// Polygons of the case that need an extra vertex, encoded as [k, e_0 .. e_{k-1}] records
  /// (k cube edges in counter-clockwise order seen from outside). Usually empty.
  std::span<const std::int8_t> centered_polygons(int cube_case, int decisions) const {
    const int key = 64 * cube_case + (decisions & ambiguous_[cube_case]);
    return {centered_.data() + centered_offset_[key], centered_.data() + centered_offset_[key + 1]};
  }
  /// Bit q set iff face q of the case is ambiguous (two diagonal inside corners).
  int ambiguous_faces(int cube_case) const { return ambiguous_[cube_case]; }

  /// Builds all tables (256 cases x every decision mask). Throws std::logic_error if a polygon
  /// cannot be closed (never happens; a self-check of the generator).
  CaseTables();

 private:
  std::array<std::uint8_t, 256> ambiguous_{};
  std::vector<std::uint32_t> offset_;  // 256*64 + 1
  std::vector<std::int8_t> edges_;
  std::vector<std::uint32_t> centered_offset_;  // 256*64 + 1
  std::vector<std::int8_t> centered_;
};

/// The tables, built on first use (thread-safe).
const CaseTables& case_tables();

}  // namespace curvbench::mc
