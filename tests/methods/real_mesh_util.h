// Test meshes shaped like the meshes people have: small holes through the solid, thin
// handles, needle and cap triangles. Built here, never downloaded.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/types.h"
#include "mesh/mesh.h"
#include "mesh/rings.h"
#include "meshgen/marching_cubes.h"
#include "methods/fits/lscm_parameterization.h"

namespace curvbench::testing {

/// Torus of major radius R and minor radius r, nu x nv quads split into triangles, faces
/// counter-clockwise seen from outside. Vertex (i, j) = index j nu + i is at angle u = 2 pi i / nu
/// around the axis (z) and v = 2 pi j / nv around the tube (v = 0 on the outer equator).
inline Mesh torus_grid(double R, double r, int nu, int nv) {
  VertexMatrix V(nu * nv, 3);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2.0 * std::numbers::pi * i / nu, v = 2.0 * std::numbers::pi * j / nv;
      V.row(j * nu + i) << (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
          r * std::sin(v);
    }
  FaceMatrix F(2 * nu * nv, 3);
  int f = 0;
  const auto id = [nu, nv](int i, int j) { return (j % nv) * nu + (i % nu); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      F.row(f++) << id(i, j), id(i + 1, j), id(i + 1, j + 1);
      F.row(f++) << id(i, j), id(i + 1, j + 1), id(i, j + 1);
    }
  return Mesh(V, F, "torus");
}

/// Signed distance (negative inside) of a Swiss-cheese-like block: a box [-a, a] x [-b, b] x
/// [-c, c] with edges rounded by `round`, pierced along z by two cylinders of radius `hole` at
/// x = -/+ 0.45 a, y = 0 and along x by a thinner one at y = 0.35, z = 0.3 c that misses both:
/// genus 3.
inline double cheese_block_distance(double x, double y, double z) {
  const double a = 1.0, b = 0.6, c = 0.5, round = 0.15, hole = 0.08;
  const double qx = std::abs(x) - (a - round), qy = std::abs(y) - (b - round),
               qz = std::abs(z) - (c - round);
  const double outside = std::sqrt(std::pow(std::max(qx, 0.0), 2) + std::pow(std::max(qy, 0.0), 2) +
                                   std::pow(std::max(qz, 0.0), 2));
  const double box = outside + std::min(std::max({qx, qy, qz}), 0.0) - round;
  const double z_hole1 = std::hypot(x + 0.45 * a, y) - hole;
  const double z_hole2 = std::hypot(x - 0.45 * a, y) - hole;
  const double x_hole = std::hypot(z - 0.3 * c, y - 0.35) - 0.7 * hole;
  return std::max({box, -z_hole1, -z_hole2, -x_hole});
}

/// Marching cubes of cheese_block_distance on an n^3 grid slightly offset from the origin (so that
/// no sample is exactly on the surface): a closed genus-3 surface with small through-holes,
/// creases where the holes meet the faces, and the needle and cap triangles marching cubes makes.
inline Mesh cheese_block(int n) {
  const auto axis = [n](double lo, double hi) {
    std::vector<double> t(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) t[static_cast<size_t>(i)] = lo + (hi - lo) * i / (n - 1) + 0.0123;
    return t;
  };
  const std::vector<double> x = axis(-1.2, 1.2), y = axis(-0.8, 0.8), z = axis(-0.7, 0.7);
  const IsosurfaceMesh iso = marching_cubes(x, y, z, cheese_block_distance);
  return Mesh(iso.vertices, iso.faces, "cheese block");
}

/// Vertices whose r-ring is not a topological disk, i.e. is cut by the LSCM maps
/// (methods/fits/lscm_parameterization.h). Every ring must map.
inline int rings_cut(const Mesh& mesh, double ring) {
  RingCollector rc(mesh);
  LscmMap map(mesh);
  std::vector<Vec2> uv;
  int cut = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    rc.collect(v, ring);
    if (!map.map(v, rc.neighbours(), rc.faces(), uv)) return -1;
    cut += map.patch().cut();
  }
  return cut;
}

/// Smallest interior angle of face f, in degrees.
inline double smallest_angle_degrees(const Mesh& mesh, int f) {
  double smallest = 180.0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 p = mesh.position(mesh.face_vertex(f, k));
    const Vec3 e1 = mesh.position(mesh.face_vertex(f, (k + 1) % 3)) - p;
    const Vec3 e2 = mesh.position(mesh.face_vertex(f, (k + 2) % 3)) - p;
    smallest =
        std::min(smallest, std::atan2(e1.cross(e2).norm(), e1.dot(e2)) * 180.0 / std::numbers::pi);
  }
  return smallest;
}

}  // namespace curvbench::testing
