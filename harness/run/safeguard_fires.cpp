// Where the safeguard's condition test fires; see safeguard_fires.h.
#include "harness/run/safeguard_fires.h"

#include <algorithm>
#include <cstdio>

#include "core/build_info.h"
#include "core/errors.h"
#include "harness/model/results_table.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"
#include "methods/fits/ring_fit_estimator.h"
#include "methods/option_schema.h"

namespace curvbench {

std::vector<SafeguardFire> safeguard_fires(const std::vector<SafeguardFireCase>& cases) {
  std::vector<SafeguardFire> out;
  for (const SafeguardFireCase& c : cases)
    for (int level : c.levels) {
      MeshSpec spec;
      spec.family = c.family;
      spec.level = level;
      const Mesh mesh = generate_mesh(spec).mesh;
      const VertexMatrix normals = mesh.area_weighted_normals();
      const MeshContext ctx{mesh, normals};
      for (const std::string& line : c.methods) {
        // "lhf-4 rings=3.5": the method and its options (option_schema.h names).
        const size_t space = line.find(' ');
        const std::string method = line.substr(0, space);
        const std::string rest = space == std::string::npos ? "" : line.substr(space + 1);
        EstimatorOptions options;
        for (size_t at = 0; at < rest.size();) {
          const size_t end = std::min(rest.find(' ', at), rest.size());
          const std::string kv = rest.substr(at, end - at);
          const size_t eq = kv.find('=');
          if (eq == std::string::npos) throw UsageError("safeguard-fires: expected key=value");
          set_option(options, kv.substr(0, eq), kv.substr(eq + 1));
          at = end + 1;
        }
        EstimatorOptions rjj = options;
        rjj.qr_condition = false;
        const auto est = make_estimator(method, options);
        const auto* fit = dynamic_cast<const RingFitEstimator*>(est.get());
        if (!fit) throw UsageError("safeguard-fires: '" + method + "' is not a ring fit");
        const std::vector<VertexEstimate> with = estimate_mesh(mesh, *est);
        const std::vector<VertexEstimate> without =
            estimate_mesh(mesh, *make_estimator(method, rjj));
        const auto ws = fit->make_workspace(mesh);
        RingFitEstimator::FitSystem sys;
        FitScratch scratch;
        SafeguardFire base;
        base.family = c.family;
        base.method = est->label() + (rest.empty() ? "" : " " + rest);
        base.level = level;
        base.vertices = mesh.num_vertices();
        bool any = false;
        for (int v = 0; v < mesh.num_vertices(); ++v) {
          if (!fit->first_system(ctx, v, *ws, sys)) continue;
          // The route's right-hand sides do not change the test (it reads A only).
          const FitResult r =
              fit_polynomial(sys.u, sys.v, sys.f, sys.w, fit->fit_settings(), scratch);
          if (r.rank >= r.column_rank) continue;
          SafeguardFire f = base;
          f.vertex = v;
          const Vec3 p = mesh.position(v);
          f.x = p.x(), f.y = p.y(), f.z = p.z();
          f.boundary = mesh.is_boundary_vertex(v);
          f.rows = r.rows;
          f.column_rank = r.column_rank;
          f.rank = r.rank;
          f.condition = r.condition;
          const auto vi = static_cast<size_t>(v);
          f.degree = with[vi].degree, f.degree_rjj_only = without[vi].degree;
          f.ring = with[vi].ring, f.ring_rjj_only = without[vi].ring;
          f.points = with[vi].points, f.points_rjj_only = without[vi].points;
          out.push_back(f);
          any = true;
        }
        if (!any) out.push_back(base);
      }
    }
  return out;
}

}  // namespace curvbench
