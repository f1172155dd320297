// libFuzzer target for one mesh reader: read_mesh() on arbitrary bytes saved as a .off, .obj or
// .ply file (CURVBENCH_FUZZ_FORMAT, set per target by fuzz/CMakeLists.txt).
//
// The contract under test (mesh/io.h): on any input, read_mesh either returns a valid mesh or
// throws InputError. A crash, a sanitizer report, a timeout, an out-of-memory, any other
// exception, or a returned mesh that breaks the Mesh invariants (index out of range, repeated
// vertex in a face, non-finite coordinate, report counts that disagree with the mesh) is a
// finding, and so is an accepted file that CGAL's reader (the differential oracle,
// tests/mesh/cgal_oracle.h) refuses or reads to another polygon soup. Run through `make fuzz`
// (fuzz/run.sh).
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <typeinfo>

#include "core/errors.h"
#include "mesh/io.h"
#include "tests/mesh/cgal_oracle.h"

#ifndef CURVBENCH_FUZZ_FORMAT
#error "CURVBENCH_FUZZ_FORMAT (off, obj or ply) must be defined"
#endif

namespace {

/// One scratch file per process (libFuzzer's -fork/-jobs run several), removed at exit.
std::string& input_path() {
  static std::string path =
      (std::filesystem::temp_directory_path() /
       ("curvbench-fuzz-" + std::to_string(::getpid()) + "." CURVBENCH_FUZZ_FORMAT))
          .string();
  return path;
}

void remove_input() {
  std::remove(input_path().c_str());
}

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_read_" CURVBENCH_FUZZ_FORMAT ": %s\n", what.c_str());
  std::abort();  // libFuzzer reports a deadly signal and saves the input
}

void check_invariants(const curvbench::Mesh& mesh, const curvbench::MeshReadReport& report) {
  if (mesh.num_vertices() <= 0 || mesh.num_faces() <= 0) finding("empty mesh returned");
  if (report.format != CURVBENCH_FUZZ_FORMAT) finding("report.format is '" + report.format + "'");
  if (report.triangles != mesh.num_faces()) finding("report.triangles != num_faces");
  if (report.polygons_read <= 0 || report.polygons_triangulated > report.polygons_read ||
      report.triangles < report.polygons_read)
    finding("inconsistent polygon counts in the report");
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(mesh.vertices()(v, c))) finding("non-finite coordinate returned");
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int a = mesh.face_vertex(f, 0), b = mesh.face_vertex(f, 1), c = mesh.face_vertex(f, 2);
    for (int i : {a, b, c})
      if (i < 0 || i >= mesh.num_vertices()) finding("face index out of range returned");
    if (a == b || b == c || a == c) finding("degenerate face (repeated vertex) returned");
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  std::atexit(remove_input);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = input_path();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) finding("cannot create the scratch file " + path);
  if (size > 0 && std::fwrite(data, 1, size, f) != size) finding("cannot write " + path);
  std::fclose(f);

  curvbench::MeshReadReport report;
  try {
    const curvbench::Mesh mesh = curvbench::read_mesh(path, &report);
    check_invariants(mesh, report);
    // Differential: CGAL's reader must read an accepted file to the same soup (cgal_oracle.h).
    const std::string difference = curvbench::oracle::differential(
        CURVBENCH_FUZZ_FORMAT, std::string(reinterpret_cast<const char*>(data), size));
    if (!difference.empty()) finding("CGAL's reader disagrees: " + difference);
  } catch (const curvbench::InputError&) {
    // expected for malformed input
  } catch (const std::exception& e) {
    finding(std::string("unexpected exception ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    finding("unexpected exception of a non-std type");
  }
  return 0;
}
