// Estimator base-class helpers and the parallel per-vertex loop; see estimator.h.
#include <omp.h>

#include <cctype>
#include <string>

#include "mesh/rings.h"
#include "methods/estimator.h"
#include "methods/vertex_result.h"

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
  }
  return "unknown";
}

std::string Estimator::display_name() const {
  std::string s = name();
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string Estimator::label() const {
  if (!takes_degree()) return display_name();
  return display_name() + "-" + std::to_string(options_.degree);
}

std::unique_ptr<MeshData> Estimator::prepare(const Mesh&, const VertexMatrix&, int) const {
  return nullptr;
}

double Estimator::default_ring() const {
  // Paper §5.1 / Table 2: (d+1)/2; noisy input (§5.3): half a ring more.
  return curvbench::default_ring(options_.degree) + (options_.noisy ? 0.5 : 0.0);
}

double Estimator::collect_neighbourhood(RingCollector& rings, int v) const {
  const double r0 = options_.ring > 0.0 ? options_.ring : default_ring();
  if (options_.adaptive)
    rings.collect_at_least(v, r0, min_neighbours(options_.degree), 2.0 * r0);
  else
    rings.collect(v, r0);
  return r0;
}

std::vector<VertexEstimate> estimate_mesh(const Mesh& mesh, const Estimator& estimator) {
  const VertexMatrix normals = mesh.area_weighted_normals();
  const int n = mesh.num_vertices();
  std::vector<VertexEstimate> out(static_cast<size_t>(n));
  int threads =
      estimator.options().threads > 0 ? estimator.options().threads : omp_get_max_threads();
  if (threads < 1) threads = 1;
  const std::unique_ptr<MeshData> data = estimator.prepare(mesh, normals, threads);
  const MeshContext ctx{mesh, normals, data.get()};
  if (threads > n) threads = n > 0 ? n : 1;
  // Workspaces are made before the parallel region: make_workspace may allocate and throw, and
  // an exception must not escape an OpenMP region.
  std::vector<std::unique_ptr<Workspace>> workspaces;
  workspaces.reserve(static_cast<size_t>(threads));
  for (int t = 0; t < threads; ++t) workspaces.push_back(estimator.make_workspace(mesh));
    // Every vertex is computed independently from read-only data with its own thread's scratch,
    // so the result does not depend on the schedule or the number of threads.
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
  for (int v = 0; v < n; ++v) {
    Workspace& ws = *workspaces[static_cast<size_t>(omp_get_thread_num())];
    VertexEstimate& o = out[static_cast<size_t>(v)];
    // The one place a per-vertex exception is caught (e.g. std::bad_alloc while a buffer grows,
    // a CGAL precondition in a debug build): no exception may escape an OpenMP region.
    try {
      estimator.estimate(ctx, v, ws, o);
    } catch (...) {
      set_failed(0.0, 0, o);
    }
  }
  return out;
}

}  // namespace curvbench
