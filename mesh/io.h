// Mesh file input and output.
//
// Reading: OFF, OBJ and PLY (ASCII and binary), chosen by extension (case-insensitive), through
// CGAL's polygon-soup readers. Polygons with more than three vertices are fan-triangulated.
// Writing: OFF (full double precision) and PLY (binary little-endian) with optional per-vertex
// properties (normal, curvatures, directions, ...) for MeshLab / ParaView.
//
// Every failure throws InputError with a one-line message naming the file and the problem.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace curvbench {

/// What the reader saw, beyond the mesh itself (reported by `curvbench info`).
struct MeshReadReport {
  std::string format;             ///< "off", "obj" or "ply"
  int polygons_read = 0;          ///< faces in the file, before triangulation
  int polygons_triangulated = 0;  ///< faces with more than 3 vertices, fan-triangulated
  int triangles = 0;              ///< triangles in the resulting mesh
};

/// Reads a triangle mesh. Throws InputError on a missing/unreadable file, an unknown extension,
/// a malformed file, an index out of range, a NaN/Inf coordinate, or an empty mesh.
Mesh read_mesh(const std::string& path, MeshReadReport* report = nullptr);

/// A named per-vertex scalar written as a PLY vertex property ("nx", "k1", "status", ...).
struct VertexProperty {
  std::string name;
  std::vector<double> values;  ///< one per vertex
  bool integer = false;        ///< written as PLY int instead of double
};

/// Writes OFF (ASCII, %.17g). Throws InputError if the file cannot be written.
void write_off(const std::string& path, const Mesh& mesh);

/// Writes binary little-endian PLY with x, y, z and the given per-vertex properties.
void write_ply(const std::string& path, const Mesh& mesh,
               const std::vector<VertexProperty>& properties = {});

/// Writes OFF or PLY by extension (.off / .ply); throws UsageError for other extensions.
void write_mesh(const std::string& path, const Mesh& mesh,
                const std::vector<VertexProperty>& properties = {});

}  // namespace curvbench
