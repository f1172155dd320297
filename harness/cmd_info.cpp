// `curvbench info MESH`: counts, boundary, mean edge length, Euler characteristic, orientation.
#include <cstdio>
#include <iostream>

#include "harness/commands.h"
#include "mesh/io.h"

namespace curvbench::cli {

Command add_info_command(CLI::App& app) {
  auto* sub = app.add_subcommand("info",
                                 "Print counts, boundary, mean edge length, Euler "
                                 "characteristic and orientation of a mesh");
  auto path = std::make_shared<std::string>();
  sub->add_option("MESH", *path, "Mesh file (.off, .obj, .ply)")->required();
  return [path]() {
    MeshReadReport report;
    const Mesh mesh = read_mesh(*path, &report);
    const double vol = mesh.signed_volume();
    std::printf("file:                  %s\n", path->c_str());
    std::printf("format:                %s\n", report.format.c_str());
    std::printf("vertices:              %d\n", mesh.num_vertices());
    std::printf("faces:                 %d", mesh.num_faces());
    if (report.polygons_triangulated > 0)
      std::printf(" (%d polygons fan-triangulated)", report.polygons_triangulated);
    std::printf("\n");
    std::printf("edges:                 %d\n", mesh.num_edges());
    std::printf("boundary edges:        %d\n", mesh.num_boundary_edges());
    std::printf("boundary vertices:     %d\n", mesh.num_boundary_vertices());
    std::printf("non-manifold edges:    %d\n", mesh.num_nonmanifold_edges());
    std::printf("isolated vertices:     %d\n", mesh.num_isolated_vertices());
    std::printf("euler characteristic:  %d\n", mesh.euler_characteristic());
    std::printf("mean edge length:      %.6g\n", mesh.mean_edge_length());
    std::printf("orientation:           %s",
                mesh.is_consistently_oriented() ? "consistent" : "inconsistent");
    if (!mesh.is_consistently_oriented())
      std::printf(" (%d edges traversed twice in the same direction)",
                  mesh.num_inconsistent_edges());
    std::printf("\n");
    if (!mesh.has_boundary() && mesh.is_consistently_oriented())
      std::printf("signed volume:         %.6g (%s)\n", vol,
                  vol > 0 ? "outward normals" : "inward normals");
    return 0;
  };
}

}  // namespace curvbench::cli
