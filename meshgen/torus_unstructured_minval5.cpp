// Edge flips and tangential relaxation that remove the vertices of valence < 5 from the
// well-shaped torus meshes (contract and method in torus_unstructured_minval5.h).
#include "meshgen/torus_unstructured_minval5.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "meshgen/generation_cache.h"
#include "meshgen/torus_unstructured.h"

namespace curvbench {
namespace {

constexpr int kMinValence = 5;
constexpr int kMaxValence = 9;  // a flip may not raise a vertex above 9
constexpr int kMaxPrepare = 4;  // neighbour-raising flips per low-valence vertex
constexpr double kMinAngle = 25.0 * std::numbers::pi / 180.0;
constexpr int kRelaxRings = 1;      // relax the corners of the flipped quads and their 1-ring
constexpr int kRelaxSweeps = 5;     // Gauss-Seidel sweeps per pass
constexpr double kRelaxStep = 0.5;  // fraction of the way to the neighbours' centroid
constexpr int kMaxPasses = 20;

double min_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto angle = [](const Vec3& o, const Vec3& x, const Vec3& y) {
    const Vec3 e1 = x - o, e2 = y - o;
    return std::atan2(e1.cross(e2).norm(), e1.dot(e2));
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

// A closed oriented triangle mesh that can flip edges: faces, a map from each directed edge to
// the face that traverses it, valences and one face per vertex. The map is only looked up, never
// iterated, so nothing depends on its order.
class FlipMesh {
 public:
  FlipMesh(const Mesh& mesh, const Surface& surface) : surface_(surface) {
    const auto n = static_cast<size_t>(mesh.num_vertices());
    points.resize(n);
    for (size_t v = 0; v < n; ++v) points[v] = mesh.position(static_cast<int>(v));
    faces.resize(static_cast<size_t>(mesh.num_faces()));
    valence.assign(n, 0);
    face_of_vertex_.assign(n, -1);
    edges_.reserve(6 * faces.size());
    for (int f = 0; f < mesh.num_faces(); ++f) {
      auto& t = faces[static_cast<size_t>(f)];
      for (int k = 0; k < 3; ++k) t[static_cast<size_t>(k)] = mesh.face_vertex(f, k);
      for (int k = 0; k < 3; ++k) {
        edges_[key(t[k], t[(k + 1) % 3])] = f;
        ++valence[static_cast<size_t>(t[k])];  // closed manifold: faces around v = valence
        face_of_vertex_[static_cast<size_t>(t[k])] = f;
      }
    }
  }

  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> faces;
  std::vector<int> valence;

  // The face traversing a -> b, or -1.
  int face(int a, int b) const {
    const auto it = edges_.find(key(a, b));
    return it == edges_.end() ? -1 : it->second;
  }

  // The neighbours of v in counter-clockwise order: v, ring[i], ring[i+1] is a face.
  std::vector<int> ring(int v) const {
    const auto& t = faces[static_cast<size_t>(face_of_vertex_[static_cast<size_t>(v)])];
    const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    const int first = t[(k + 1) % 3];
    std::vector<int> out;
    int a = first;
    do {
      out.push_back(a);
      a = third(face(v, a), v, a);
    } while (a != first);
    return out;
  }

  // True if the triangle faces outward (its normal agrees with the torus normal at its centroid).
  bool outward(const Vec3& a, const Vec3& b, const Vec3& c) const {
    return (b - a).cross(c - a).dot(surface_.evaluate((a + b + c) / 3.0).normal) > 0;
  }

  // The flip of edge a-b: faces (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c). Sets c
  // and d; false if the flip is not allowed (c-d already an edge, or a new face turned inward).
  bool can_flip(int a, int b, int& c, int& d) const {
    const int f1 = face(a, b), f2 = face(b, a);
    c = third(f1, a, b);
    d = third(f2, b, a);
    if (c == d || face(c, d) >= 0 || face(d, c) >= 0) return false;
    return outward(pt(c), pt(a), pt(d)) && outward(pt(d), pt(b), pt(c));
  }

  // Smallest angle of the two faces after the flip of a-b (c, d from can_flip).
  double flipped_min_angle(int a, int b, int c, int d) const {
    return std::min(min_angle(pt(c), pt(a), pt(d)), min_angle(pt(d), pt(b), pt(c)));
  }

  void flip(int a, int b, int c, int d) {
    const int f1 = face(a, b), f2 = face(b, a);
    edges_.erase(key(a, b));
    edges_.erase(key(b, a));
    faces[static_cast<size_t>(f1)] = {c, a, d};
    faces[static_cast<size_t>(f2)] = {d, b, c};
    edges_[key(a, d)] = f1;
    edges_[key(d, c)] = f1;
    edges_[key(b, c)] = f2;
    edges_[key(c, d)] = f2;
    --valence[static_cast<size_t>(a)];
    --valence[static_cast<size_t>(b)];
    ++valence[static_cast<size_t>(c)];
    ++valence[static_cast<size_t>(d)];
    face_of_vertex_[static_cast<size_t>(a)] = f1;
    face_of_vertex_[static_cast<size_t>(b)] = f2;
    face_of_vertex_[static_cast<size_t>(c)] = f1;
    face_of_vertex_[static_cast<size_t>(d)] = f1;
  }

  // Smallest angle of the faces around v if v were at p; -1 if one of them would turn inward.
  double star_min_angle(const std::vector<int>& ring, const Vec3& p) const {
    double out = std::numbers::pi;
    for (size_t i = 0; i < ring.size(); ++i) {
      const Vec3& a = pt(ring[i]);
      const Vec3& b = pt(ring[(i + 1) % ring.size()]);
      if (!outward(p, a, b)) return -1.0;
      out = std::min(out, min_angle(p, a, b));
    }
    return out;
  }

  const Vec3& pt(int v) const { return points[static_cast<size_t>(v)]; }
  const Surface& surface() const { return surface_; }

 private:
  std::uint64_t key(int a, int b) const {
    return static_cast<std::uint64_t>(a) * points.size() + static_cast<std::uint64_t>(b);
  }
  int third(int f, int a, int b) const {
    for (const int v : faces[static_cast<size_t>(f)])
      if (v != a && v != b) return v;
    return -1;
  }

  const Surface& surface_;
  std::unordered_map<std::uint64_t, int> edges_;
  std::vector<int> face_of_vertex_;
};

// The best flip of an edge of v's link (the edge a-b opposite v in a face (v, a, b); the flip
// joins v to the far corner d, raising v's valence by one): allowed if a and b keep valence
// >= kMinValence, d stays <= kMaxValence and can_flip agrees; edges with an end at `keep` are
// left alone. Best = largest smallest angle of the two new faces. quad[0] < 0 if none.
struct LinkFlip {
  std::array<int, 4> quad{-1, -1, -1, -1};  // a, b, c (the raised vertex), d
  double min_angle = -1.0;
};
LinkFlip best_link_flip(const FlipMesh& m, int v, int keep) {
  LinkFlip best;
  const std::vector<int> ring = m.ring(v);
  for (size_t i = 0; i < ring.size(); ++i) {
    const int a = ring[i], b = ring[(i + 1) % ring.size()];
    if (a == keep || b == keep) continue;
    if (m.valence[static_cast<size_t>(a)] <= kMinValence ||
        m.valence[static_cast<size_t>(b)] <= kMinValence)
      continue;
    int c = -1, d = -1;
    if (!m.can_flip(a, b, c, d) || m.valence[static_cast<size_t>(d)] >= kMaxValence) continue;
    const double q = m.flipped_min_angle(a, b, c, d);
    if (q > best.min_angle) best = {{a, b, c, d}, q};
  }
  return best;
}

// Step 1: raises every vertex of valence < kMinValence by flips of edges of its link. When every
// such flip would leave an end of the flipped edge at valence 4 (a link like 7, 5, 8, 5), first
// raises one of v's valence-5 neighbours by a flip of its own link that leaves v's edges alone,
// at most kMaxPrepare times per vertex. Marks the corners of the flipped quads in `touched`.
// Returns the number of flips.
int flip_low_valences(FlipMesh& m, std::vector<unsigned char>& touched) {
  int flips = 0;
  for (int v = 0; v < static_cast<int>(m.points.size()); ++v) {
    int prepared = 0;
    while (m.valence[static_cast<size_t>(v)] < kMinValence) {
      LinkFlip f = best_link_flip(m, v, -1);
      if (f.quad[0] < 0 && prepared < kMaxPrepare) {
        for (const int e : m.ring(v)) {
          if (m.valence[static_cast<size_t>(e)] != kMinValence) continue;
          const LinkFlip g = best_link_flip(m, e, v);
          if (g.min_angle > f.min_angle) f = g;
        }
        ++prepared;
      }
      if (f.quad[0] < 0) break;  // nothing allowed now; relaxation and the next pass may help
      m.flip(f.quad[0], f.quad[1], f.quad[2], f.quad[3]);
      for (const int u : f.quad) touched[static_cast<size_t>(u)] = 1;
      ++flips;
    }
  }
  return flips;
}

// Adds the corners of every face that has a marked corner, `rings` times.
void grow(const FlipMesh& m, std::vector<unsigned char>& marked, int rings) {
  for (int r = 0; r < rings; ++r) {
    std::vector<unsigned char> next = marked;
    for (const auto& t : m.faces)
      if (marked[static_cast<size_t>(t[0])] || marked[static_cast<size_t>(t[1])] ||
          marked[static_cast<size_t>(t[2])])
        for (const int v : t) next[static_cast<size_t>(v)] = 1;
    marked.swap(next);
  }
}

// Step 2: tangential relaxation of the marked vertices, each move kept only if it raises the
// smallest angle around the vertex. Returns the number of kept moves.
int relax(FlipMesh& m, const std::vector<unsigned char>& marked) {
  int moves = 0;
  for (int sweep = 0; sweep < kRelaxSweeps; ++sweep) {
    for (int v = 0; v < static_cast<int>(m.points.size()); ++v) {
      if (!marked[static_cast<size_t>(v)]) continue;
      const std::vector<int> ring = m.ring(v);
      Vec3 centroid = Vec3::Zero();
      for (const int u : ring) centroid += m.pt(u);
      centroid /= static_cast<double>(ring.size());
      const Vec3& p = m.pt(v);
      const Vec3 n = m.surface().evaluate(p).normal;
      Vec3 step = centroid - p;
      step -= n.dot(step) * n;
      const Vec3 q = m.surface().project(p + kRelaxStep * step);
      if (m.star_min_angle(ring, q) > m.star_min_angle(ring, p)) {
        m.points[static_cast<size_t>(v)] = q;
        ++moves;
      }
    }
  }
  return moves;
}

// Marks the corners of every face with an angle under kMinAngle; returns how many faces.
int mark_small_angles(const FlipMesh& m, std::vector<unsigned char>& marked) {
  int count = 0;
  for (const auto& t : m.faces)
    if (min_angle(m.pt(t[0]), m.pt(t[1]), m.pt(t[2])) < kMinAngle) {
      ++count;
      for (const int v : t) marked[static_cast<size_t>(v)] = 1;
    }
  return count;
}

GeneratedMesh generate(int level, std::uint64_t seed) {
  const GeneratedMesh base = torus_unstructured(level, seed);
  FlipMesh m(base.mesh, *base.surface);
  const size_t nv = m.points.size();
  int flips = 0, moves = 0, passes = 0;
  for (;; ++passes) {
    std::vector<unsigned char> marked(nv, 0);
    const int flipped = flip_low_valences(m, marked);
    const int small = mark_small_angles(m, marked);
    const bool low_valence =
        std::any_of(m.valence.begin(), m.valence.end(), [](int v) { return v < kMinValence; });
    if (flipped == 0 && small == 0 && !low_valence) break;
    if (passes == kMaxPasses)
      throw std::runtime_error(
          "torus-unstructured-minval5 level " + std::to_string(level) +
          ": vertices of valence < 5 or angles under 25 degrees remain after " +
          std::to_string(kMaxPasses) + " passes");
    flips += flipped;
    grow(m, marked, kRelaxRings);
    moves += relax(m, marked);
  }

  // Faces by their smallest vertex, as in the base family (the vertex numbering is the base's).
  std::stable_sort(m.faces.begin(), m.faces.end(), [](const auto& a, const auto& b) {
    return std::min({a[0], a[1], a[2]}) < std::min({b[0], b[1], b[2]});
  });
  VertexMatrix V(static_cast<Eigen::Index>(nv), 3);
  for (size_t i = 0; i < nv; ++i) V.row(static_cast<Eigen::Index>(i)) = m.points[i].transpose();
  FaceMatrix F(static_cast<Eigen::Index>(m.faces.size()), 3);
  for (size_t i = 0; i < m.faces.size(); ++i)
    F.row(static_cast<Eigen::Index>(i)) << m.faces[i][0], m.faces[i][1], m.faces[i][2];

  GeneratedMesh out;
  out.exact_points = V;
  out.mesh = Mesh(std::move(V), std::move(F), "torus-unstructured-minval5");
  out.surface = base.surface;
  out.family = "torus-unstructured-minval5";
  out.level = level;
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "; then %d edge flips (no valence < 5) and %d relaxation moves in %d pass%s, "
                "vertices on the torus",
                flips, moves, passes, passes == 1 ? "" : "es");
  out.description = "torus-unstructured-minval5 from " + base.description + buf;
  return out;
}

}  // namespace

int torus_unstructured_minval5_max_level() {
  return torus_unstructured_max_level();
}

GeneratedMesh torus_unstructured_minval5(int level, std::uint64_t seed) {
  if (level < 1 || level > torus_unstructured_max_level())
    throw UsageError("torus-unstructured-minval5: level " + std::to_string(level) +
                     " out of range [1, " + std::to_string(torus_unstructured_max_level()) + "]");
  return generate_once("torus-unstructured-minval5", level, seed, generate);
}

}  // namespace curvbench
