// Estimator base-class helpers and the parallel per-vertex loop; see estimator.h.
#include <omp.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>

#include "core/errors.h"
#include "core/huge_pages.h"
#include "core/text.h"
#include "mesh/neighbourhood_table.h"
#include "mesh/rings.h"
#include "methods/estimator.h"
#include "methods/operators/vertex_normals.h"
#include "methods/option_schema.h"
#include "methods/vertex_result.h"
#include "points/point_normals.h"
#include "points/point_search.h"

namespace curvbench {

const char* to_string(VertexStatus status) {
  switch (status) {
    case VertexStatus::ok:
      return "ok";
    case VertexStatus::degree_reduced:
      return "degree_reduced";
    case VertexStatus::failed:
      return "failed";
    case VertexStatus::excluded:
      return "excluded";
    case VertexStatus::disk_cut:
      return "disk_cut";
    case VertexStatus::sign_undetermined:
      return "sign_undetermined";
    case VertexStatus::partial:
      return "partial";
    case VertexStatus::reprojected:
      return "reprojected";
    case VertexStatus::normal_fallback:
      return "normal_fallback";
  }
  return "unknown";
}

std::string Estimator::display_name() const {
  std::string s = name();
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

Estimator::Estimator(EstimatorOptions options) : options_(options) {
  validate_options(options_);
  if (options_.rings > 0.0 && options_.neighbourhood.kind != PointNeighbourhood::Kind::none)
    throw UsageError("rings and neighbourhood are two sizes of one neighbourhood: give one");
}

double Estimator::half_rings(double rings, const std::string& method) {
  const bool half_ring = rings >= 1.0 && std::abs(2.0 * rings - std::round(2.0 * rings)) < 1e-12;
  if (!(rings == 0.0 || half_ring))
    throw UsageError(method + ": ring " + format_g(rings) +
                     " is not supported (valid: 0 = default, or 1, 1.5, 2, 2.5, ...)");
  return rings == 0.0 ? 0.0 : 0.5 * std::round(2.0 * rings);
}

std::string Estimator::label() const {
  std::string s =
      takes_degree() ? display_name() + "-" + std::to_string(options_.degree) : display_name();
  // An operator fed a fit's normals says so: "ICC (LHF-3 normals)".
  if (options_.vertex_normals.fitted()) {
    s.append(" (").append(make_estimator(options_.vertex_normals.fit, {})->label());
    s.append(" normals)");
  }
  return s;
}

std::unique_ptr<MeshData> Estimator::prepare(const Mesh&, const VertexMatrix&, int) const {
  return nullptr;
}

double Estimator::default_ring() const {
  // Paper §5.1 / Table 2: (d+1)/2; noisy input (§5.3): half a ring more.
  return curvbench::default_ring(options_.degree) + (options_.noisy ? 0.5 : 0.0);
}

NeighbourhoodSpec Estimator::neighbourhood_spec() const {
  using Kind = PointNeighbourhood::Kind;
  using Points = NeighbourhoodSpec::Points;
  const PointNeighbourhood& p = options_.neighbourhood;
  if (p.kind != Kind::none)
    return NeighbourhoodSpec::point_rule(p.kind == Kind::knn      ? Points::knn
                                         : p.kind == Kind::radius ? Points::radius
                                                                  : Points::radius_spacing,
                                         p.size);
  const double r0 = options_.rings > 0.0 ? options_.rings : default_ring();
  return options_.adaptive
             ? NeighbourhoodSpec::at_least(r0, min_neighbours(options_.degree), 2.0 * r0)
             : NeighbourhoodSpec::fixed(r0);
}

int Estimator::default_knn() const {
  return std::max((options_.noisy ? 3 : 2) * num_coefficients(std::max(options_.degree, 1)),
                  regular_ring_size(default_ring()));
}

NeighbourhoodSpec Estimator::neighbourhood_spec(const Mesh& mesh) const {
  if (mesh.num_faces() == 0 && options_.neighbourhood.kind == PointNeighbourhood::Kind::none)
    return NeighbourhoodSpec::point_rule(NeighbourhoodSpec::Points::knn, default_knn());
  return neighbourhood_spec();
}

namespace {

// Every vertex's result goes through here or estimate_batch: a vertex that throws is failed (no
// exception may escape an OpenMP region; e.g. std::bad_alloc while a buffer grows, a CGAL
// precondition in a debug build).
void estimate_or_fail(const Estimator& estimator, const MeshContext& ctx, int v, Workspace& ws,
                      VertexEstimate& out) {
  try {
    estimator.estimate(ctx, v, ws, out);
  } catch (...) {
    set_failed(0.0, 0, out);
  }
}

}  // namespace

void Estimator::estimate_batch(const MeshContext& ctx, int first, int count, Workspace& ws,
                               VertexEstimate* out) const {
  for (int i = 0; i < count; ++i) estimate_or_fail(*this, ctx, first + i, ws, out[i]);
}

double Estimator::collect_neighbourhood(RingCollector& rings, int v) const {
  const NeighbourhoodSpec spec = neighbourhood_spec();
  rings.collect(v, spec);
  return spec.ring;
}

double Estimator::collect_neighbourhood(const MeshContext& ctx, RingCollector& rings, int v) const {
  const NeighbourhoodSpec spec = neighbourhood_spec(ctx.mesh);
  const NeighbourhoodTable* table = ctx.neighbourhoods;
  if (spec.is_points() && (table == nullptr || !(table->spec() == spec)))
    throw std::logic_error("collect_neighbourhood: the point neighbourhood's table is missing");
  if (table != nullptr && table->spec() == spec &&
      (table->has_faces() || neighbourhood_use() != NeighbourhoodUse::neighbours_and_faces))
    table->assign(rings, v);
  else
    rings.collect(v, spec);
  return spec.ring;
}

namespace {
int thread_count(const Estimator& estimator) {
  const int threads =
      estimator.options().threads > 0 ? estimator.options().threads : omp_get_max_threads();
  return threads < 1 ? 1 : threads;
}

}  // namespace

std::string point_set_methods() {
  std::string names;
  for (const std::string& name : estimator_names()) {
    try {
      if (make_estimator(name, {})->neighbourhood_use() == NeighbourhoodUse::neighbours)
        names += (names.empty() ? "" : ", ") + name;
    } catch (const UsageError&) {
    }
  }
  return names;
}

namespace {

// A point set (no faces) or a point neighbourhood (the option) needs a method that reads
// neighbours only: the others refuse with one line saying why.
void check_point_method(const Estimator& estimator, const Mesh& mesh) {
  if (estimator.neighbourhood_use() == NeighbourhoodUse::neighbours) return;
  const std::string why = estimator.neighbourhood_use() == NeighbourhoodUse::none
                              ? " works on a mesh's faces (its 1-ring or per-face quantities)"
                              : " parameterizes the faces of its rings";
  if (mesh.num_faces() == 0)
    throw UsageError(estimator.label() + why + ": a point set has no faces (methods for points: " +
                     point_set_methods() + ")");
  throw UsageError(estimator.label() + why + ": the neighbourhood option applies to " +
                   point_set_methods() + " only");
}

// The starting normals of a point set by the option point-normals (points/point_normals.h); a
// file's normals are checked to exist before the search (MeshEstimation).
PointNormals point_set_normals(const Mesh& mesh, const PointRows& nearest,
                               const Estimator& estimator, int threads) {
  const PointNormalSource source = estimator.options().point_normals;
  if (source == PointNormalSource::jet)
    return oriented_jet_normals(mesh.vertices(), nearest, threads);
  if (source == PointNormalSource::pca)
    return oriented_pca_normals(mesh.vertices(), nearest, threads);
  return given_point_normals(mesh.vertices(), nearest, mesh.given_normals(), threads);
}

}  // namespace

MeshEstimation::MeshEstimation(const Mesh& mesh, const Estimator& estimator,
                               NeighbourhoodCache* neighbourhoods)
    : mesh_(mesh),
      estimator_(estimator),
      normals_(estimator.uses_approx_normals() && mesh.num_faces() > 0
                   ? weighted_vertex_normals(mesh, VertexNormals::area, thread_count(estimator))
                   : VertexMatrix()) {
  if (neighbourhoods != nullptr && &neighbourhoods->mesh() != &mesh)
    throw std::invalid_argument("MeshEstimation: the neighbourhood cache is of another mesh");
  const int n = mesh.num_vertices();
  int threads = thread_count(estimator);
  const NeighbourhoodUse use = estimator.neighbourhood_use();
  const NeighbourhoodSpec spec = estimator.neighbourhood_spec(mesh);
  if (mesh.num_faces() > 0 && estimator.options().point_normals != PointNormalSource::pca)
    throw UsageError(
        "point-normals=" + option_text(estimator.options(), option_info("point-normals")) +
        " applies to point sets: " + mesh.source() +
        " has faces, whose area-weighted vertex normals start the fits");
  if (estimator.options().point_normals == PointNormalSource::file && !mesh.has_given_normals())
    throw InputError(mesh.source() +
                     ": point-normals=file, but the points come without normals (a .pwn file, an "
                     ".xyz file of 6 numbers per line, PLY with nx ny nz, or NOFF has them)");
  if (spec.is_points() || mesh.num_faces() == 0) {
    check_point_method(estimator, mesh);
    // One search (its grid, or its tree built on first use) serves the normals and the table;
    // of k-NN rows, one search of the larger k serves both (each takes the first k of every
    // row: the same rows as its own search).
    const PointSearch search(mesh.vertices());
    const int table_k = spec.points == NeighbourhoodSpec::Points::knn && spec.size >= 1.0 &&
                                spec.size < 1e9 && spec.size == std::floor(spec.size)
                            ? static_cast<int>(spec.size)
                            : 0;  // (the table refuses another size)
    PointRows nearest;
    int nearest_k = 0;
    if (mesh.num_faces() == 0 && n > 0) {
      // The normals of a point set (points/point_normals.h): the fits' frames and signs.
      nearest_k =
          neighbourhoods == nullptr ? std::max(kNormalNeighbours, table_k) : kNormalNeighbours;
      nearest = knn_rows(search, nearest_k, threads);
      PointNormals pn = point_set_normals(mesh, nearest, estimator, threads);
      normals_ = std::move(pn.normals);
      sign_undetermined_ = std::move(pn.undetermined);
    }
    // A point neighbourhood is always read from its table (it cannot be collected per vertex).
    if (neighbourhoods != nullptr)
      neighbourhoods_ = neighbourhoods->get(spec, false, threads);
    else
      neighbourhoods_ = std::make_shared<const NeighbourhoodTable>(
          search, spec, threads, table_k > 0 && nearest_k >= table_k ? &nearest : nullptr);
  } else if (neighbourhoods != nullptr && use != NeighbourhoodUse::none) {
    neighbourhoods_ =
        neighbourhoods->get(spec, use == NeighbourhoodUse::neighbours_and_faces, threads);
  }
  data_ = estimator.prepare(mesh, normals_, threads);
  if (threads > n) threads = n > 0 ? n : 1;
  threads_ = threads;
  // Each thread makes its own workspace (cache-line aligned, Workspace): its buffers then come
  // from that thread's allocator arena instead of lying next to another thread's, and its
  // scratch is zeroed in parallel (a two-thread pass at 1.44 million vertices: 156 ms instead of
  // 160). make_workspace may throw, and an exception must not escape an OpenMP region: the
  // first one is rethrown after it.
  workspaces_.resize(static_cast<size_t>(threads));
  std::vector<std::exception_ptr> errors(static_cast<size_t>(threads));
#pragma omp parallel for num_threads(threads) schedule(static, 1)
  for (int t = 0; t < threads; ++t) {
    try {
      workspaces_[static_cast<size_t>(t)] = estimator.make_workspace(mesh);
    } catch (...) {
      errors[static_cast<size_t>(t)] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

MeshEstimation::~MeshEstimation() = default;

void MeshEstimation::run(int first, std::span<VertexEstimate> out) {
  const long long last = static_cast<long long>(first) + static_cast<long long>(out.size());
  if (first < 0 || last > mesh_.num_vertices())
    throw std::out_of_range("MeshEstimation::run: vertex range outside the mesh");
  const MeshContext ctx{mesh_, normals_, data_.get(), neighbourhoods_.get()};
  const int count = static_cast<int>(out.size());
  const Estimator& estimator = estimator_;
  // Every vertex is computed independently from read-only data with its own thread's scratch
  // (a batch's lanes are independent too), so the result does not depend on the schedule, the
  // number of threads, the ranges or the split into batches.
  constexpr int kBlock = 64;  // vertices per estimate_batch call (a multiple of the SIMD batch)
  const int blocks = (count + kBlock - 1) / kBlock;
  // Threads take runs of up to 16 consecutive blocks (fewer on small ranges, so that every thread
  // gets work): handing out single blocks interleaves the threads' output and mesh regions and
  // contends for the schedule's counter (a two-thread pass at 1.44 million vertices took 181 ms
  // instead of 159).
  const int run_length = std::clamp(blocks / (8 * threads_), 1, 16);
#pragma omp parallel for num_threads(threads_) schedule(dynamic, run_length)
  for (int b = 0; b < blocks; ++b) {
    Workspace& ws = *workspaces_[static_cast<size_t>(omp_get_thread_num())];
    const int begin = b * kBlock;
    const int n = std::min(kBlock, count - begin);
    VertexEstimate* const o = out.data() + begin;
    try {
      estimator.estimate_batch(ctx, first + begin, n, ws, o);
    } catch (...) {
      for (int i = 0; i < n; ++i) estimate_or_fail(estimator, ctx, first + begin + i, ws, o[i]);
    }
  }
  // A point whose normal's sign is undecided (points/point_normals.h): its signs are arbitrary.
  if (!sign_undetermined_.empty())
    for (int i = 0; i < count; ++i) {
      VertexEstimate& o = out[static_cast<size_t>(i)];
      if (sign_undetermined_[static_cast<size_t>(first + i)] &&
          (o.status == VertexStatus::ok || o.status == VertexStatus::degree_reduced ||
           o.status == VertexStatus::reprojected))
        o.status = VertexStatus::sign_undetermined;
    }
}

std::vector<VertexEstimate> estimate_mesh(const Mesh& mesh, const Estimator& estimator,
                                          NeighbourhoodCache* neighbourhoods) {
  MeshEstimation run(mesh, estimator, neighbourhoods);
  const size_t n = static_cast<size_t>(mesh.num_vertices());
  std::vector<VertexEstimate> out;
  // 144 bytes per vertex (207 MB at 1.44 million vertices), value-initialised by one thread: on
  // huge pages, one first-touch fault per 2 MiB instead of per 4 KiB; and the pages are touched
  // first by all threads (the kernel zeroes each page at its first touch: 22% of a two-thread
  // run at 1.44 million vertices when one thread did it), so resize() only writes the values.
  reserve_huge(out, n);
  auto* const raw = reinterpret_cast<unsigned char*>(out.data());
  const std::ptrdiff_t bytes = static_cast<std::ptrdiff_t>(n * sizeof(VertexEstimate));
  constexpr std::ptrdiff_t kPage = 4096;
#pragma omp parallel for num_threads(thread_count(estimator)) schedule(static)
  for (std::ptrdiff_t at = 0; at < bytes; at += kPage) raw[at] = 0;
  out.resize(n);
  run.run(0, out);
  return out;
}

}  // namespace curvbench
