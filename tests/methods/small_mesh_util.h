// Small closed meshes that made estimators give up on whole vertices where part of the answer
// exists: a cube whose flat faces carry valence-4 vertices with two collinear pairs of edges, the
// tetrahedron and octahedron (every neighbour's normal turns away), and a sphere with a
// four-vertex component beside it. Built here, never downloaded.
#pragma once

#include <array>
#include <map>
#include <tuple>
#include <vector>

#include "core/types.h"
#include "mesh/mesh.h"

namespace curvbench::testing {

/// A mesh from vertex and triangle lists.
inline Mesh mesh_of(const std::vector<Vec3>& P, const std::vector<std::array<int, 3>>& T,
                    const char* name) {
  VertexMatrix V(static_cast<Eigen::Index>(P.size()), 3);
  for (size_t i = 0; i < P.size(); ++i) V.row(static_cast<Eigen::Index>(i)) = P[i].transpose();
  FaceMatrix F(static_cast<Eigen::Index>(T.size()), 3);
  for (size_t i = 0; i < T.size(); ++i)
    F.row(static_cast<Eigen::Index>(i)) << T[i][0], T[i][1], T[i][2];
  return Mesh(V, F, name);
}

/// The cube [-1, 1]^3, each face an n x n grid of squares, each square split into four
/// triangles at its centre: the centres have valence 4, their edges two collinear pairs.
/// Closed, manifold, faces counter-clockwise seen from outside. Centre vertices come last in
/// each square's creation order; is_centre[v] says which they are.
inline Mesh cube_with_square_centres(int n, std::vector<bool>* is_centre = nullptr) {
  std::vector<Vec3> P;
  std::vector<std::array<int, 3>> T;
  std::map<std::tuple<long, long, long>, int> index;  // grid points in units of 1/(2n)
  std::vector<bool> centre;
  const auto id = [&](const Vec3& x, bool c) {
    const auto key = std::make_tuple(std::lround(x.x() * 2 * n), std::lround(x.y() * 2 * n),
                                     std::lround(x.z() * 2 * n));
    const auto [it, fresh] = index.emplace(key, static_cast<int>(P.size()));
    if (fresh) {
      P.push_back(x);
      centre.push_back(c);
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {-1, 1}) {
      Vec3 normal = Vec3::Zero();
      normal(axis) = side;
      Vec3 s = Vec3::Zero(), t = Vec3::Zero();
      s((axis + 1) % 3) = 1.0;
      t((axis + 2) % 3) = 1.0;
      if (side < 0) std::swap(s, t);  // s x t = normal: counter-clockwise seen from outside
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const auto at = [&](double a, double b) {
            return Vec3(normal + (2.0 * a / n - 1.0) * s + (2.0 * b / n - 1.0) * t);
          };
          const int a = id(at(i, j), false), b = id(at(i + 1, j), false),
                    c = id(at(i + 1, j + 1), false), d = id(at(i, j + 1), false);
          const int m = id(at(i + 0.5, j + 0.5), true);
          T.push_back({a, b, m});
          T.push_back({b, c, m});
          T.push_back({c, d, m});
          T.push_back({d, a, m});
        }
    }
  if (is_centre) *is_centre = centre;
  return mesh_of(P, T, "cube-with-centres");
}

/// The regular tetrahedron, outward faces.
inline Mesh tetrahedron() {
  return mesh_of({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}},
                 {{{0, 1, 2}}, {{0, 3, 1}}, {{0, 2, 3}}, {{1, 3, 2}}}, "tetrahedron");
}

/// The regular octahedron, outward faces.
inline Mesh octahedron() {
  return mesh_of({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
                 {{{0, 2, 4}},
                  {{2, 1, 4}},
                  {{1, 3, 4}},
                  {{3, 0, 4}},
                  {{2, 0, 5}},
                  {{1, 2, 5}},
                  {{3, 1, 5}},
                  {{0, 3, 5}}},
                 "octahedron");
}

/// An octahedron (apexes 0 and 5 on the y axis, the square 1-2-3-4 at y = 0) without two of the
/// faces at apex 5: vertex 5 keeps the faces 1-5-2 and 3-2-5, and its neighbours' normals turn
/// more than 90 degrees from its own. The mesh of Debian's CGAL data file hedra_open.off.
inline Mesh open_octahedron() {
  const double a = 1.686, b = 1.192;
  return mesh_of({{0, a, 0}, {b, 0, -b}, {-b, 0, -b}, {-b, 0, b}, {b, 0, b}, {0, -a, 0}},
                 {{{0, 4, 1}}, {{1, 5, 2}}, {{2, 3, 0}}, {{1, 2, 0}}, {{3, 4, 0}}, {{3, 2, 5}}},
                 "open octahedron");
}

/// `big` with a tetrahedron of edge ~0.1 beside it (a second, four-vertex component; its
/// vertices come last).
inline Mesh with_tiny_tetrahedron(const Mesh& big) {
  std::vector<Vec3> P;
  std::vector<std::array<int, 3>> T;
  for (int v = 0; v < big.num_vertices(); ++v) P.push_back(big.position(v));
  for (int f = 0; f < big.num_faces(); ++f)
    T.push_back({big.face_vertex(f, 0), big.face_vertex(f, 1), big.face_vertex(f, 2)});
  const Mesh tet = tetrahedron();
  const int base = static_cast<int>(P.size());
  for (int v = 0; v < 4; ++v) P.push_back(Vec3(5.0, 0.0, 0.0) + 0.05 * tet.position(v));
  for (int f = 0; f < 4; ++f)
    T.push_back(
        {base + tet.face_vertex(f, 0), base + tet.face_vertex(f, 1), base + tet.face_vertex(f, 2)});
  return mesh_of(P, T, "sphere-and-tetrahedron");
}

}  // namespace curvbench::testing
