// Consistent face orientation; see orientation.h.
#include "mesh/orientation.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/huge_pages.h"

namespace curvbench {

namespace {

// Position of edge (a, b) in face f as k with F(f,k) = a, F(f,k+1) = b (+1: same direction), or
// with F(f,k) = b, F(f,k+1) = a (-1: opposite); 0 if f has no such edge.
int edge_direction(const FaceMatrix& F, int f, int a, int b) {
  for (int k = 0; k < 3; ++k) {
    const int x = F(f, k), y = F(f, (k + 1) % 3);
    if (x == a && y == b) return 1;
    if (x == b && y == a) return -1;
  }
  return 0;
}

}  // namespace

namespace {

/// The patches of a consistently oriented mesh (Mesh::is_consistently_oriented, checked while
/// the adjacency was built): no walk, and nothing to repair. One pass over the edges joins the
/// faces across each manifold edge (union-find over face indices, a root always the lowest face of
/// its set), one pass over the faces numbers the patches in the order of their lowest face (the
/// walk's order) and sums each patch's signed volume; a closed patch of negative volume is
/// reversed as a whole, an open one kept (the walk would flip none of its faces). patch[f]: the
/// patch of face f.
void consistent_patches(const Mesh& mesh, std::vector<int>& patch, std::vector<unsigned char>& flip,
                        OrientationResult& out) {
  const int m = mesh.num_faces();
  const FaceMatrix& F = mesh.faces();
  patch.resize(static_cast<size_t>(m));
  int* parent = patch.data();
  const auto find = [parent](int f) {
    while (parent[f] != f) {
      parent[f] = parent[parent[f]];  // path halving: parents only ever point down
      f = parent[f];
    }
    return f;
  };
  // The same pass sums the signed volume and notes a face at a boundary or non-manifold edge:
  // with a single patch (the usual mesh) that is all there is to know.
  int joined = 0;
  double total = 0.0;
  bool open = false;
  for (int f = 0; f < m; ++f) {
    int root = f;  // of f's set so far
    parent[f] = f;
    for (int k = 0; k < 3; ++k) {
      const int g = mesh.face_neighbor(f, k);
      open = open || g < 0;
      if (g < 0 || g >= f) continue;  // each manifold edge once, from its higher face
      const int a = find(g);
      if (a < root) {
        parent[root] = a;
        root = a;
        ++joined;
      } else if (root < a) {
        parent[a] = root;
        ++joined;
      }
    }
    const Vec3 a = mesh.position(F(f, 0)), b = mesh.position(F(f, 1)), c = mesh.position(F(f, 2));
    total += a.dot(b.cross(c));
  }
  if (m - joined == 1) {
    out.patches = 1;
    if (!open) {
      ++out.closed_patches;
      if (total < 0.0) std::fill(flip.begin(), flip.end(), 1);
    }
    std::fill(parent, parent + m, 0);
    return;
  }
  // Patch ids in increasing lowest face, stored as ~id (negative) while the pass runs: a face
  // whose parent is below it takes its parent's id, already final.
  std::vector<char> closed;
  std::vector<double> volume;
  for (int f = 0; f < m; ++f) {
    const int p = parent[f];
    int id;
    if (p == f) {
      id = out.patches++;
      closed.push_back(1);
      volume.push_back(0.0);
    } else {
      id = ~parent[p];
    }
    parent[f] = ~id;
    const Vec3 a = mesh.position(F(f, 0)), b = mesh.position(F(f, 1)), c = mesh.position(F(f, 2));
    volume[static_cast<size_t>(id)] += a.dot(b.cross(c));
    if (mesh.face_neighbor(f, 0) < 0 || mesh.face_neighbor(f, 1) < 0 ||
        mesh.face_neighbor(f, 2) < 0)
      closed[static_cast<size_t>(id)] = 0;
  }
  bool any_reversed = false;
  std::vector<char> reverse(static_cast<size_t>(out.patches), 0);
  for (int id = 0; id < out.patches; ++id) {
    if (!closed[static_cast<size_t>(id)]) continue;
    ++out.closed_patches;
    if (volume[static_cast<size_t>(id)] < 0.0) {
      reverse[static_cast<size_t>(id)] = 1;
      any_reversed = true;
    }
  }
  for (int f = 0; f < m; ++f) {
    parent[f] = ~parent[f];
    if (any_reversed) flip[static_cast<size_t>(f)] = reverse[static_cast<size_t>(parent[f])];
  }
}

/// The breadth-first walk of every patch (see orientation.h), for a mesh with an inconsistent
/// edge. patch[f]: the patch of face f.
void walk_patches(const Mesh& mesh, std::vector<int>& patch, std::vector<unsigned char>& flip,
                  OrientationResult& out) {
  const int m = mesh.num_faces();
  const FaceMatrix& F = mesh.faces();
  // queue: the faces of the current patch in the order the walk reached them (all of them once
  // the walk is done).
  patch.assign(static_cast<size_t>(m), -1);
  std::vector<int> queue;
  reserve_huge(queue, static_cast<size_t>(m));
  for (int seed = 0; seed < m; ++seed) {
    if (patch[static_cast<size_t>(seed)] >= 0) continue;
    const int id = out.patches++;
    queue.assign(1, seed);
    patch[static_cast<size_t>(seed)] = id;
    bool orientable = true, closed = true;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      for (int k = 0; k < 3; ++k) {
        const int g = mesh.face_neighbor(f, k);
        if (g < 0) {
          closed = false;
          continue;
        }
        // f runs its edge k from a to b (in its new orientation); g must run it from b to a.
        int a = F(f, k), b = F(f, (k + 1) % 3);
        if (flip[static_cast<size_t>(f)]) std::swap(a, b);
        const unsigned char want = edge_direction(F, g, a, b) == 1 ? 1 : 0;  // in g's input
        if (patch[static_cast<size_t>(g)] < 0) {
          patch[static_cast<size_t>(g)] = id;
          flip[static_cast<size_t>(g)] = want;
          queue.push_back(g);
        } else if (flip[static_cast<size_t>(g)] != want) {
          orientable = false;  // g was reached the other way round: a seam
        }
      }
    }
    if (!orientable) {
      ++out.nonorientable_patches;
      for (int f : queue)
        for (int k = 0; k < 3; ++k) out.sign_undetermined[static_cast<size_t>(F(f, k))] = 1;
      continue;
    }
    // Choose between the walk's orientation and its reverse.
    bool reverse;
    if (closed) {
      ++out.closed_patches;
      double volume = 0.0;
      for (int f : queue) {
        const Vec3 a = mesh.position(F(f, 0)), b = mesh.position(F(f, 1)),
                   c = mesh.position(F(f, 2));
        const double v = a.dot(b.cross(c));
        volume += flip[static_cast<size_t>(f)] ? -v : v;
      }
      reverse = volume < 0.0;
    } else {
      int flipped = 0;
      for (int f : queue) flipped += flip[static_cast<size_t>(f)];
      reverse = 2 * flipped > static_cast<int>(queue.size());
    }
    if (reverse)
      for (int f : queue) flip[static_cast<size_t>(f)] ^= 1;
  }
}

/// Everything but the reoriented mesh, and the faces to reverse.
OrientationResult orientation_of(const Mesh& mesh, std::vector<unsigned char>& flip) {
  const int n = mesh.num_vertices();
  const int m = mesh.num_faces();
  const FaceMatrix& F = mesh.faces();
  OrientationResult out;
  out.sign_undetermined.assign(static_cast<size_t>(n), 0);

  // flip[f]: reverse face f relative to the input. patch[f]: patch index.
  reserve_huge(flip, static_cast<size_t>(m));
  flip.assign(static_cast<size_t>(m), 0);
  std::vector<int> patch;
  reserve_huge(patch, static_cast<size_t>(m));
  if (mesh.is_consistently_oriented())
    consistent_patches(mesh, patch, flip, out);
  else
    walk_patches(mesh, patch, flip, out);

  // Vertices whose faces lie in several patches (none with a single patch) or that end a
  // non-manifold edge.
  for (int v = 0; v < (out.patches > 1 ? n : 0); ++v) {
    const auto faces = mesh.vertex_faces(v);
    if (faces.empty()) continue;
    const int first = patch[static_cast<size_t>(faces[0])];
    for (int f : faces)
      if (patch[static_cast<size_t>(f)] != first) {
        out.sign_undetermined[static_cast<size_t>(v)] = 1;
        break;
      }
  }
  if (mesh.num_nonmanifold_edges() > 0)
    for (int f = 0; f < m; ++f)
      for (int k = 0; k < 3; ++k)
        if (mesh.is_nonmanifold_edge(f, k)) {
          out.sign_undetermined[static_cast<size_t>(F(f, k))] = 1;
          out.sign_undetermined[static_cast<size_t>(F(f, (k + 1) % 3))] = 1;
        }
  for (unsigned char u : out.sign_undetermined) out.vertices_undetermined += u;
  for (unsigned char u : flip) out.faces_flipped += u;
  return out;
}

}  // namespace

OrientationResult orient_mesh(Mesh&& mesh) {
  std::vector<unsigned char> flip;
  OrientationResult out = orientation_of(mesh, flip);
  // Flip, then rotate each face to start at its smallest vertex index: the same triangle with
  // the same orientation then has the same row whatever corner the input started at. In place:
  // a mesh that is already so (the usual case) is not touched at all.
  out.mesh = std::move(mesh);
  out.mesh.reorient_faces(flip);
  return out;
}

OrientationResult orient_mesh(const Mesh& mesh) {
  std::vector<unsigned char> flip;
  OrientationResult out = orientation_of(mesh, flip);
  out.mesh = mesh;
  out.mesh.reorient_faces(flip);
  return out;
}

std::vector<std::string> orientation_warnings(const OrientationResult& r) {
  std::vector<std::string> out;
  const int m = r.mesh.num_faces();
  if (r.faces_flipped > 0)
    out.push_back("reoriented " + std::to_string(r.faces_flipped) + " of " + std::to_string(m) +
                  " faces (consistent orientation, closed parts outward; vertex numbering kept)");
  if (r.vertices_undetermined > 0)
    out.push_back(std::to_string(r.vertices_undetermined) + " vertices are on a non-orientable (" +
                  std::to_string(r.nonorientable_patches) +
                  " patches) or non-manifold part: status sign_undetermined");
  return out;
}

}  // namespace curvbench
