#include "mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "core/errors.h"
#include "core/huge_pages.h"

namespace curvbench {

namespace {

struct HalfEdge {
  int hi;  // the larger vertex of the edge (the smaller one is known)
  int face;
  int k;         // the edge runs from the face's vertex k to vertex k + 1
  bool forward;  // true if the face traverses min -> max
};

}  // namespace

Mesh::Mesh(VertexMatrix vertices, FaceMatrix faces, const std::string& source)
    : V_(std::move(vertices)), F_(std::move(faces)), source_(source) {
  const int n = num_vertices();
  const int m = num_faces();

  for (int v = 0; v < n; ++v) {
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(V_(v, c))) {
        std::ostringstream msg;
        msg << source << ": vertex " << v << " has a non-finite coordinate (" << V_(v, 0) << ", "
            << V_(v, 1) << ", " << V_(v, 2) << ")";
        throw InputError(msg.str());
      }
    }
  }
  for (int f = 0; f < m; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int idx = F_(f, k);
      if (idx < 0 || idx >= n) {
        std::ostringstream msg;
        msg << source << ": face " << f << " references vertex " << idx << ", out of range [0, "
            << n << ")";
        throw InputError(msg.str());
      }
    }
    if (F_(f, 0) == F_(f, 1) || F_(f, 1) == F_(f, 2) || F_(f, 0) == F_(f, 2)) {
      std::ostringstream msg;
      msg << source << ": face " << f << " repeats a vertex (" << F_(f, 0) << " " << F_(f, 1) << " "
          << F_(f, 2) << ")";
      throw InputError(msg.str());
    }
  }

  // Vertex -> faces, compressed (counting sort keeps faces in increasing order).
  // The big arrays are advised to huge pages before they are first written (core/huge_pages.h).
  reserve_huge(vf_offsets_, static_cast<size_t>(n) + 1);
  vf_offsets_.assign(n + 1, 0);
  for (int f = 0; f < m; ++f)
    for (int k = 0; k < 3; ++k) ++vf_offsets_[F_(f, k) + 1];
  for (int v = 0; v < n; ++v) vf_offsets_[v + 1] += vf_offsets_[v];
  reserve_huge(vf_faces_, static_cast<size_t>(3) * m);
  vf_faces_.resize(static_cast<size_t>(3) * m);
  {
    std::vector<int> cursor;
    reserve_huge(cursor, static_cast<size_t>(n));
    cursor.assign(vf_offsets_.begin(), vf_offsets_.end() - 1);
    for (int f = 0; f < m; ++f)
      for (int k = 0; k < 3; ++k) vf_faces_[cursor[F_(f, k)]++] = f;
  }
  num_isolated_vertices_ = 0;
  for (int v = 0; v < n; ++v)
    if (vf_offsets_[v + 1] == vf_offsets_[v]) ++num_isolated_vertices_;

  // Face -> face across each edge, from the half-edges grouped by undirected edge {lo, hi} in
  // increasing (lo, hi) order: the half-edges of vertex lo's edges are among its faces' (vf_),
  // gathered per vertex and sorted by (hi, face, k). No mesh-sized temporary.
  reserve_huge(ff_, static_cast<size_t>(3) * m);
  ff_.assign(static_cast<size_t>(3) * m, kBoundary);
  reserve_huge(boundary_vertex_, static_cast<size_t>(n));
  boundary_vertex_.assign(n, 0);
  num_edges_ = num_boundary_edges_ = num_nonmanifold_edges_ = num_inconsistent_edges_ = 0;
  double total_length = 0.0;
  std::vector<HalfEdge> he;  // the half-edges whose smaller vertex is the current one
  for (int lo = 0; lo < n; ++lo) {
    he.clear();
    for (int i = vf_offsets_[lo]; i < vf_offsets_[lo + 1]; ++i) {
      const int f = vf_faces_[i];
      for (int k = 0; k < 3; ++k) {  // the face's edges k (from vertex k to k + 1) at lo
        const int a = F_(f, k), b = F_(f, (k + 1) % 3);
        if (std::min(a, b) == lo) he.push_back({std::max(a, b), f, k, a < b});
      }
    }
    // Faces come in increasing order (vf_), so a stable sort by hi gives (hi, face, k): an
    // insertion sort for the usual handful.
    const auto by_hi = [](const HalfEdge& x, const HalfEdge& y) { return x.hi < y.hi; };
    if (he.size() > 32) {
      std::stable_sort(he.begin(), he.end(), by_hi);
    } else {
      for (size_t i = 1; i < he.size(); ++i) {
        const HalfEdge x = he[i];
        size_t j = i;
        for (; j > 0 && by_hi(x, he[j - 1]); --j) he[j] = he[j - 1];
        he[j] = x;
      }
    }
    for (size_t i = 0; i < he.size();) {
      size_t j = i;
      while (j < he.size() && he[j].hi == he[i].hi) ++j;
      const size_t count = j - i;
      ++num_edges_;
      const int hi = he[i].hi;
      total_length += (V_.row(lo) - V_.row(hi)).norm();
      if (count == 1) {
        ++num_boundary_edges_;
        boundary_vertex_[lo] = boundary_vertex_[hi] = 1;
      } else if (count == 2) {
        ff_[3 * he[i].face + he[i].k] = he[i + 1].face;
        ff_[3 * he[i + 1].face + he[i + 1].k] = he[i].face;
        if (he[i].forward == he[i + 1].forward) ++num_inconsistent_edges_;
      } else {
        ++num_nonmanifold_edges_;
        for (size_t h = i; h < j; ++h) ff_[3 * he[h].face + he[h].k] = kNonManifold;
      }
      i = j;
    }
  }
  num_boundary_vertices_ =
      static_cast<int>(std::count(boundary_vertex_.begin(), boundary_vertex_.end(), 1));
  mean_edge_length_ = num_edges_ > 0 ? total_length / num_edges_ : 0.0;
}

int Mesh::reorient_faces(const std::vector<unsigned char>& flip) {
  const int m = num_faces();
  int changed = 0;
  bool any_flipped = false;
  for (int f = 0; f < m; ++f) {
    // Corners c and the edges e (e[k] from c[k] to c[k+1]) after the flip: (a, b, c) reversed is
    // (a, c, b), whose edges are the old edges 2, 1, 0.
    int c[3] = {F_(f, 0), F_(f, 1), F_(f, 2)};
    const bool flipped = flip[static_cast<size_t>(f)] != 0;
    if (!flipped && c[0] < c[1] && c[0] < c[2]) continue;  // the usual face: as it is
    any_flipped = any_flipped || flipped;
    int e[3] = {ff_[3 * f], ff_[3 * f + 1], ff_[3 * f + 2]};
    if (flipped) {
      std::swap(c[1], c[2]);
      std::swap(e[0], e[2]);
    }
    int first = 0;
    for (int k = 1; k < 3; ++k)
      if (c[k] < c[first]) first = k;
    if (!flipped && first == 0) continue;
    ++changed;
    for (int k = 0; k < 3; ++k) {
      F_(f, k) = c[(k + first) % 3];
      ff_[3 * f + k] = e[(k + first) % 3];
    }
  }
  // Manifold interior edges run the same way by both faces, counted once per edge. A rotation
  // keeps every edge's direction: without a flip the count stands.
  if (!any_flipped) return changed;
  num_inconsistent_edges_ = 0;
  for (int f = 0; f < m; ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = ff_[3 * f + k];
      if (g <= f) continue;  // boundary, non-manifold, or counted from g
      const int a = F_(f, k), b = F_(f, (k + 1) % 3);
      for (int j = 0; j < 3; ++j)
        if (F_(g, j) == a && F_(g, (j + 1) % 3) == b) ++num_inconsistent_edges_;
    }
  return changed;
}

void Mesh::set_given_normals(VertexMatrix normals) {
  if (normals.rows() != 0 && normals.rows() != V_.rows())
    throw InputError(source_ + ": " + std::to_string(normals.rows()) + " normals for " +
                     std::to_string(V_.rows()) + " points");
  given_normals_ = std::move(normals);
}

double Mesh::signed_volume() const {
  double vol = 0.0;
  for (int f = 0; f < num_faces(); ++f) {
    const Vec3 a = position(F_(f, 0)), b = position(F_(f, 1)), c = position(F_(f, 2));
    vol += a.dot(b.cross(c));
  }
  return vol / 6.0;
}

Vec3 Mesh::area_weighted_normal(int v) const {
  Vec3 sum = Vec3::Zero();
  for (int f : vertex_faces(v)) {
    const Vec3 a = position(F_(f, 0)), b = position(F_(f, 1)), c = position(F_(f, 2));
    sum += (b - a).cross(c - a);
  }
  const double len = sum.norm();
  return len > 0.0 ? Vec3(sum / len) : sum;
}

VertexMatrix Mesh::area_weighted_normals() const {
  VertexMatrix N(num_vertices(), 3);
  advise_huge_pages(N.data(), sizeof(double) * static_cast<size_t>(N.size()));
  for (int v = 0; v < num_vertices(); ++v) N.row(v) = area_weighted_normal(v).transpose();
  return N;
}

}  // namespace curvbench
