#include "meshgen/marching_cubes_tables.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <stdexcept>
#include <string>

namespace curvbench::mc {

namespace {

using P3 = Eigen::Vector3d;

P3 corner_point(int c) {
  return {double(kCornerOffset[c][0]), double(kCornerOffset[c][1]), double(kCornerOffset[c][2])};
}

// Midpoint of cube edge e: the vertex position used to orient and check segments.
P3 edge_midpoint(int e) {
  return 0.5 * (corner_point(kEdgeCorner[e][0]) + corner_point(kEdgeCorner[e][1]));
}

int edge_of(int a, int b) {
  for (int e = 0; e < 12; ++e) {
    if ((kEdgeCorner[e][0] == a && kEdgeCorner[e][1] == b) ||
        (kEdgeCorner[e][0] == b && kEdgeCorner[e][1] == a))
      return e;
  }
  throw std::logic_error("marching cubes tables: corners " + std::to_string(a) + ", " +
                         std::to_string(b) + " are not joined by an edge");
}

bool edge_on_face(int e, int q) {
  auto on = [q](int c) {
    for (int k = 0; k < 4; ++k)
      if (kFaceCorner[q][k] == c) return true;
    return false;
  };
  return on(kEdgeCorner[e][0]) && on(kEdgeCorner[e][1]);
}

bool edges_share_face(int e1, int e2) {
  for (int q = 0; q < 6; ++q)
    if (edge_on_face(e1, q) && edge_on_face(e2, q)) return true;
  return false;
}

P3 face_outward_normal(int q) {
  P3 m = P3::Zero();
  m[2 - q / 2] = (q % 2 == 0) ? -1.0 : 1.0;  // q = 0,1: z; 2,3: y; 4,5: x
  return m;
}

// Polygons (closed cycles of cube edges, counter-clockwise seen from outside) of one case under
// one decision mask.
std::vector<std::vector<int>> case_polygons(int cube_case, int decisions) {
  auto inside = [cube_case](int c) { return ((cube_case >> c) & 1) != 0; };
  std::array<int, 12> next;
  std::array<int, 12> incoming{};
  next.fill(-1);

  auto add_segment = [&](int q, int ea, int eb, const P3& p) {
    // Direction t = p x m (p: towards the outside within the face, m: outward face normal) makes
    // the bounded polygon counter-clockwise around the outward surface normal.
    const P3 t = p.cross(face_outward_normal(q));
    const double s = (edge_midpoint(eb) - edge_midpoint(ea)).dot(t);
    if (s == 0.0) throw std::logic_error("marching cubes tables: segment without direction");
    if (s < 0.0) std::swap(ea, eb);
    if (next[ea] != -1) throw std::logic_error("marching cubes tables: edge leaves twice");
    next[ea] = eb;
    ++incoming[eb];
  };

  for (int q = 0; q < 6; ++q) {
    const auto& fc = kFaceCorner[q];
    P3 center = P3::Zero();
    for (int k = 0; k < 4; ++k) center += 0.25 * corner_point(fc[k]);
    int count = 0;
    for (int k = 0; k < 4; ++k) count += inside(fc[k]) ? 1 : 0;
    if (count == 0 || count == 4) continue;

    // Segment cutting off corner k of the face.
    auto cut_corner = [&](int k) {
      const int c = fc[k], prev = fc[(k + 3) % 4], nxt = fc[(k + 1) % 4];
      const P3 p = inside(c) ? P3(center - corner_point(c)) : P3(corner_point(c) - center);
      add_segment(q, edge_of(prev, c), edge_of(c, nxt), p);
    };

    if (count == 1 || count == 3) {
      for (int k = 0; k < 4; ++k)
        if (inside(fc[k]) == (count == 1)) cut_corner(k);
    } else if (inside(fc[0]) == inside(fc[2])) {  // ambiguous: diagonal corners alike
      const bool cut_inside = ((decisions >> q) & 1) != 0;
      for (int k = 0; k < 4; ++k)
        if (inside(fc[k]) == cut_inside) cut_corner(k);
    } else {  // two adjacent inside corners
      int cut[2], n = 0;
      P3 p = P3::Zero();
      for (int k = 0; k < 4; ++k) {
        const int a = fc[k], b = fc[(k + 1) % 4];
        if (inside(a) != inside(b)) cut[n++] = edge_of(a, b);
        p += (inside(a) ? -0.5 : 0.5) * corner_point(a);
      }
      add_segment(q, cut[0], cut[1], p);
    }
  }

  std::vector<std::vector<int>> polygons;
  std::array<bool, 12> visited{};
  for (int e = 0; e < 12; ++e) {
    const bool cut = inside(kEdgeCorner[e][0]) != inside(kEdgeCorner[e][1]);
    if ((next[e] != -1) != cut || incoming[e] != (cut ? 1 : 0))
      throw std::logic_error("marching cubes tables: open polygon in case " +
                             std::to_string(cube_case));
    if (!cut || visited[e]) continue;
    std::vector<int> poly;
    for (int x = e; !visited[x]; x = next[x]) {
      visited[x] = true;
      poly.push_back(x);
    }
    polygons.push_back(std::move(poly));
  }
  return polygons;
}

// Triangulates a polygon of cube edges without a chord between two cut edges of one cube face
// (the neighbouring cell could create the same chord). Prefers a fan (lowest apex position),
// else the first valid triangulation found by recursion on edge (v0, v1). Returns false when no
// such triangulation exists.
bool triangulate(const std::vector<int>& poly, std::vector<std::array<int, 3>>& tris) {
  const int k = static_cast<int>(poly.size());
  auto chord_ok = [&](int i, int j) {  // positions in poly, not adjacent
    return !edges_share_face(poly[i], poly[j]);
  };
  tris.clear();
  for (int s = 0; s < k; ++s) {
    bool ok = true;
    for (int j = 2; j < k - 1 && ok; ++j) ok = chord_ok(s, (s + j) % k);
    if (!ok) continue;
    for (int j = 1; j < k - 1; ++j)
      tris.push_back({poly[s], poly[(s + j) % k], poly[(s + j + 1) % k]});
    return true;
  }
  // General search over the triangulations of the sub-polygon idx (positions, cyclic order).
  std::function<bool(const std::vector<int>&, std::vector<std::array<int, 3>>&)> rec =
      [&](const std::vector<int>& idx, std::vector<std::array<int, 3>>& out) {
        const int m = static_cast<int>(idx.size());
        if (m < 3) return true;
        for (int j = 2; j < m; ++j) {
          if (j != 2 && !chord_ok(idx[1], idx[j])) continue;
          if (j != m - 1 && !chord_ok(idx[j], idx[0])) continue;
          std::vector<std::array<int, 3>> trial{{poly[idx[0]], poly[idx[1]], poly[idx[j]]}};
          const std::vector<int> left(idx.begin() + 1, idx.begin() + j + 1);
          std::vector<int> right(idx.begin() + j, idx.end());
          right.push_back(idx[0]);
          if (rec(left, trial) && rec(right, trial)) {
            out.insert(out.end(), trial.begin(), trial.end());
            return true;
          }
        }
        return false;
      };
  std::vector<int> all(k);
  for (int i = 0; i < k; ++i) all[i] = i;
  return rec(all, tris);
}

}  // namespace

CaseTables::CaseTables() {
  offset_.assign(256 * 64 + 1, 0);
  centered_offset_.assign(256 * 64 + 1, 0);
  for (int c = 0; c < 256; ++c) {
    int amb = 0;
    for (int q = 0; q < 6; ++q) {
      const auto& fc = kFaceCorner[q];
      const bool i0 = (c >> fc[0]) & 1, i1 = (c >> fc[1]) & 1, i2 = (c >> fc[2]) & 1,
                 i3 = (c >> fc[3]) & 1;
      if (i0 == i2 && i1 == i3 && i0 != i1) amb |= 1 << q;
    }
    ambiguous_[c] = static_cast<std::uint8_t>(amb);
    for (int d = 0; d < 64; ++d) {
      const int key = 64 * c + d;
      if ((d & ~amb) == 0) {
        std::vector<std::array<int, 3>> tris;
        for (const auto& poly : case_polygons(c, d)) {
          if (triangulate(poly, tris)) {
            for (const auto& t : tris)
              for (int e : t) edges_.push_back(static_cast<std::int8_t>(e));
          } else {
            centered_.push_back(static_cast<std::int8_t>(poly.size()));
            for (int e : poly) centered_.push_back(static_cast<std::int8_t>(e));
          }
        }
      }
      offset_[key + 1] = static_cast<std::uint32_t>(edges_.size());
      centered_offset_[key + 1] = static_cast<std::uint32_t>(centered_.size());
    }
  }
}

const CaseTables& case_tables() {
  static const CaseTables tables;
  return tables;
}

}  // namespace curvbench::mc
