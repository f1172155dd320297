// Topology checks shared by the marching-cubes and torus-isosurface tests.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <span>
#include <vector>

#include "mesh/mesh.h"

namespace curvbench::testing {

/// Vertices whose incident faces do not form one closed fan (walking across the edges that leave
/// the vertex must visit every incident face once and return). 0 on a closed 2-manifold.
inline int num_nonmanifold_vertices(const Mesh& m) {
  int bad = 0;
  for (int v = 0; v < m.num_vertices(); ++v) {
    const std::span<const int> fs = m.vertex_faces(v);
    if (fs.empty()) {
      ++bad;
      continue;
    }
    int f = fs[0], steps = 0;
    do {
      int k = 0;
      while (m.face_vertex(f, k) != v) ++k;
      f = m.face_neighbor(f, k);  // across the edge v -> next
      ++steps;
    } while (f >= 0 && f != fs[0] && steps <= static_cast<int>(fs.size()));
    if (f != fs[0] || steps != static_cast<int>(fs.size())) ++bad;
  }
  return bad;
}

/// Connected components of the face-adjacency graph.
inline int num_components(const Mesh& m) {
  std::vector<int> comp(m.num_faces(), -1);
  int count = 0;
  for (int s = 0; s < m.num_faces(); ++s) {
    if (comp[s] >= 0) continue;
    std::vector<int> stack{s};
    comp[s] = count;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int g = m.face_neighbor(f, k);
        if (g >= 0 && comp[g] < 0) {
          comp[g] = count;
          stack.push_back(g);
        }
      }
    }
    ++count;
  }
  return count;
}

/// Closed, consistently oriented 2-manifold without isolated vertices.
inline void expect_closed_oriented_manifold(const Mesh& m) {
  EXPECT_GT(m.num_faces(), 0);
  EXPECT_EQ(m.num_boundary_edges(), 0);
  EXPECT_EQ(m.num_nonmanifold_edges(), 0);
  EXPECT_EQ(m.num_inconsistent_edges(), 0);
  EXPECT_EQ(m.num_isolated_vertices(), 0);
  EXPECT_EQ(num_nonmanifold_vertices(m), 0);
  EXPECT_EQ(2 * m.num_edges(), 3 * m.num_faces());
}

/// Grid edges of the cubic grid ax^3 whose end samples differ in "inside" (f < 0), counted
/// independently of marching_cubes.
inline int count_sign_changing_edges(const std::vector<double>& ax,
                                     const std::function<double(double, double, double)>& f) {
  const int n = static_cast<int>(ax.size());
  std::vector<char> in(static_cast<size_t>(n) * n * n);
  auto id = [n](int i, int j, int k) { return (static_cast<size_t>(k) * n + j) * n + i; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) in[id(i, j, k)] = f(ax[i], ax[j], ax[k]) < 0.0;
  int count = 0;
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        if (i + 1 < n && in[id(i, j, k)] != in[id(i + 1, j, k)]) ++count;
        if (j + 1 < n && in[id(i, j, k)] != in[id(i, j + 1, k)]) ++count;
        if (k + 1 < n && in[id(i, j, k)] != in[id(i, j, k + 1)]) ++count;
      }
    }
  }
  return count;
}

}  // namespace curvbench::testing
