// Mesh defect counts (contract in mesh_checks.h).
#include "mesh/mesh_checks.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>
#include <vector>

namespace curvbench {

namespace {

/// Union-find with path halving and union by size; near-linear in the number of operations.
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(static_cast<size_t>(n)), size_(static_cast<size_t>(n), 1) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }

  int find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<int> parent_;
  std::vector<int> size_;
};

/// Distinct roots among the elements with flag set.
int count_roots(DisjointSets& sets, const std::vector<unsigned char>& flag) {
  int roots = 0;
  for (size_t i = 0; i < flag.size(); ++i)
    if (flag[i] && sets.find(static_cast<int>(i)) == static_cast<int>(i)) ++roots;
  return roots;
}

/// Position (0..2) of vertex v in face f; -1 if absent.
int corner_of(const Mesh& mesh, int f, int v) {
  for (int k = 0; k < 3; ++k)
    if (mesh.face_vertex(f, k) == v) return k;
  return -1;
}

}  // namespace

bool is_zero_area_face(const Mesh& mesh, int f) {
  const Vec3 a = mesh.position(mesh.face_vertex(f, 0));
  const Vec3 b = mesh.position(mesh.face_vertex(f, 1));
  const Vec3 c = mesh.position(mesh.face_vertex(f, 2));
  const double longest =
      std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return (b - a).cross(c - a).norm() <= kZeroAreaTolerance * longest;
}

int count_zero_area_faces(const Mesh& mesh) {
  int count = 0;
  for (int f = 0; f < mesh.num_faces(); ++f) count += is_zero_area_face(mesh, f);
  return count;
}

int count_duplicate_vertices(const Mesh& mesh) {
  const VertexMatrix& V = mesh.vertices();
  std::vector<int> order(static_cast<size_t>(mesh.num_vertices()));
  std::iota(order.begin(), order.end(), 0);
  const auto less = [&](int i, int j) {
    for (int c = 0; c < 3; ++c)
      if (V(i, c) != V(j, c)) return V(i, c) < V(j, c);
    return false;
  };
  std::sort(order.begin(), order.end(), less);
  int count = 0;
  for (size_t i = 1; i < order.size(); ++i)
    if (!less(order[i - 1], order[i])) ++count;  // sorted and not less: equal
  return count;
}

int count_duplicate_faces(const Mesh& mesh) {
  std::vector<std::array<int, 3>> keys(static_cast<size_t>(mesh.num_faces()));
  for (int f = 0; f < mesh.num_faces(); ++f) {
    auto& k = keys[static_cast<size_t>(f)];
    k = {mesh.face_vertex(f, 0), mesh.face_vertex(f, 1), mesh.face_vertex(f, 2)};
    std::sort(k.begin(), k.end());
  }
  std::sort(keys.begin(), keys.end());
  int count = 0;
  for (size_t i = 1; i < keys.size(); ++i)
    if (keys[i] == keys[i - 1]) ++count;
  return count;
}

std::vector<unsigned char> nonmanifold_vertex_flags(const Mesh& mesh) {
  // Corners 3f + k; join the two corners of each endpoint across every manifold edge.
  const int m = mesh.num_faces();
  DisjointSets corners(3 * m);
  for (int f = 0; f < m; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int g = mesh.face_neighbor(f, k);
      if (g < f) continue;  // boundary/non-manifold (-1), or handled from g
      for (const int kk : {k, (k + 1) % 3}) {
        const int l = corner_of(mesh, g, mesh.face_vertex(f, kk));
        if (l >= 0) corners.unite(3 * f + kk, 3 * g + l);
      }
    }
  }
  // A vertex is non-manifold when its corners fall into more than one set (fan).
  std::vector<int> seen(static_cast<size_t>(3) * m, -1);  // root -> last vertex that saw it
  std::vector<unsigned char> flags(static_cast<size_t>(mesh.num_vertices()), 0);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    int fans = 0;
    for (const int f : mesh.vertex_faces(v)) {
      const int root = corners.find(3 * f + corner_of(mesh, f, v));
      if (seen[root] != v) {
        seen[root] = v;
        ++fans;
      }
    }
    flags[static_cast<size_t>(v)] = fans > 1;
  }
  return flags;
}

int count_nonmanifold_vertices(const Mesh& mesh) {
  const std::vector<unsigned char> flags = nonmanifold_vertex_flags(mesh);
  return static_cast<int>(std::count(flags.begin(), flags.end(), 1));
}

std::vector<int> vertex_valences(const Mesh& mesh) {
  // Each undirected edge once, as (smaller, larger) vertex: its endpoints each gain a neighbour.
  std::vector<std::pair<int, int>> edges;
  edges.reserve(static_cast<size_t>(3 * mesh.num_faces()));
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.face_vertex(f, k), b = mesh.face_vertex(f, (k + 1) % 3);
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<int> valence(static_cast<size_t>(mesh.num_vertices()), 0);
  for (const auto& [a, b] : edges) {
    ++valence[static_cast<size_t>(a)];
    ++valence[static_cast<size_t>(b)];
  }
  return valence;
}

std::vector<int> valence_histogram(const Mesh& mesh) {
  std::vector<int> histogram;
  for (const int v : vertex_valences(mesh)) {
    if (static_cast<size_t>(v) >= histogram.size()) histogram.resize(static_cast<size_t>(v) + 1, 0);
    ++histogram[static_cast<size_t>(v)];
  }
  return histogram;
}

int count_components(const Mesh& mesh) {
  DisjointSets sets(mesh.num_vertices());
  std::vector<unsigned char> used(static_cast<size_t>(mesh.num_vertices()), 0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) used[mesh.face_vertex(f, k)] = 1;
    sets.unite(mesh.face_vertex(f, 0), mesh.face_vertex(f, 1));
    sets.unite(mesh.face_vertex(f, 0), mesh.face_vertex(f, 2));
  }
  return count_roots(sets, used);
}

int count_boundary_loops(const Mesh& mesh) {
  if (!mesh.has_boundary()) return 0;
  DisjointSets sets(mesh.num_vertices());
  std::vector<unsigned char> on_boundary(static_cast<size_t>(mesh.num_vertices()), 0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) {
      if (!mesh.is_boundary_edge(f, k)) continue;
      const int a = mesh.face_vertex(f, k), b = mesh.face_vertex(f, (k + 1) % 3);
      on_boundary[a] = on_boundary[b] = 1;
      sets.unite(a, b);
    }
  }
  return count_roots(sets, on_boundary);
}

MeshChecks check_mesh(const Mesh& mesh) {
  MeshChecks c;
  c.zero_area_faces = count_zero_area_faces(mesh);
  c.duplicate_vertices = count_duplicate_vertices(mesh);
  c.duplicate_faces = count_duplicate_faces(mesh);
  c.isolated_vertices = mesh.num_isolated_vertices();
  c.nonmanifold_edges = mesh.num_nonmanifold_edges();
  c.nonmanifold_vertices = count_nonmanifold_vertices(mesh);
  c.components = count_components(mesh);
  c.inconsistent_edges = mesh.num_inconsistent_edges();
  c.boundary_edges = mesh.num_boundary_edges();
  c.boundary_loops = count_boundary_loops(mesh);
  return c;
}

const char* to_string(VertexDefect defect) {
  switch (defect) {
    case VertexDefect::none:
      return "none";
    case VertexDefect::isolated:
      return "isolated vertex";
    case VertexDefect::small_component:
      return "component of fewer than 7 vertices";
    case VertexDefect::nonmanifold:
      return "non-manifold neighbourhood";
    case VertexDefect::zero_area_star:
      return "zero-area faces only";
    case VertexDefect::boundary:
      return "boundary vertex";
  }
  return "unknown";
}

std::vector<VertexDefect> vertex_defects(const Mesh& mesh) {
  const int n = mesh.num_vertices();
  DisjointSets sets(n);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    sets.unite(mesh.face_vertex(f, 0), mesh.face_vertex(f, 1));
    sets.unite(mesh.face_vertex(f, 0), mesh.face_vertex(f, 2));
  }
  std::vector<int> component_size(static_cast<size_t>(n), 0);
  for (int v = 0; v < n; ++v) ++component_size[static_cast<size_t>(sets.find(v))];
  const std::vector<unsigned char> nonmanifold = nonmanifold_vertex_flags(mesh);
  std::vector<VertexDefect> out(static_cast<size_t>(n), VertexDefect::none);
  for (int v = 0; v < n; ++v) {
    const auto faces = mesh.vertex_faces(v);
    VertexDefect& d = out[static_cast<size_t>(v)];
    if (faces.empty())
      d = VertexDefect::isolated;
    else if (component_size[static_cast<size_t>(sets.find(v))] < kSmallComponent)
      d = VertexDefect::small_component;
    else if (nonmanifold[static_cast<size_t>(v)])
      d = VertexDefect::nonmanifold;
    else if (std::all_of(faces.begin(), faces.end(),
                         [&](int f) { return is_zero_area_face(mesh, f); }))
      d = VertexDefect::zero_area_star;
    else if (mesh.is_boundary_vertex(v))
      d = VertexDefect::boundary;
  }
  return out;
}

}  // namespace curvbench
