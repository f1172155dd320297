// `curvbench mesh`: writes a generated test mesh (docs/algorithms.md §10) with its exact per-vertex
// quantities, or prints the reproduction of the paper's Table 4 (isosurface position errors).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/model/paper_tables.h"
#include "harness/report/report.h"
#include "mesh/io.h"
#include "meshgen/generate.h"
#include "meshgen/torus_isosurface.h"

namespace curvbench::cli {

namespace {

struct MeshOptions {
  std::string family;
  bool list = false;  // --list: the family table
  int level = 1;
  int noise_order = 0;
  std::uint64_t seed = 1;
  bool jitter = false;
  MeshShape shape;  // --aspect, --density: the mesh option table (meshgen/generate.h)
  std::string output;
  bool table4 = false;
  int max_grid = 256;
};

// Per-vertex exact quantities at the exact points: ex ey ez, exact normal nx ny nz, k1 k2 H K,
// principal direction d1x d1y d1z and umbilic (1 where d1 is arbitrary); `curvbench score`
// reads them.
std::vector<VertexProperty> exact_properties(const GeneratedMesh& gm) {
  const char* names[] = {"ex", "ey", "ez", "nx",  "ny",  "nz",  "k1",
                         "k2", "H",  "K",  "d1x", "d1y", "d1z", "umbilic"};
  std::vector<VertexProperty> props;
  for (const char* name : names) props.push_back({name, {}, std::string(name) == "umbilic"});
  const int n = gm.mesh.num_vertices();
  for (auto& p : props) p.values.resize(n);
  for (int i = 0; i < n; ++i) {
    const SurfacePoint sp = gm.surface->evaluate(gm.exact_points.row(i).transpose());
    const double values[] = {gm.exact_points(i, 0),
                             gm.exact_points(i, 1),
                             gm.exact_points(i, 2),
                             sp.normal.x(),
                             sp.normal.y(),
                             sp.normal.z(),
                             sp.k1,
                             sp.k2,
                             sp.H,
                             sp.K,
                             sp.d1.x(),
                             sp.d1.y(),
                             sp.d1.z(),
                             sp.umbilic ? 1.0 : 0.0};
    for (size_t k = 0; k < props.size(); ++k) props[k].values[i] = values[k];
  }
  return props;
}

int write_generated_mesh(const MeshOptions& o) {
  const std::string ext = lower_extension(o.output);
  if (ext != "off" && ext != "ply")
    throw UsageError("--output " + o.output + ": extension must be .off or .ply");
  MeshSpec spec;
  spec.family = o.family;
  spec.level = o.level;
  spec.noise_order = o.noise_order;
  spec.seed = o.seed;
  spec.jitter = o.jitter;
  spec.shape = o.shape;
  const GeneratedMesh gm = generate_mesh(spec);
  write_mesh(o.output, gm.mesh,
             ext == "ply" ? exact_properties(gm) : std::vector<VertexProperty>{});

  const Mesh& m = gm.mesh;
  const MeshQuality q = mesh_quality(m);
  std::printf("wrote:                 %s\n", o.output.c_str());
  std::printf("mesh:                  %s\n", gm.description.c_str());
  std::printf("vertices:              %d\n", m.num_vertices());
  std::printf("faces:                 %d\n", m.num_faces());
  if (m.num_faces() == 0) {  // a point-cloud family: no boundary, edges, angles or valences
    std::printf("nominal spacing h:     %.6g (sqrt(area / points))\n", gm.spacing);
  } else {
    std::printf("boundary vertices:     %d\n", m.num_boundary_vertices());
    std::printf("euler characteristic:  %d\n", m.euler_characteristic());
    std::printf("mean edge length:      %.6g\n", m.mean_edge_length());
    std::printf("angles (deg):          min %.3f, max %.3f\n", q.min_angle_deg, q.max_angle_deg);
    std::printf("valence:               interior %d..%d", q.min_valence, q.max_valence);
    if (m.has_boundary())
      std::printf(", boundary %d..%d", q.min_boundary_valence, q.max_boundary_valence);
    std::printf("\n");
  }
  if (ext == "ply")
    std::printf(
        "vertex properties:     ex ey ez (exact point), nx ny nz (exact normal), "
        "k1 k2 H K, d1x d1y d1z, umbilic (exact)\n");
  return 0;
}

// "torus-structured 1..6, ..." from the generator's own table, so the help cannot go stale.
std::string level_ranges() {
  std::string s;
  for (const auto& f : mesh_families())
    s += (s.empty() ? "" : ", ") + f + " 1.." + std::to_string(max_mesh_level(f));
  return s;
}

// The Table 4 section of the report, rendered as markdown (one rendering of the table).
int print_table4(int max_grid) {
  std::printf("%s", report::to_markdown(table4_section(table4(max_grid)), 1).c_str());
  return 0;
}

}  // namespace

Command add_mesh_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "mesh",
      "Generate a test mesh (docs/mesh_families.md) and write it with its exact per-vertex "
      "quantities, or print the reproduction of the paper's Table 4");
  auto o = std::make_shared<MeshOptions>();
  std::string families;
  for (const auto& f : mesh_families()) families += (families.empty() ? "" : ", ") + f;
  auto* family = sub->add_option("--family", o->family, "Mesh family: " + families);
  auto* level = sub->add_option("--level", o->level,
                                "Resolution level, 1 = coarsest (" + level_ranges() + ")");
  auto* noise = sub->add_option("--noise-order", o->noise_order,
                                "Add alpha h^k normal noise of order k (1.." +
                                    std::to_string(kMaxNoiseOrder) +
                                    "; 0 = none), "
                                    "alpha = 0.1 N(0,1)");
  auto* seed = sub->add_option("--seed", o->seed,
                               "Seed for the noise, the jitter and the irregular bump points")
                   ->check(CLI::Validator(
                       [](const std::string& s) {
                         return s.starts_with("-") ? "the seed must be a non-negative integer" : "";
                       },
                       "UINT"));
  auto* jitter = sub->add_flag("--jitter", o->jitter,
                               "torus-structured only: jitter the vertices by +-0.15 cells "
                               "along the torus");
  std::vector<const CLI::Option*> shape_flags;
  for (const MeshOptionInfo& info : mesh_option_table())
    shape_flags.push_back(sub->add_option_function<double>(
        "--" + info.name, [o, name = info.name](double v) { set_mesh_option(o->shape, name, v); },
        info.help + " (default " + format_g(info.default_value) + ")"));
  auto* output = sub->add_option("--output", o->output,
                                 "Output file, .off or .ply (PLY carries the exact point ex ey "
                                 "ez, exact normal nx ny nz, k1 k2 H K, principal direction "
                                 "d1x d1y d1z and umbilic per vertex; `curvbench score` reads "
                                 "them)");
  auto* table = sub->add_flag("--table4", o->table4,
                              "Print the Table 4 reproduction (isosurface torus position errors)");
  auto* max_grid = sub->add_option("--max-grid", o->max_grid,
                                   "With --table4: largest grid n (16, 32, 64, 128 or 256; "
                                   "default 256)");
  auto* list =
      sub->add_flag("--list", o->list, "Print the family table (docs/mesh_families.md) and exit");
  return [o, family, level, noise, seed, jitter, shape_flags, output, table, max_grid, list]() {
    if (list->count() > 0) {
      std::fputs(mesh_family_markdown().c_str(), stdout);
      return 0;
    }
    if ((output->count() > 0) == (table->count() > 0))
      throw UsageError("mesh: give exactly one of --output FILE, --table4 and --list");
    if (table->count() > 0) {
      std::vector<const CLI::Option*> given = {family, level, noise, seed, jitter};
      given.insert(given.end(), shape_flags.begin(), shape_flags.end());
      for (const CLI::Option* opt : given)
        if (opt->count() > 0)
          throw UsageError("mesh: " + opt->get_name() + " does not apply to --table4");
      const int n = o->max_grid;
      if (n != 16 && n != 32 && n != 64 && n != 128 && n != 256)
        throw UsageError("mesh: --max-grid " + std::to_string(n) +
                         " must be one of 16, 32, 64, 128, 256");
      return print_table4(n);
    }
    if (max_grid->count() > 0) throw UsageError("mesh: --max-grid applies only to --table4");
    if (family->count() == 0) throw UsageError("mesh: --output needs --family");
    return write_generated_mesh(*o);
  };
}

}  // namespace curvbench::cli
