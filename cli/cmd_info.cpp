// `curvbench info MESH [--skip-invalid] [--crease-angle DEG]`: counts, boundary, defects
// (mesh/mesh_checks.h), mean edge length, Euler characteristic, orientation, sharp edges and
// crease vertices (mesh/creases.h) and the noise estimate away from them
// (harness/model/noise_estimate.h). What the reader dropped (faces with fewer than
// 3 vertices or a repeated index; with --skip-invalid, vertices with NaN/Inf coordinates and
// their faces) is also reported as a one-line warning on stderr.
#include <array>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "core/errors.h"
#include "core/text.h"
#include "harness/model/noise_estimate.h"
#include "mesh/creases.h"
#include "mesh/io.h"
#include "mesh/mesh_checks.h"

namespace curvbench::cli {

namespace {

struct InfoOptions {
  std::string path;
  bool skip_invalid = false;
  double crease_angle = kDefaultCreaseAngle;
};

}  // namespace

Mesh read_input_mesh(const std::string& path, bool skip_invalid, MeshReadReport& report) {
  MeshReadOptions read_options;
  read_options.skip_invalid = skip_invalid;
  Mesh mesh = read_mesh(path, &report, read_options);
  for (const std::string& w : read_warnings(path, report))
    std::fprintf(stderr, "curvbench: warning: %s\n", w.c_str());
  return mesh;
}

namespace {

int run_info(const InfoOptions& o) {
  if (!(o.crease_angle > 0 && o.crease_angle < 180))
    throw UsageError("--crease-angle " + format_g(o.crease_angle) +
                     ": the angle between face normals must be in (0, 180) degrees");
  MeshReadReport report;
  const Mesh mesh = read_input_mesh(o.path, o.skip_invalid, report);
  const MeshChecks c = check_mesh(mesh);
  const double vol = mesh.signed_volume();
  std::printf("file:                  %s\n", o.path.c_str());
  std::printf("format:                %s\n", report.format.c_str());
  std::printf("vertices:              %d", mesh.num_vertices());
  if (report.vertices_skipped > 0)
    std::printf(" (%d of %d in the file; %d with a NaN/Inf coordinate skipped)",
                mesh.num_vertices(), report.vertices_in_file, report.vertices_skipped);
  std::printf("\n");
  std::printf("faces:                 %d", mesh.num_faces());
  if (report.polygons_triangulated > 0)
    std::printf(" (%d polygons fan-triangulated)", report.polygons_triangulated);
  std::printf("\n");
  std::printf("polygons triangulated: %d\n", report.polygons_triangulated);
  std::printf("faces dropped:         %d", report.faces_dropped() + report.faces_skipped);
  if (report.faces_dropped() + report.faces_skipped > 0)
    std::printf(
        " (%d with fewer than 3 vertices, %d with a repeated vertex index, %d using a "
        "skipped vertex)",
        report.faces_with_few_vertices, report.faces_with_repeated_index, report.faces_skipped);
  std::printf("\n");
  std::printf("edges:                 %d\n", mesh.num_edges());
  std::printf("boundary edges:        %d\n", mesh.num_boundary_edges());
  std::printf("boundary loops:        %d\n", c.boundary_loops);
  std::printf("boundary vertices:     %d\n", mesh.num_boundary_vertices());
  std::printf("non-manifold edges:    %d\n", mesh.num_nonmanifold_edges());
  std::printf("non-manifold vertices: %d\n", c.nonmanifold_vertices);
  std::printf("isolated vertices:     %d\n", mesh.num_isolated_vertices());
  std::printf("zero-area faces:       %d\n", c.zero_area_faces);
  std::printf("duplicate vertices:    %d\n", c.duplicate_vertices);
  std::printf("duplicate faces:       %d\n", c.duplicate_faces);
  std::printf("components:            %d\n", c.components);
  std::printf("euler characteristic:  %d\n", mesh.euler_characteristic());
  std::printf("mean edge length:      %.6g\n", mesh.mean_edge_length());
  std::printf("orientation:           %s",
              mesh.is_consistently_oriented() ? "consistent" : "inconsistent");
  if (!mesh.is_consistently_oriented())
    std::printf(" (%d edges traversed twice in the same direction)", mesh.num_inconsistent_edges());
  std::printf("\n");
  // What the estimators will not handle (the causes `estimate` counts failed vertices by).
  std::array<int, kVertexDefectCount> defects{};
  for (const VertexDefect d : vertex_defects(mesh)) ++defects[static_cast<size_t>(d)];
  std::printf("hard for estimators:   ");
  for (int d = 1; d < kVertexDefectCount; ++d)
    std::printf("%s%s %d", d > 1 ? ", " : "", to_string(static_cast<VertexDefect>(d)),
                defects[static_cast<size_t>(d)]);
  std::printf(" (vertices)\n");
  if (!mesh.has_boundary() && mesh.is_consistently_oriented())
    std::printf("signed volume:         %.6g (%s)\n", vol,
                vol > 0 ? "outward normals" : "inward normals");
  const Creases creases = detect_creases(mesh, o.crease_angle);
  std::printf("sharp edges:           %d (face normals more than %g degrees apart)\n",
              creases.num_edges(), o.crease_angle);
  std::printf("crease vertices:       %d\n", creases.num_vertices());
  try {
    const NoiseEstimate e = estimate_noise(mesh, o.crease_angle);
    std::printf(
        "noise estimate:        sigma/h = %.3g, sigma/h^2 = %.3g (from %d vertices; %d "
        "crease vertices and %d next to one left out",
        e.sigma_over_h, e.sigma_over_h2, e.vertices_used, e.crease_vertices,
        e.near_crease_vertices);
    if (!e.creases_left_out) std::printf(", then counted: no other vertex has a fit");
    if (e.crease_angle > o.crease_angle)
      std::printf("; creases taken at %.3g degrees, %g times the median dihedral angle",
                  e.crease_angle, kCreaseOverMedianAngle);
    std::printf(")\n");
  } catch (const InputError& e) {
    std::printf("noise estimate:        none (%s)\n", e.what());
  }
  return 0;
}

}  // namespace

Command add_info_command(CLI::App& app) {
  auto* sub = app.add_subcommand("info",
                                 "Print counts, boundary, defects (zero-area, duplicate and "
                                 "non-manifold elements, components), mean edge length, Euler "
                                 "characteristic, orientation, sharp edges and the noise "
                                 "estimate of a mesh");
  auto o = std::make_shared<InfoOptions>();
  sub->add_option("MESH", o->path, "Mesh file (.off, .obj, .ply)")->required();
  sub->add_flag("--skip-invalid", o->skip_invalid,
                "Drop vertices with a NaN/Inf coordinate and the faces using them (reported) "
                "instead of failing");
  sub->add_option("--crease-angle", o->crease_angle,
                  "An edge is sharp (a crease) when its two faces' normals are more than this many "
                  "degrees apart, in (0, 180); crease vertices are left out of the noise estimate")
      ->capture_default_str();
  return [o]() { return run_info(*o); };
}

}  // namespace curvbench::cli
