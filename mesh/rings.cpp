#include "mesh/rings.h"

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
  verts_.reserve(128);
  faces_.reserve(256);
}

void RingCollector::begin(int v) {
  if (++stamp_ == 0) {  // wrapped around: clear the stamps once every 2^32 collections
    std::fill(vert_stamp_.begin(), vert_stamp_.end(), 0);
    std::fill(face_stamp_.begin(), face_stamp_.end(), 0);
    stamp_ = 1;
  }
  center_ = v;
  assigned_ = false;
  verts_.clear();
  faces_.clear();
  verts_.push_back(v);
  vert_stamp_[v] = stamp_;
  half_steps_ = 0;
  layer_begin_ = 0;
  layer_end_ = 1;
  face_layer_begin_ = face_layer_end_ = 0;
}

// Inlined into the steps below: it runs a dozen times per vertex and per ring step.
[[gnu::always_inline]] inline bool RingCollector::add_face(int f) {
  if (face_stamp_[f] == stamp_) return false;
  face_stamp_[f] = stamp_;
  faces_.push_back(f);
  for (int k = 0; k < 3; ++k) {
    const int w = mesh_->face_vertex(f, k);
    if (vert_stamp_[w] != stamp_) {
      vert_stamp_[w] = stamp_;
      verts_.push_back(w);
    }
  }
  return true;
}

// F_{k+1} = F_k plus the faces of the vertices V_k \ V_{k-1} (the faces of older vertices are
// already in). After a half step, the half-step vertices are in V_{k+1} \ V_k and become part of
// the next layer automatically, because they are appended after layer_end_.
bool RingCollector::integer_step() {
  const size_t first_new_face = faces_.size();
  for (size_t i = layer_begin_; i < layer_end_; ++i)
    for (int f : mesh_->vertex_faces(verts_[i])) add_face(f);
  layer_begin_ = layer_end_;
  layer_end_ = verts_.size();
  face_layer_begin_ = first_new_face;
  face_layer_end_ = faces_.size();
  return faces_.size() > first_new_face;
}

// Adds every face sharing an edge with a face of F_k. Only faces added by the last integer step
// can have such neighbours outside F_k (docs/algorithms.md §1.1). Edges are matched through the
// vertex-face lists, so non-manifold edges contribute all their faces.
bool RingCollector::half_step() {
  const size_t before = faces_.size();
  for (size_t i = face_layer_begin_; i < face_layer_end_; ++i) {
    const int f = faces_[i];
    for (int k = 0; k < 3; ++k) {
      const int a = mesh_->face_vertex(f, k);
      const int b = mesh_->face_vertex(f, (k + 1) % 3);
      const int g = mesh_->face_neighbor(f, k);
      if (g >= 0) {
        add_face(g);
        continue;
      }
      // Boundary or non-manifold edge: scan the faces of a for faces that also contain b.
      for (int h : mesh_->vertex_faces(a)) {
        if (h == f || face_stamp_[h] == stamp_) continue;
        if (mesh_->face_vertex(h, 0) == b || mesh_->face_vertex(h, 1) == b ||
            mesh_->face_vertex(h, 2) == b)
          add_face(h);
      }
    }
  }
  return faces_.size() > before;
}

// One half ring further: 0 -> 1 (the first step is an integer step), k -> k+½, k+½ -> k+1.
bool RingCollector::grow() {
  if (assigned_) collect(center_, ring());  // rebuild the buffers and the layer bookkeeping
  const size_t before = faces_.size();
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
  return faces_.size() > before;
}

void RingCollector::collect(int v, double ring) {
  const long target = std::lround(2.0 * ring);
  if (!(ring >= 1.0) || std::abs(0.5 * static_cast<double>(target) - ring) > 1e-9)
    throw UsageError("ring size must be a multiple of 0.5 and at least 1, got " +
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
  const long max_steps = std::lround(2.0 * max_ring);
  int stalled = 0;  // two half steps in a row that add nothing: the component is exhausted
  while (static_cast<int>(verts_.size()) - 1 < min_neighbours && half_steps_ < max_steps &&
         stalled < 2) {
    stalled = grow() ? 0 : stalled + 1;
  }
  return ring();
}

double RingCollector::collect(int v, const NeighbourhoodSpec& spec) {
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
