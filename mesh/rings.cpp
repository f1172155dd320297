#include "mesh/rings.h"

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "core/huge_pages.h"

namespace curvbench {

RingCollector::RingCollector(const Mesh& mesh) : mesh_(&mesh) {
  // 12 bytes per vertex and thread, zeroed before the parallel loop: on huge pages, one
  // first-touch fault per 2 MiB (core/huge_pages.h).
  reserve_huge(vert_stamp_, static_cast<size_t>(mesh.num_vertices()));
  vert_stamp_.resize(static_cast<size_t>(mesh.num_vertices()), 0);
  reserve_huge(face_stamp_, static_cast<size_t>(mesh.num_faces()));
  face_stamp_.resize(static_cast<size_t>(mesh.num_faces()), 0);
  verts_.resize(128);
  faces_.resize(256);
}

void RingCollector::begin(int v) {
  if (++stamp_ == 0) {  // wrapped around: clear the stamps once every 2^32 collections
    std::fill(vert_stamp_.begin(), vert_stamp_.end(), 0);
    std::fill(face_stamp_.begin(), face_stamp_.end(), 0);
    stamp_ = 1;
  }
  center_ = v;
  assigned_ = false;
  verts_[0] = v;
  num_verts_ = 1;
  num_faces_ = 0;
  vert_stamp_[v] = stamp_;
  half_steps_ = 0;
  layer_begin_ = 0;
  layer_end_ = 1;
  face_layer_begin_ = face_layer_end_ = 0;
}

// Room for up to new_faces more faces and their vertices (3 each), plus the one slot that
// add_face and add_vertex write past the end.
void RingCollector::reserve(size_t new_faces) {
  if (faces_.size() < num_faces_ + new_faces + 1) faces_.resize(2 * (num_faces_ + new_faces + 1));
  if (verts_.size() < num_verts_ + 3 * new_faces + 1)
    verts_.resize(2 * (num_verts_ + 3 * new_faces + 1));
}

// Written unconditionally, kept (the count advanced) only if new: which neighbours are new
// follows the mesh, not a pattern a branch predictor learns.
[[gnu::always_inline]] inline void RingCollector::add_vertex(int w, std::uint32_t stamp) {
  verts_[num_verts_] = w;
  num_verts_ += vert_stamp_[w] != stamp ? 1 : 0;
  vert_stamp_[w] = stamp;
}

// Inlined into the steps below: it runs a dozen times per vertex and per ring step. The face's
// vertices are offered whether or not the face is new: the vertices of a face already in the
// ring are all in it, so they are not added again. `stamp` is stamp_, passed by value: a store
// to a stamp array could otherwise alias the member and force a reload after every store.
[[gnu::always_inline]] inline void RingCollector::add_face(int f, std::uint32_t stamp) {
  faces_[num_faces_] = f;
  num_faces_ += face_stamp_[f] != stamp ? 1 : 0;
  face_stamp_[f] = stamp;
  for (int k = 0; k < 3; ++k) add_vertex(mesh_->face_vertex(f, k), stamp);
}

// F_{k+1} = F_k plus the faces of the vertices V_k \ V_{k-1} (the faces of older vertices are
// already in). After a half step, the half-step vertices are in V_{k+1} \ V_k and become part of
// the next layer automatically, because they are appended after layer_end_.
bool RingCollector::integer_step() {
  size_t incident = 0;
  for (size_t i = layer_begin_; i < layer_end_; ++i)
    incident += mesh_->vertex_faces(verts_[i]).size();
  reserve(incident);
  const size_t first_new_face = num_faces_;
  const std::uint32_t stamp = stamp_;
  for (size_t i = layer_begin_; i < layer_end_; ++i)
    for (int f : mesh_->vertex_faces(verts_[i])) add_face(f, stamp);
  layer_begin_ = layer_end_;
  layer_end_ = num_verts_;
  face_layer_begin_ = first_new_face;
  face_layer_end_ = num_faces_;
  return num_faces_ > first_new_face;
}

// Adds every face sharing an edge with a face of F_k. Only faces added by the last integer step
// can have such neighbours outside F_k (docs/algorithms.md §1.1). Edges are matched through the
// vertex-face lists, so non-manifold edges contribute all their faces.
bool RingCollector::half_step() {
  const size_t before = num_faces_;
  reserve(3 * (face_layer_end_ - face_layer_begin_));
  const std::uint32_t stamp = stamp_;
  // From F_1, only the edge of each face opposite the centre can lead out of F_1: a face across
  // an edge at the centre contains the centre, so it is in F_1 already (for boundary and
  // non-manifold edges too). Those edges are skipped; the rest is the same walk in the same order.
  const bool first = half_steps_ == 2;
  for (size_t i = face_layer_begin_; i < face_layer_end_; ++i) {
    const int f = faces_[i];
    int k_begin = 0, k_end = 3;
    if (first) {
      k_begin = mesh_->face_vertex(f, 0) == center_   ? 1
                : mesh_->face_vertex(f, 1) == center_ ? 2
                                                      : 0;
      k_end = k_begin + 1;
    }
    for (int k = k_begin; k < k_end; ++k) {
      const int g = mesh_->face_neighbor(f, k);
      if (g >= 0) {
        add_face(g, stamp);
        continue;
      }
      // Boundary or non-manifold edge: scan the faces of a for faces that also contain b.
      const int a = mesh_->face_vertex(f, k);
      const int b = mesh_->face_vertex(f, (k + 1) % 3);
      const auto around_a = mesh_->vertex_faces(a);
      reserve(3 * (face_layer_end_ - i) + around_a.size());
      for (int h : around_a) {
        if (h == f || face_stamp_[h] == stamp) continue;
        if (mesh_->face_vertex(h, 0) == b || mesh_->face_vertex(h, 1) == b ||
            mesh_->face_vertex(h, 2) == b)
          add_face(h, stamp);
      }
    }
  }
  return num_faces_ > before;
}

// One half ring further: 0 -> 1 (the first step is an integer step), k -> k+½, k+½ -> k+1.
bool RingCollector::grow() {
  if (assigned_ && half_steps_ == 0) return false;  // a point neighbourhood does not grow
  if (assigned_) collect(center_, ring());  // rebuild the buffers and the layer bookkeeping
  const size_t before = num_faces_;
  if (half_steps_ == 0) {
    integer_step();
    half_steps_ = 2;
  } else if (half_steps_ % 2 == 0) {
    half_step();
    ++half_steps_;
  } else {
    integer_step();
    ++half_steps_;
  }
  return num_faces_ > before;
}

namespace {

constexpr double kLargestRing = 1e6;

// 2 r rounded to the nearest integer for r in [0, kLargestRing] (no libm call: once per vertex).
long half_steps_of(double ring) {
  return static_cast<long>(2.0 * ring + 0.5);
}

}  // namespace

void RingCollector::collect(int v, double ring) {
  const long target = ring >= 1.0 && ring <= kLargestRing ? half_steps_of(ring) : 0;
  if (target == 0 || std::abs(0.5 * static_cast<double>(target) - ring) > 1e-9)
    throw UsageError("ring size must be a multiple of 0.5, at least 1 and at most 1e6, got " +
                     std::to_string(ring));
  begin(v);
  while (half_steps_ < target) grow();
}

void RingCollector::collect_integer(int v, int k) {
  if (k < 1) throw UsageError("ring size must be at least 1, got " + std::to_string(k));
  begin(v);
  // F_{j+1} = F_j plus the faces of V_j \ V_{j-1}: the half rings F_{j+1/2} lie in F_{j+1}.
  for (int j = 0; j < k; ++j) integer_step();
  half_steps_ = 2 * k;
}

double RingCollector::collect_at_least(int v, double r0, int min_neighbours, double max_ring) {
  collect(v, r0);
  const long max_steps = half_steps_of(max_ring >= 0.0 ? std::min(max_ring, kLargestRing) : 0.0);
  int stalled = 0;  // two half steps in a row that add nothing: the component is exhausted
  while (static_cast<int>(num_verts_) - 1 < min_neighbours && half_steps_ < max_steps &&
         stalled < 2) {
    stalled = grow() ? 0 : stalled + 1;
  }
  return ring();
}

double RingCollector::collect(int v, const NeighbourhoodSpec& spec) {
  if (spec.is_points())
    throw UsageError("a point neighbourhood (k-NN or ball) is served from its table, not collected");
  if (spec.adaptive) return collect_at_least(v, spec.ring, spec.min_neighbours, spec.max_ring);
  collect(v, spec.ring);
  return ring();
}

void RingCollector::assign(int v, double ring, std::span<const int> neighbours,
                           std::span<const int> faces, size_t num_faces) {
  center_ = v;
  half_steps_ = static_cast<int>(std::lround(2.0 * ring));
  assigned_ = true;
  assigned_neighbours_ = neighbours;
  assigned_faces_ = faces;
  assigned_num_faces_ = num_faces;
}

}  // namespace curvbench
