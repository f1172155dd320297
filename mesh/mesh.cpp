#include "mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "core/errors.h"

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
    : V_(std::move(vertices)), F_(std::move(faces)) {
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
  vf_offsets_.assign(n + 1, 0);
  for (int f = 0; f < m; ++f)
    for (int k = 0; k < 3; ++k) ++vf_offsets_[F_(f, k) + 1];
  for (int v = 0; v < n; ++v) vf_offsets_[v + 1] += vf_offsets_[v];
  vf_faces_.resize(static_cast<size_t>(3) * m);
  {
    std::vector<int> cursor(vf_offsets_.begin(), vf_offsets_.end() - 1);
    for (int f = 0; f < m; ++f)
      for (int k = 0; k < 3; ++k) vf_faces_[cursor[F_(f, k)]++] = f;
  }
  num_isolated_vertices_ = 0;
  for (int v = 0; v < n; ++v)
    if (vf_offsets_[v + 1] == vf_offsets_[v]) ++num_isolated_vertices_;

  // Face -> face across each edge, from the half-edges grouped by undirected edge {lo, hi} in
  // increasing (lo, hi) order: the half-edges of vertex lo's edges are among its faces' (vf_),
  // gathered per vertex and sorted by (hi, face, k). No mesh-sized temporary.
  ff_.assign(static_cast<size_t>(3) * m, kBoundary);
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

double Mesh::signed_volume() const {
  double vol = 0.0;
  for (int f = 0; f < num_faces(); ++f) {
    const Vec3 a = position(F_(f, 0)), b = position(F_(f, 1)), c = position(F_(f, 2));
    vol += a.dot(b.cross(c));
  }
  return vol / 6.0;
}

VertexMatrix Mesh::area_weighted_normals() const {
  VertexMatrix N = VertexMatrix::Zero(num_vertices(), 3);
  for (int f = 0; f < num_faces(); ++f) {
    const Vec3 a = position(F_(f, 0)), b = position(F_(f, 1)), c = position(F_(f, 2));
    const Vec3 cr = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) N.row(F_(f, k)) += cr.transpose();
  }
  for (int v = 0; v < num_vertices(); ++v) {
    const double len = N.row(v).norm();
    if (len > 0.0) N.row(v) /= len;
  }
  return N;
}

}  // namespace curvbench
