// The starting neighbourhoods of a whole mesh, gathered once and kept in compressed rows (CSR),
// so that several methods, degrees and repeated runs on the same mesh share them.
//
//   neighbour_offsets  (n+1)  int64   row v = neighbours[offsets[v] .. offsets[v+1])
//   neighbours         sum    int32   V_r \ {v} of vertex v, in RingCollector's discovery order
//   face_offsets       (n+1)  int64   |F_r| of vertex v = offsets[v+1] - offsets[v]
//   faces              sum    int32   (only with faces) F_r of v = faces[offsets[v] ..
//   offsets[v+1]) half_steps         n      uint16  2 r, r the ring actually reached (after
//   adaptive growth)
//
// Row v is exactly what RingCollector::collect(v, spec) leaves in neighbours(), faces() and
// ring() (docs/algorithms.md §1.2). Rows are gathered in parallel in fixed blocks of vertices,
// so the arrays are the same for any number of threads.
//
// NeighbourhoodCache keeps the tables of one mesh, one per NeighbourhoodSpec, built on first
// request. MeshEstimation (estimator.h) takes a cache; a ring-based method then reads its
// starting neighbourhoods from the table (Estimator::collect_neighbourhood) instead of collecting
// them per vertex, with bit-identical results.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/rings.h"
#include "points/point_search.h"

namespace curvbench {

class NeighbourhoodTable {
 public:
  /// Largest ring a table holds (half steps are stored in 16 bits).
  static constexpr double kMaxRing = 32767.0;

  /// Gathers the neighbourhood `spec` of every vertex with `threads` OpenMP threads (0 = the
  /// OpenMP default); with_faces: also the ring faces. Throws UsageError for a ring that
  /// RingCollector rejects or a ring (or max ring) above kMaxRing. A point spec (k-NN or ball,
  /// NeighbourhoodSpec::is_points) is gathered from the vertex positions alone (faces ignored,
  /// rows sorted by distance then index, coincident points left out: points/point_search.h),
  /// with ring 0; it has no faces (UsageError if with_faces).
  NeighbourhoodTable(const Mesh& mesh, const NeighbourhoodSpec& spec, bool with_faces, int threads);
  /// The same point neighbourhood (spec.is_points(), else std::invalid_argument) with a tree
  /// already built over the mesh's vertices; for knn=K, `nearest` may give knn_rows of the same
  /// points with K or more neighbours, whose first K are the rows (points/point_search.h: the same
  /// rows as a search of K).
  NeighbourhoodTable(const PointSearch& search, const NeighbourhoodSpec& spec, int threads,
                     const PointRows* nearest = nullptr);

  const NeighbourhoodSpec& spec() const { return spec_; }
  bool has_faces() const { return has_faces_; }
  int num_vertices() const { return static_cast<int>(half_steps_.size()); }

  /// V_r \ {v} in discovery order.
  std::span<const int> neighbours(int v) const {
    return {neighbours_.get() + nb_offsets_[static_cast<size_t>(v)],
            neighbours_.get() + nb_offsets_[static_cast<size_t>(v) + 1]};
  }
  /// F_r in discovery order; empty without faces.
  std::span<const int> faces(int v) const {
    if (!has_faces_) return {};
    return {faces_.get() + face_offsets_[static_cast<size_t>(v)],
            faces_.get() + face_offsets_[static_cast<size_t>(v) + 1]};
  }
  /// |F_r| (also without faces).
  size_t num_faces(int v) const {
    return static_cast<size_t>(face_offsets_[static_cast<size_t>(v) + 1] -
                               face_offsets_[static_cast<size_t>(v)]);
  }
  /// The ring actually reached at v.
  double ring(int v) const { return 0.5 * half_steps_[static_cast<size_t>(v)]; }

  /// Makes `rings` serve row v (RingCollector::assign).
  void assign(RingCollector& rings, int v) const {
    rings.assign(v, ring(v), neighbours(v), faces(v), num_faces(v));
  }

  /// The ball's radius of a radius spec (radius_spacing: resolved with the mean spacing); 0
  /// otherwise.
  double radius() const { return radius_; }

  /// Bytes held by the arrays.
  std::size_t bytes() const;

 private:
  void build_points(const PointSearch& search, int threads, const PointRows* nearest);

  NeighbourhoodSpec spec_;
  double radius_ = 0.0;
  bool has_faces_ = false;
  std::vector<std::int64_t> nb_offsets_;
  std::unique_ptr<int[]> neighbours_;
  std::size_t num_neighbours_ = 0;
  std::vector<std::int64_t> face_offsets_;
  std::unique_ptr<int[]> faces_;
  std::size_t num_faces_ = 0;
  std::vector<std::uint16_t> half_steps_;
};

/// The neighbourhood tables of one mesh, one per spec, built on first request. Safe to use from
/// several threads (a request waits while another builds). The mesh must outlive the cache.
class NeighbourhoodCache {
 public:
  explicit NeighbourhoodCache(const Mesh& mesh) : mesh_(&mesh) {}
  NeighbourhoodCache(const NeighbourhoodCache&) = delete;
  NeighbourhoodCache& operator=(const NeighbourhoodCache&) = delete;

  const Mesh& mesh() const { return *mesh_; }

  /// The table of `spec` (with faces if with_faces), built with `threads` threads if there is
  /// none yet. A table with faces also serves requests without; a request with faces replaces a
  /// table without (holders of the old one keep it alive). Null for a spec whose rings exceed
  /// NeighbourhoodTable::kMaxRing (the caller collects per vertex instead).
  std::shared_ptr<const NeighbourhoodTable> get(const NeighbourhoodSpec& spec, bool with_faces,
                                                int threads);

  /// Tables held and their bytes (NeighbourhoodTable::bytes).
  int num_tables() const;
  std::size_t bytes() const;

 private:
  const Mesh* mesh_;
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<const NeighbourhoodTable>> tables_;
};

}  // namespace curvbench
