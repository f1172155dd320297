// The soup step of the mesh readers (read_soup.h): a reader's polygon soup becomes a Mesh.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "mesh/io.h"
#include "mesh/read_soup.h"

namespace curvbench {
namespace io_detail {

namespace {

/// True if the k-gon p[0..k) names a vertex twice. O(k log k).
bool has_repeated_index(const std::int32_t* p, std::size_t k, std::vector<std::int32_t>& scratch) {
  if (k == 3) return p[0] == p[1] || p[1] == p[2] || p[0] == p[2];
  scratch.assign(p, p + k);
  std::sort(scratch.begin(), scratch.end());
  return std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end();
}

}  // namespace

/// Builds the Mesh from a reader's soup: drops polygons with fewer than 3 vertices or a repeated
/// index; refuses non-finite coordinates or, with skip_invalid, drops those vertices and the
/// polygons using them and renumbers; fan-triangulates (v0, vi, vi+1) the rest; hands the
/// file's normals (of the kept vertices) of a point set to the Mesh (Mesh::given_normals()).
/// Takes the soup by value and frees it before the Mesh builds its adjacency (peak memory). The
/// usual file (triangles, every vertex finite) becomes the Mesh without a copy.
Mesh soup_to_mesh(const std::string& path, const std::string& format, Soup soup,
                  MeshReadReport* report) {
  const std::size_t n = soup.num_vertices();
  const std::size_t num_polygons = soup.num_polygons();
  if (n == 0) fail(path, "empty mesh: no vertices");
  if (n > kMaxCount) fail(path, "too many vertices");
  const double* xyz = soup.xyz.data();

  // Vertices to skip: non-finite tokens seen by the text readers and non-finite values decoded
  // from binary PLY (or made by a homogeneous OFF division). `skip` is made on the first one.
  std::vector<unsigned char> skip;
  if (!soup.nonfinite.empty()) {
    skip.assign(n, 0);
    for (const unsigned long long v : soup.nonfinite) skip[v] = 1;
  }
  std::vector<int> skipped;
  for (std::size_t v = 0; v < n; ++v) {
    const double* q = xyz + 3 * v;
    if ((skip.empty() || !skip[v]) && std::isfinite(q[0]) && std::isfinite(q[1]) &&
        std::isfinite(q[2]))
      continue;
    if (!soup.skip_invalid) {
      std::ostringstream msg;
      msg << "vertex " << v << " has a non-finite coordinate (" << q[0] << ", " << q[1] << ", "
          << q[2] << ")" << kSkipHint;
      fail(path, msg.str());
    }
    if (skip.empty()) skip.assign(n, 0);
    skip[v] = 1;
    skipped.push_back(static_cast<int>(v));
  }
  // New index of each kept vertex (file order).
  std::vector<int> index;
  std::vector<int> source;
  int kept_vertices = static_cast<int>(n);
  if (!skipped.empty()) {
    index.assign(n, -1);
    kept_vertices = 0;
    for (std::size_t v = 0; v < n; ++v)
      if (!skip[v]) index[v] = kept_vertices++;
    if (kept_vertices == 0)
      fail(path, "empty mesh: all " + std::to_string(n) + " vertices have a non-finite coordinate");
    source.reserve(static_cast<std::size_t>(kept_vertices));
    for (std::size_t v = 0; v < n; ++v)
      if (!skip[v]) source.push_back(static_cast<int>(v));
  }
  const auto new_index = [&](std::int32_t v) { return index.empty() ? v : index[v]; };

  // Classify the polygons (the same test again when copying them, instead of a stored fate).
  enum Fate : unsigned char { kKeep, kFew, kSkipped, kRepeated };
  std::vector<std::int32_t> scratch;
  const auto fate = [&](const std::int32_t* p, std::size_t k) {
    // (Every index was checked by the reader: 0 <= p[i] < n.)
    if (k < 3) return kFew;
    if (!skipped.empty() && std::any_of(p, p + k, [&](std::int32_t i) { return skip[i] != 0; }))
      return kSkipped;
    if (has_repeated_index(p, k, scratch)) return kRepeated;
    return kKeep;
  };
  unsigned long long triangles = 0;
  int kept = 0, triangulated = 0, few = 0, repeated = 0, faces_skipped = 0;
  for (std::size_t f = 0; f < num_polygons; ++f) {
    const std::size_t k = soup.polygon_size(f);
    switch (fate(soup.indices.data() + soup.polygon_begin(f), k)) {
      case kFew:
        ++few;
        break;
      case kSkipped:
        ++faces_skipped;
        break;
      case kRepeated:
        ++repeated;
        break;
      case kKeep:
        ++kept;
        triangles += k - 2;
        if (k > 3) ++triangulated;
    }
  }
  if (triangles > kMaxCount) fail(path, "too many triangles after fan triangulation");
  if (kept == 0 && num_polygons > 0) {
    std::string why;
    for (const auto& [k, what] : {std::pair{few, "with fewer than 3 vertices"},
                                  std::pair{repeated, "with a repeated vertex index"},
                                  std::pair{faces_skipped, "using a NaN/Inf vertex"}})
      if (k > 0) why += (why.empty() ? "" : ", ") + std::to_string(k) + " " + what;
    fail(path, "empty mesh: no faces left after dropping all " + std::to_string(num_polygons) +
                   " (" + why + ")");
  }

  VertexMatrix V;
  if (skipped.empty()) {
    V = soup.xyz.take();
  } else {
    V.resize(kept_vertices, 3);
    for (std::size_t v = 0; v < n; ++v) {
      if (skip[v]) continue;
      const Eigen::Index r = new_index(static_cast<std::int32_t>(v));
      V(r, 0) = xyz[3 * v];
      V(r, 1) = xyz[3 * v + 1];
      V(r, 2) = xyz[3 * v + 2];
    }
  }
  soup.xyz.release();
  // The file's normals, of the kept vertices, of a point set only (a mesh's come from its faces;
  // point-normals=file applies to point sets).
  VertexMatrix N;
  if (num_polygons > 0) soup.normals.release();
  if (!soup.normals.empty()) {
    if (skipped.empty()) {
      N = soup.normals.take();
    } else {
      N.resize(kept_vertices, 3);
      for (std::size_t v = 0; v < n; ++v)
        if (!skip[v])
          for (int c = 0; c < 3; ++c)
            N(new_index(static_cast<std::int32_t>(v)), c) = soup.normals[3 * v + c];
    }
    soup.normals.release();
  }
  // Fan triangulation (v0, vi, vi+1) of each kept polygon.
  FaceMatrix F;
  if (soup.all_triangles() && static_cast<std::size_t>(kept) == num_polygons && index.empty()) {
    F = soup.indices.take();
  } else {
    F.resize(static_cast<Eigen::Index>(triangles), 3);
    advise_huge_pages(F.data(), sizeof(int) * static_cast<std::size_t>(F.size()));
    Eigen::Index t = 0;
    for (std::size_t f = 0; f < num_polygons; ++f) {
      const std::int32_t* p = soup.indices.data() + soup.polygon_begin(f);
      const std::size_t k = soup.polygon_size(f);
      if (fate(p, k) != kKeep) continue;
      for (std::size_t i = 1; i + 1 < k; ++i, ++t) {
        F(t, 0) = new_index(p[0]);
        F(t, 1) = new_index(p[i]);
        F(t, 2) = new_index(p[i + 1]);
      }
    }
  }
  soup.indices.release();
  std::vector<std::size_t>().swap(soup.starts);

  Mesh mesh(std::move(V), std::move(F), path);
  mesh.set_given_normals(std::move(N));
  if (report != nullptr) {
    *report = MeshReadReport{};
    report->format = format;
    report->polygons_read = kept;
    report->polygons_triangulated = triangulated;
    report->triangles = static_cast<int>(triangles);
    report->faces_with_few_vertices = few;
    report->faces_with_repeated_index = repeated;
    report->vertices_in_file = static_cast<int>(n);
    report->vertices_skipped = static_cast<int>(skipped.size());
    report->faces_skipped = faces_skipped;
    report->skipped_vertices = std::move(skipped);
    report->source_vertex = std::move(source);
  }
  return mesh;
}

}  // namespace io_detail
}  // namespace curvbench
