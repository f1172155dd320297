// Neighbourhood tables of a whole mesh; see neighbourhood_table.h.
#include "mesh/neighbourhood_table.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

#include "core/errors.h"
#include "core/text.h"

namespace curvbench {

namespace {

// Vertices per block of the parallel gather: each block is gathered by one thread into its own
// buffer, then copied to its place in the rows. Fixed, so the rows do not depend on the threads.
constexpr int kBlock = 1024;

void check_ring(double ring, const char* what) {
  if (!(ring >= 1.0) || ring > NeighbourhoodTable::kMaxRing ||
      std::abs(2.0 * ring - std::round(2.0 * ring)) > 1e-9)
    throw UsageError(std::string("neighbourhood table: ") + what + " " + format_g(ring) +
                     " is not one of 1, 1.5, 2, ... up to " +
                     format_g(NeighbourhoodTable::kMaxRing));
}

struct Block {
  std::vector<int> neighbours;
  std::vector<int> faces;
};

}  // namespace

NeighbourhoodTable::NeighbourhoodTable(const Mesh& mesh, const NeighbourhoodSpec& spec,
                                       bool with_faces, int threads)
    : spec_(spec), has_faces_(with_faces) {
  if (spec.is_points()) {
    if (with_faces)
      throw UsageError("neighbourhood table: a k-NN or ball neighbourhood has no faces");
    build_points(PointSearch(mesh.vertices()), threads, nullptr);
    return;
  }
  check_ring(spec.ring, "ring");
  if (spec.adaptive) check_ring(spec.max_ring, "max ring");
  const int n = mesh.num_vertices();
  if (threads <= 0) threads = omp_get_max_threads();
  threads = std::max(1, threads);
  const int blocks = (n + kBlock - 1) / kBlock;
  threads = std::max(1, std::min(threads, blocks));

  half_steps_.resize(static_cast<size_t>(n));
  nb_offsets_.assign(static_cast<size_t>(n) + 1, 0);
  face_offsets_.assign(static_cast<size_t>(n) + 1, 0);
  std::vector<Block> gathered(static_cast<size_t>(blocks));
  // Collectors and buffers are made before the parallel region: an exception must not escape it.
  std::vector<RingCollector> rings;
  rings.reserve(static_cast<size_t>(threads));
  for (int t = 0; t < threads; ++t) rings.emplace_back(mesh);

  // Pass 1: each block's rows into its own buffers; offsets[v + 1] = the row length of v.
  std::exception_ptr error;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
  for (int b = 0; b < blocks; ++b) {
    RingCollector& rc = rings[static_cast<size_t>(omp_get_thread_num())];
    Block& out = gathered[static_cast<size_t>(b)];
    try {
      const int end = std::min(n, (b + 1) * kBlock);
      for (int v = b * kBlock; v < end; ++v) {
        const double r = rc.collect(v, spec);
        half_steps_[static_cast<size_t>(v)] = static_cast<std::uint16_t>(std::lround(2.0 * r));
        const auto nb = rc.neighbours();
        out.neighbours.insert(out.neighbours.end(), nb.begin(), nb.end());
        nb_offsets_[static_cast<size_t>(v) + 1] = static_cast<std::int64_t>(nb.size());
        const auto f = rc.faces();
        if (with_faces) out.faces.insert(out.faces.end(), f.begin(), f.end());
        face_offsets_[static_cast<size_t>(v) + 1] = static_cast<std::int64_t>(f.size());
      }
    } catch (...) {  // e.g. std::bad_alloc
#pragma omp critical(neighbourhood_table_error)
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);

  // Row lengths -> offsets (a sequential prefix sum: cheap next to the gather).
  for (size_t v = 0; v < static_cast<size_t>(n); ++v) {
    nb_offsets_[v + 1] += nb_offsets_[v];
    face_offsets_[v + 1] += face_offsets_[v];
  }
  num_neighbours_ = static_cast<size_t>(nb_offsets_.back());
  neighbours_ = std::make_unique_for_overwrite<int[]>(num_neighbours_);
  if (with_faces) {
    num_faces_ = static_cast<size_t>(face_offsets_.back());
    faces_ = std::make_unique_for_overwrite<int[]>(num_faces_);
  }

  // Pass 2: the blocks into place (in parallel, so each thread also first-touches its pages).
#pragma omp parallel for num_threads(threads) schedule(static)
  for (int b = 0; b < blocks; ++b) {
    Block& in = gathered[static_cast<size_t>(b)];
    const size_t first = static_cast<size_t>(b) * kBlock;
    if (!in.neighbours.empty())
      std::memcpy(neighbours_.get() + nb_offsets_[first], in.neighbours.data(),
                  in.neighbours.size() * sizeof(int));
    if (with_faces && !in.faces.empty())
      std::memcpy(faces_.get() + face_offsets_[first], in.faces.data(),
                  in.faces.size() * sizeof(int));
    std::vector<int>().swap(in.neighbours);
    std::vector<int>().swap(in.faces);
  }
}

NeighbourhoodTable::NeighbourhoodTable(const PointSearch& search, const NeighbourhoodSpec& spec,
                                       int threads, const PointRows* nearest)
    : spec_(spec), has_faces_(false) {
  if (!spec.is_points())
    throw std::invalid_argument("NeighbourhoodTable: a tree serves a point neighbourhood only");
  build_points(search, threads, nearest);
}

void NeighbourhoodTable::build_points(const PointSearch& search, int threads,
                                      const PointRows* nearest) {
  using Points = NeighbourhoodSpec::Points;
  if (spec_.points == Points::knn &&
      !(spec_.size >= 1.0 && spec_.size == std::floor(spec_.size) && spec_.size < 1e9))
    throw UsageError("neighbourhood table: knn=" + format_g(spec_.size) +
                     " is not a whole number of neighbours >= 1");
  if (spec_.points != Points::knn && !(spec_.size > 0.0 && std::isfinite(spec_.size)))
    throw UsageError("neighbourhood table: radius " + format_g(spec_.size) + " is not positive");
  PointRows rows;
  if (spec_.points == Points::knn) {
    const int k = static_cast<int>(spec_.size);
    rows = nearest != nullptr ? first_of_rows(*nearest, k) : knn_rows(search, k, threads);
  } else {
    radius_ = spec_.size;
    if (spec_.points == Points::radius_spacing) radius_ *= mean_spacing(search, threads);
    rows = ball_rows(search, radius_, threads);
  }
  const size_t n = static_cast<size_t>(search.num_points());
  half_steps_.assign(n, 0);
  nb_offsets_ = std::move(rows.offsets);
  face_offsets_.assign(n + 1, 0);
  num_neighbours_ = rows.neighbours.size();
  neighbours_ = std::make_unique_for_overwrite<int[]>(num_neighbours_);
  std::copy(rows.neighbours.begin(), rows.neighbours.end(), neighbours_.get());
}

std::size_t NeighbourhoodTable::bytes() const {
  return (nb_offsets_.size() + face_offsets_.size()) * sizeof(std::int64_t) +
         (num_neighbours_ + num_faces_) * sizeof(int) + half_steps_.size() * sizeof(std::uint16_t);
}

std::shared_ptr<const NeighbourhoodTable> NeighbourhoodCache::get(const NeighbourhoodSpec& spec,
                                                                  bool with_faces, int threads) {
  if (std::max(spec.ring, spec.adaptive ? spec.max_ring : 0.0) > NeighbourhoodTable::kMaxRing)
    return nullptr;
  const std::lock_guard<std::mutex> lock(mutex_);
  auto it = std::find_if(tables_.begin(), tables_.end(),
                         [&](const auto& t) { return t->spec() == spec; });
  if (it != tables_.end() && ((*it)->has_faces() || !with_faces)) return *it;
  auto table = std::make_shared<const NeighbourhoodTable>(*mesh_, spec, with_faces, threads);
  if (it != tables_.end())
    *it = table;  // a table with faces replaces the one without
  else
    tables_.push_back(table);
  return table;
}

int NeighbourhoodCache::num_tables() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<int>(tables_.size());
}

std::size_t NeighbourhoodCache::bytes() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::size_t total = 0;
  for (const auto& t : tables_) total += t->bytes();
  return total;
}

}  // namespace curvbench
