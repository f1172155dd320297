// Mesh file input and output.
//
// Reading: OFF, OBJ and PLY (ASCII and binary), and the point sets .xyz/.pts/.pwn, chosen by
// extension (case-insensitive), one reader per format (mesh/read_off.cpp, read_obj.cpp,
// read_ply.cpp, read_xyz.cpp), each a single validating pass that builds the polygon soup. A file
// without faces (a point file, OFF with 0 faces, PLY without a face element) gives a Mesh
// without faces: a point set (docs/point_sets.md). The normals a point set's file gives with its
// vertices (.pwn, a 6-column .xyz/.pts, PLY float/double nx ny nz, NOFF) are kept, as read, as
// Mesh::given_normals(); a file with faces keeps none (a mesh's vertex normals come from its
// faces). Polygons with more than three vertices are fan-triangulated;
// polygons with fewer than three vertices or a repeated vertex index are dropped and counted.
// Writing: OFF (full double precision) and PLY (binary little-endian) with optional per-vertex
// properties (normal, curvatures, directions, ...) for MeshLab / ParaView.
//
// Every failure throws InputError with a one-line message naming the file and the problem.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace curvbench {

/// Reader options.
struct MeshReadOptions {
  /// Drop vertices with a NaN or Inf coordinate and every polygon using them (the remaining
  /// vertices are renumbered in file order) instead of throwing InputError.
  bool skip_invalid = false;
};

/// What the reader saw, beyond the mesh itself (reported by `curvbench info`). The file holds
/// polygons_read + faces_with_few_vertices + faces_with_repeated_index + faces_skipped polygons.
struct MeshReadReport {
  std::string format;                 ///< "off", "obj" or "ply"
  int polygons_read = 0;              ///< polygons kept (triangulated into the mesh)
  int polygons_triangulated = 0;      ///< kept polygons with more than 3 vertices, fan-triangulated
  int triangles = 0;                  ///< triangles in the resulting mesh
  int faces_with_few_vertices = 0;    ///< polygons with 0, 1 or 2 vertices: dropped
  int faces_with_repeated_index = 0;  ///< polygons naming a vertex twice: dropped
  int vertices_in_file = 0;           ///< vertices in the file
  int vertices_skipped = 0;           ///< vertices with a NaN/Inf coordinate dropped (skip_invalid)
  int faces_skipped = 0;              ///< polygons dropped because they use a skipped vertex
  std::vector<int> skipped_vertices;  ///< file indices of the skipped vertices, increasing
  /// File index of each mesh vertex when vertices were skipped; empty when the mesh vertices are
  /// the file's (the identity).
  std::vector<int> source_vertex;

  int faces_dropped() const { return faces_with_few_vertices + faces_with_repeated_index; }
};

/// The whole file as bytes. Throws InputError naming the path: no such file, a directory, or
/// cannot be read (with the system's reason).
std::string read_file(const std::string& path);

/// Reads a triangle mesh. Throws InputError on a missing/unreadable file, an unknown extension,
/// a malformed file (bad header or body, counts that disagree with the body, non-numeric token),
/// an index out of range or negative, a NaN/Inf coordinate (unless options.skip_invalid), a mesh
/// without vertices, or one whose every polygon was dropped. A file without polygons is a point
/// set (a Mesh with 0 faces); a point file whose lines differ in their number of columns (2-D and
/// 3-D lines mixed) is refused naming the line. Header counts or polygon sizes the file cannot hold
/// are refused before anything is allocated by them. Polygons with fewer than 3 vertices or with a
/// repeated vertex index are dropped and counted in the report.
Mesh read_mesh(const std::string& path, MeshReadReport* report = nullptr,
               const MeshReadOptions& options = {});

/// One-line warnings (without a prefix or newline) about what read_mesh dropped or skipped:
/// empty when nothing was. `path` names the file.
std::vector<std::string> read_warnings(const std::string& path, const MeshReadReport& report);

/// A named per-vertex scalar written as a PLY vertex property ("nx", "k1", "status", ...).
struct VertexProperty {
  std::string name;
  std::vector<double> values;  ///< one per vertex
  bool integer = false;        ///< written as PLY int instead of double
};

/// Writes OFF (ASCII, %.17g) with one "# " comment line per entry of `comments` after the
/// keyword. Throws InputError if the file cannot be written.
void write_off(const std::string& path, const Mesh& mesh,
               const std::vector<std::string>& comments = {});

/// Writes binary little-endian PLY with x, y, z and the given per-vertex properties, and one
/// header comment line per entry of `comments` (each must be a single line).
void write_ply(const std::string& path, const Mesh& mesh,
               const std::vector<VertexProperty>& properties = {},
               const std::vector<std::string>& comments = {});

/// Binary little-endian PLY written vertex block by vertex block, so that per-vertex properties
/// never need to be held for the whole mesh: the header at construction, then the vertex records
/// (x, y, z and the properties) of consecutive vertex ranges from the first vertex on, then the
/// faces at commit(). The bytes are those of write_ply with the same properties and comments
/// (write_ply is this writer with one pass over its property arrays); a failure leaves no file
/// (core/atomic_file.h). `mesh` must outlive the writer; its faces are read at commit().
class PlyWriter {
 public:
  /// A vertex property's name and type (its values come with each block).
  struct Property {
    std::string name;
    bool integer = false;  ///< PLY int (the values must be 32-bit integers) instead of double
  };

  /// Throws UsageError for a bad property name (empty, not a printable word, x/y/z or given
  /// twice) or a comment of several lines; InputError if the file cannot be written.
  PlyWriter(const std::string& path, const Mesh& mesh, std::vector<Property> properties,
            const std::vector<std::string>& comments = {});
  ~PlyWriter();
  PlyWriter(const PlyWriter&) = delete;
  PlyWriter& operator=(const PlyWriter&) = delete;

  /// Appends the records of vertices [first, first + count), where first is the number of
  /// vertices written so far: values[i * P + p] is property p of vertex first + i (P properties).
  /// Throws UsageError for an integer property whose value is not a 32-bit integer.
  void write_vertices(int first, int count, const double* values);

  /// Writes the faces (after all vertices), closes and renames into place.
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Writes OFF or PLY by extension (.off / .ply); throws UsageError for other extensions.
/// `comments` go into the header of either format. Like write_off and write_ply, it writes to a
/// temporary file in the target folder and renames it into place: a failure leaves no file.
void write_mesh(const std::string& path, const Mesh& mesh,
                const std::vector<VertexProperty>& properties = {},
                const std::vector<std::string>& comments = {});

}  // namespace curvbench
