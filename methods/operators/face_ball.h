// A breadth-first walk over the faces of a ball around a vertex, shared by the operators that
// integrate over a ball of radius r instead of the 1-ring (normal cycle, ICC): it starts from the
// vertex's faces and visits each face once; the visitor decides, per face, across which edges the
// walk continues (enqueue(g) adds the neighbour face g unless it was visited).
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/mesh.h"
#include "methods/estimator.h"

namespace curvbench {

/// Per-thread scratch: a visit stamp per face (no clearing between vertices) and the queue.
struct FaceBallWorkspace final : Workspace {
  explicit FaceBallWorkspace(const Mesh& mesh) : stamp(static_cast<size_t>(mesh.num_faces()), 0) {
    queue.reserve(256);
  }
  std::vector<std::uint32_t> stamp;
  std::uint32_t current = 0;
  std::vector<int> queue;
};

/// Visits `start` (the vertex's faces) and then every face the visitor enqueues, in
/// breadth-first order: visit(f, enqueue) with enqueue(g) for g >= 0.
template <class Visit>
void walk_face_ball(std::span<const int> start, FaceBallWorkspace& ws, Visit&& visit) {
  if (++ws.current == 0) {  // stamps wrapped: clear
    std::fill(ws.stamp.begin(), ws.stamp.end(), 0);
    ws.current = 1;
  }
  ws.queue.assign(start.begin(), start.end());
  for (int f : start) ws.stamp[static_cast<size_t>(f)] = ws.current;
  const auto enqueue = [&ws](int g) {
    if (g < 0 || ws.stamp[static_cast<size_t>(g)] == ws.current) return;
    ws.stamp[static_cast<size_t>(g)] = ws.current;
    ws.queue.push_back(g);
  };
  for (size_t q = 0; q < ws.queue.size(); ++q) visit(ws.queue[q], enqueue);
}

}  // namespace curvbench
