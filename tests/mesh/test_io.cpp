// Mesh file I/O: OFF / OBJ / ASCII PLY / binary PLY reading (counts, exact coordinates, fan
// triangulation), bit-exact write -> read round trips, the binary PLY layout with vertex
// properties, atomic writing, and one InputError per malformed-input case naming file and problem.
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "mesh/io.h"
#include "mesh/mesh.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::slurp;

/// Bytes of a binary file under construction.
struct Bytes {
  std::string s;
  template <typename T>
  Bytes& le(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
    return *this;
  }
  template <typename T>
  Bytes& be(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if constexpr (std::endian::native == std::endian::little) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
    return *this;
  }
};

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

struct BadFile {
  const char* name;
  std::string content;
  std::vector<std::string> parts;  // expected in the message
};

class MeshIo : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() /
           ("curvbench_test_io_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string file(const std::string& name, const std::string& content) const {
    std::ofstream out(path(name), std::ios::binary);
    out << content;
    return path(name);
  }

  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  void expect_errors(const std::vector<BadFile>& cases) const;

  fs::path dir_;
};

/// read_mesh(p) must throw InputError: one line, starting with the file name, containing every
/// part.
void expect_read_error(const std::string& p, const std::vector<std::string>& parts) {
  try {
    read_mesh(p);
    ADD_FAILURE() << "no InputError for " << p;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(p + ": ", 0), 0u) << "message does not start with the file: " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "not one line: " << msg;
    for (const std::string& part : parts)
      EXPECT_NE(msg.find(part), std::string::npos) << "missing '" << part << "' in: " << msg;
  }
}

// Regular tetrahedron-like mesh (outward faces) with coordinates that are not short decimals.
Mesh awkward_tetrahedron() {
  VertexMatrix V(4, 3);
  V << 0.1, 1.0 / 3.0, -0.0,                                       //
      std::nextafter(1.0, 2.0), -2.5e17, 4.9406564584124654e-324,  // subnormal
      -1e-300, 2.0 / 3.0, 7.0,                                     //
      123456.789, 0.2, std::sqrt(2.0);
  FaceMatrix F(4, 3);
  F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  return Mesh(V, F);
}

void expect_bit_identical_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.num_vertices(), b.num_vertices());
  ASSERT_EQ(a.num_faces(), b.num_faces());
  for (int v = 0; v < a.num_vertices(); ++v)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(bits(a.vertices()(v, c)), bits(b.vertices()(v, c))) << "vertex " << v << " " << c;
  EXPECT_EQ(a.faces(), b.faces());
}

// ---- reading -----------------------------------------------------------------------------------

TEST_F(MeshIo, OffTetrahedronWithCommentsReadsExactly) {
  const std::string p = file("tet.off",
                             "# a comment line\n"
                             "OFF  # keyword\n"
                             "\n"
                             "4 4 6\n"
                             "0.1 0 0\n"
                             "0 -2.5e-3 0   # trailing comment\n"
                             "\n"
                             "0 0 0.33333333333333331\n"
                             "1 1 1\n"
                             "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  MeshReadReport report;
  const Mesh m = read_mesh(p, &report);
  ASSERT_EQ(m.num_vertices(), 4);
  ASSERT_EQ(m.num_faces(), 4);
  EXPECT_EQ(m.vertices()(0, 0), 0.1);
  EXPECT_EQ(m.vertices()(1, 1), -2.5e-3);
  EXPECT_EQ(m.vertices()(2, 2), 1.0 / 3.0);
  EXPECT_EQ(m.vertices()(3, 0), 1.0);
  FaceMatrix F(4, 3);
  F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  EXPECT_EQ(m.faces(), F);
  EXPECT_EQ(report.format, "off");
  EXPECT_EQ(report.polygons_read, 4);
  EXPECT_EQ(report.polygons_triangulated, 0);
  EXPECT_EQ(report.triangles, 4);
  EXPECT_EQ(m.euler_characteristic(), 2);
}

TEST_F(MeshIo, NoffCoffAndCountsOnKeywordLineRead) {
  const std::string noff = file("n.off",
                                "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1.5 0 0 0 1\n"
                                "3 0 1 2\n");
  const std::string coff = file("c.OFF",
                                "COFF 3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
                                "0 1.5 0 0 0 255 255\n3 0 1 2 0.5 0.5 0.5\n");
  for (const std::string& p : {noff, coff}) {
    SCOPED_TRACE(p);
    const Mesh m = read_mesh(p);
    ASSERT_EQ(m.num_vertices(), 3);
    ASSERT_EQ(m.num_faces(), 1);
    EXPECT_EQ(m.vertices()(2, 1), 1.5);
    EXPECT_EQ(m.vertices()(1, 0), 1.0);
    EXPECT_EQ(m.face_vertex(0, 2), 2);
  }
}

// Two unit quads side by side: 0-1-2 on y = 0, 3-4-5 on y = 1.
const char* const kTwoQuadsObj =
    "# two quads\n"
    "o quads\n"
    "v 0 0 0\nv 1 0 0\nv 2 0 0.25\n"
    "v 0 1 0\nv 1 1 0\nv 2 1 -0.5\n"
    "vn 0 0 1\n"
    "s off\n"
    "f 1 2 5 4\n"
    "f 2 3 6 5\n";

TEST_F(MeshIo, ObjQuadsAreFanTriangulatedAndCounted) {
  MeshReadReport report;
  const Mesh m = read_mesh(file("quads.obj", kTwoQuadsObj), &report);
  ASSERT_EQ(m.num_vertices(), 6);
  ASSERT_EQ(m.num_faces(), 4);
  FaceMatrix F(4, 3);
  F << 0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4;  // (v0, vi, vi+1)
  EXPECT_EQ(m.faces(), F);
  EXPECT_EQ(m.vertices()(2, 2), 0.25);
  EXPECT_EQ(m.vertices()(5, 2), -0.5);
  EXPECT_EQ(report.format, "obj");
  EXPECT_EQ(report.polygons_read, 2);
  EXPECT_EQ(report.polygons_triangulated, 2);
  EXPECT_EQ(report.triangles, 4);
  EXPECT_TRUE(m.is_consistently_oriented());
}

TEST_F(MeshIo, ObjSlashesRelativeIndicesTabsAndCrlf) {
  // CGAL alone reads "f 1\t2\t3" as the 1-gon [0]; tabs must survive.
  const std::string p = file("t.obj",
                             "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 0\r\nvt 0 0\r\n"
                             "f 1/1\t2/1\t3/1\r\n"
                             "f -3//1 -1//1 -2//1\r\n");
  MeshReadReport report;
  const Mesh m = read_mesh(p, &report);
  ASSERT_EQ(m.num_faces(), 2);
  FaceMatrix F(2, 3);
  F << 0, 1, 2, 1, 3, 2;
  EXPECT_EQ(m.faces(), F);
  EXPECT_EQ(report.polygons_triangulated, 0);
}

TEST_F(MeshIo, AsciiPlyWithColorsAndMixedPolygons) {
  const std::string p = file("a.ply",
                             "ply\r\n"
                             "format ascii 1.0\r\n"
                             "comment colors and a quad\r\n"
                             "element vertex 5\r\n"
                             "property float x\r\nproperty float y\r\nproperty float z\r\n"
                             "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\n"
                             "element face 2\r\n"
                             "property list uchar int vertex_indices\r\n"
                             "end_header\r\n"
                             "0 0 0 255 0 0\r\n1.25 0 0 0 255 0\r\n1 1 -3 0 0 255\r\n"
                             "0 1 0 1 2 3\r\n0.5 2 0 4 5 6\r\n"
                             "4 0 1 2 3\r\n3 3 2 4\r\n");
  MeshReadReport report;
  const Mesh m = read_mesh(p, &report);
  ASSERT_EQ(m.num_vertices(), 5);
  ASSERT_EQ(m.num_faces(), 3);
  FaceMatrix F(3, 3);
  F << 0, 1, 2, 0, 2, 3, 3, 2, 4;
  EXPECT_EQ(m.faces(), F);
  EXPECT_EQ(m.vertices()(1, 0), 1.25);
  EXPECT_EQ(m.vertices()(2, 2), -3.0);
  EXPECT_EQ(m.vertices()(4, 1), 2.0);
  EXPECT_EQ(report.format, "ply");
  EXPECT_EQ(report.polygons_read, 2);
  EXPECT_EQ(report.polygons_triangulated, 1);
  EXPECT_EQ(report.triangles, 3);
}

TEST_F(MeshIo, BinaryPlyLittleAndBigEndian) {
  const double xs[4][3] = {{0.1, 0, 0}, {1.0 / 3.0, 1, 0}, {0, -1e-200, 2}, {1, 1, 1e20}};
  // Little endian: double coordinates, an extra float property, an int list, a trailing element.
  Bytes le;
  le.s =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\n"
      "property double x\nproperty double y\nproperty double z\nproperty float quality\n"
      "element face 2\nproperty list uchar int vertex_indices\n"
      "element extra 1\nproperty list int short stuff\nend_header\n";
  for (const auto& x : xs) le.le(x[0]).le(x[1]).le(x[2]).le(0.5f);
  le.le(std::uint8_t{4}).le(std::int32_t{0}).le(std::int32_t{1}).le(std::int32_t{2});
  le.le(std::int32_t{3});
  le.le(std::uint8_t{3}).le(std::int32_t{3}).le(std::int32_t{2}).le(std::int32_t{1});
  le.le(std::int32_t{2}).le(std::int16_t{7}).le(std::int16_t{-7});
  // Big endian: float coordinates, a uint list under the alternative name vertex_index.
  Bytes be;
  be.s =
      "ply\nformat binary_big_endian 1.0\nelement vertex 4\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar uint vertex_index\nend_header\n";
  for (const auto& x : xs)
    be.be(static_cast<float>(x[0])).be(static_cast<float>(x[1])).be(static_cast<float>(x[2]));
  be.be(std::uint8_t{4}).be(std::uint32_t{0}).be(std::uint32_t{1}).be(std::uint32_t{2});
  be.be(std::uint32_t{3});
  be.be(std::uint8_t{3}).be(std::uint32_t{3}).be(std::uint32_t{2}).be(std::uint32_t{1});

  FaceMatrix F(3, 3);
  F << 0, 1, 2, 0, 2, 3, 3, 2, 1;
  MeshReadReport report;
  const Mesh a = read_mesh(file("le.ply", le.s), &report);
  ASSERT_EQ(a.num_vertices(), 4);
  EXPECT_EQ(a.faces(), F);
  EXPECT_EQ(report.polygons_triangulated, 1);
  const Mesh b = read_mesh(file("be.ply", be.s));
  ASSERT_EQ(b.num_vertices(), 4);
  EXPECT_EQ(b.faces(), F);
  for (int v = 0; v < 4; ++v) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(bits(a.vertices()(v, c)), bits(xs[v][c]));
      EXPECT_EQ(bits(b.vertices()(v, c)), bits(static_cast<double>(static_cast<float>(xs[v][c]))));
    }
  }
}

// ---- writing -----------------------------------------------------------------------------------

TEST_F(MeshIo, WriteOffRoundTripIsBitExact) {
  const Mesh m = awkward_tetrahedron();
  const std::string p = path("out.off");
  write_off(p, m);
  const std::string text = slurp(p);
  EXPECT_EQ(text.rfind("OFF\n4 4 0\n", 0), 0u) << text;
  EXPECT_NE(text.find("0.10000000000000001 0.33333333333333331 -0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n3 1 2 3\n"), std::string::npos);
  MeshReadReport report;
  expect_bit_identical_mesh(read_mesh(p, &report), m);
  EXPECT_EQ(report.format, "off");
  EXPECT_EQ(listing(), std::vector<std::string>{"out.off"});  // no temporary left over
}

TEST_F(MeshIo, WritePlyWithPropertiesHasExactLayoutAndRoundTrips) {
  const Mesh m = awkward_tetrahedron();
  const std::vector<double> k1 = {-1.5, 0.1, std::numeric_limits<double>::quiet_NaN(), 1e-310};
  const std::vector<double> status = {0, -3, 7, 2147483647};
  const std::string p = path("out.ply");
  write_ply(p, m, {{"k1", k1, false}, {"status", status, true}});

  const std::string expected_header =
      "ply\nformat binary_little_endian 1.0\ncomment written by curvbench\n"
      "element vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
      "property double k1\nproperty int status\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string data = slurp(p);
  ASSERT_EQ(data.size(), expected_header.size() + 4 * (3 * 8 + 8 + 4) + 4 * (1 + 3 * 4));
  EXPECT_EQ(data.substr(0, expected_header.size()), expected_header);

  // Decode the body by hand.
  std::size_t at = expected_header.size();
  auto take = [&](auto v) {
    std::memcpy(&v, data.data() + at, sizeof(v));  // the test machine is little endian
    at += sizeof(v);
    return v;
  };
  static_assert(std::endian::native == std::endian::little);
  for (int v = 0; v < 4; ++v) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(bits(take(0.0)), bits(m.vertices()(v, c)));
    EXPECT_EQ(bits(take(0.0)), bits(k1[v]));
    EXPECT_EQ(take(std::int32_t{}), static_cast<std::int32_t>(status[v]));
  }
  for (int f = 0; f < 4; ++f) {
    EXPECT_EQ(take(std::uint8_t{}), 3);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(take(std::int32_t{}), m.face_vertex(f, k));
  }

  MeshReadReport report;
  expect_bit_identical_mesh(read_mesh(p, &report), m);
  EXPECT_EQ(report.format, "ply");
}

TEST_F(MeshIo, WriteMeshDispatchesOverwritesAndLeavesNoTemporaries) {
  const Mesh m = awkward_tetrahedron();
  const std::vector<VertexProperty> props = {{"k2", {1, 2, 3, 4}, false}};
  write_mesh(path("a.OFF"), m);
  write_mesh(path("b.Ply"), m, props);
  write_mesh(path("b.Ply"), m, props);  // replaces the existing file
  expect_bit_identical_mesh(read_mesh(path("a.OFF")), m);
  expect_bit_identical_mesh(read_mesh(path("b.Ply")), m);
  EXPECT_NE(slurp(path("b.Ply")).find("property double k2\n"), std::string::npos);
  EXPECT_THROW(write_mesh(path("c.stl"), m), UsageError);
  EXPECT_THROW(write_mesh(path("c.off"), m, props), UsageError);  // OFF has no properties
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.OFF", "b.Ply"}));
}

TEST_F(MeshIo, WritePlyRejectsBadPropertiesWithoutWriting) {
  const Mesh m = awkward_tetrahedron();
  const std::string p = path("bad.ply");
  EXPECT_THROW(write_ply(p, m, {{"k1", {1, 2, 3}, false}}), UsageError);     // 3 values, 4 vertices
  EXPECT_THROW(write_ply(p, m, {{"s", {0, 1, 2.5, 3}, true}}), UsageError);  // not an integer
  EXPECT_THROW(write_ply(p, m, {{"s", {0, 1, 3e9, 3}, true}}), UsageError);  // beyond int32
  EXPECT_THROW(write_ply(p, m, {{"x", {0, 1, 2, 3}, false}}), UsageError);   // clashes with x
  EXPECT_THROW(write_ply(p, m, {{"a b", {0, 1, 2, 3}, false}}), UsageError);
  EXPECT_TRUE(listing().empty());
}

TEST_F(MeshIo, WriteErrorsNameTheFile) {
  const Mesh m = awkward_tetrahedron();
  const std::string missing_dir = path("no/such/dir/m.off");
  try {
    write_off(missing_dir, m);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing_dir), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  fs::create_directory(path("d.ply"));
  try {
    write_ply(path("d.ply"), m);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
  EXPECT_EQ(listing(), std::vector<std::string>{"d.ply"});
}

// ---- read errors -------------------------------------------------------------------------------

// A 10 x 10 grid height field with non-round coordinates.
Mesh grid() {
  const int n = 10;
  VertexMatrix V(n * n, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) V.row(i * n + j) << i / 7.0, j / 9.0, std::sin(i + 0.3 * j);
  FaceMatrix F(2 * (n - 1) * (n - 1), 3);
  int f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j;
      F.row(f++) << a, a + n, a + n + 1;
      F.row(f++) << a, a + n + 1, a + 1;
    }
  return Mesh(V, F);
}

TEST_F(MeshIo, WrittenFilesCutShortAreTruncated) {
  const Mesh m = grid();
  write_off(path("g.off"), m);
  write_ply(path("g.ply"), m, {{"k", std::vector<double>(100, 0.5), false}});
  expect_bit_identical_mesh(read_mesh(path("g.off")), m);
  expect_bit_identical_mesh(read_mesh(path("g.ply")), m);
  // Cut inside the vertex block and inside the face block.
  for (const double keep : {0.3, 0.8}) {
    SCOPED_TRACE(keep);
    for (const char* name : {"g.off", "g.ply"}) {
      const std::string text = slurp(path(name));
      const std::string cut = file(std::string("cut_") + name,
                                   text.substr(0, static_cast<std::size_t>(keep * text.size())));
      expect_read_error(cut, {"truncated"});
    }
  }
}

// Point sets: OFF with 0 faces, PLY without a face element or with 0 faces, and the point files
// .xyz/.pts/.pwn read as meshes without faces; a point file mixing 2-D and 3-D lines, or with a
// NaN, is refused naming the line (the NaN point skipped with --skip-invalid).
TEST_F(MeshIo, PointSetsReadAsMeshesWithoutFaces) {
  const std::string pts = "0 0 0\n1 0 0.5\n0 2 0\n";
  const std::string ply_head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
      "property double y\nproperty double z\n";
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"a.off", "OFF\n3 0 0\n" + pts},
           {"a.ply", ply_head + "end_header\n" + pts},
           {"b.ply", ply_head +
                         "element face 0\nproperty list uchar int vertex_indices\n"
                         "end_header\n" +
                         pts},
           {"a.xyz", "# a comment\n" + pts},
           {"a.pts", "3\n" + pts},
           {"a.pwn", "0 0 0 0 0 1\n1 0 0.5 0 0 1\n\n0 2 0 0 0 1\n"}}) {
    SCOPED_TRACE(name);
    const Mesh m = read_mesh(file(name, text));
    EXPECT_EQ(m.num_faces(), 0);
    ASSERT_EQ(m.num_vertices(), 3);
    EXPECT_EQ(m.position(1), Vec3(1, 0, 0.5));
    EXPECT_EQ(m.position(2), Vec3(0, 2, 0));
  }
  expect_read_error(file("mixed.xyz", "0 0 0\n1 0 0\n\n2 1\n"),
                    {"line 4", "point 2 has 2 numbers where line 1 has 3"});
  expect_read_error(file("flat.xyz", "0 0\n1 0\n"), {"line 1", "2 numbers"});
  expect_read_error(file("nan.xyz", "0 0 0\n1 nan 0\n2 0 1\n"),
                    {"line 2", "non-finite coordinate", "--skip-invalid"});
  expect_read_error(file("empty.xyz", "# nothing\n"), {"no points"});
  MeshReadReport report;
  const Mesh skipped = read_mesh(path("nan.xyz"), &report, {.skip_invalid = true});
  EXPECT_EQ(skipped.num_vertices(), 2);
  EXPECT_EQ(report.vertices_skipped, 1);
  EXPECT_EQ(skipped.position(1), Vec3(2, 0, 1));
}

// The normals a point file gives (nx ny nz) are kept as read, not normalised (a zero one too):
// .pwn and 6-column .xyz, PLY nx ny nz (ASCII; binary in bulk and with a list property), NOFF;
// a file without them gives none, and --skip-invalid drops a skipped point's normal with it.
TEST_F(MeshIo, PointFilesKeepTheirNormals) {
  const std::string ply_head =
      "property double x\nproperty double y\nproperty double z\nproperty float nx\n"
      "property float ny\nproperty float nz\n";
  Bytes binary;  // x y z nx ny nz as doubles/floats, then a uchar list: the record-by-record path
  Bytes bulk;    // the same without the list: the block path
  const double xyz[3][3] = {{0, 0, 0}, {1, 0, 0.5}, {0, 2, 0}};
  const float nrm[3][3] = {{0, 0, 2}, {0, 0, 0}, {0.5f, 0, 0}};
  for (int v = 0; v < 3; ++v) {
    for (Bytes* b : {&binary, &bulk}) {
      for (int c = 0; c < 3; ++c) b->le(xyz[v][c]);
      for (int c = 0; c < 3; ++c) b->le(nrm[v][c]);
    }
    binary.le(std::uint8_t{1}).le(std::int32_t{7});
  }
  const std::string binary_head =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + ply_head;
  const std::string rows = "0 0 0 0 0 2\n1 0 0.5 0 0 0\n0 2 0 0.5 0 0\n";
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"n.pwn", rows},
           {"n.xyz", "# x y z nx ny nz\n" + rows},
           {"n.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\n" + ply_head + "end_header\n" + rows},
           {"bulk.ply", binary_head + "end_header\n" + bulk.s},
           {"list.ply", binary_head + "property list uchar int extra\nend_header\n" + binary.s},
           {"n.off", "NOFF\n3 0 0\n" + rows}}) {
    SCOPED_TRACE(name);
    const Mesh m = read_mesh(file(name, text));
    ASSERT_TRUE(m.has_given_normals());
    ASSERT_EQ(m.given_normals().rows(), 3);
    EXPECT_EQ(Vec3(m.given_normals().row(0).transpose()), Vec3(0, 0, 2));
    EXPECT_EQ(Vec3(m.given_normals().row(1).transpose()), Vec3(0, 0, 0));
    EXPECT_EQ(Vec3(m.given_normals().row(2).transpose()), Vec3(0.5, 0, 0));
    EXPECT_EQ(m.position(1), Vec3(1, 0, 0.5));
  }
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"plain.xyz", "0 0 0\n1 0 0\n0 1 0\n"},
           {"plain.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"},
           {"nx_only.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\n"
            "property double y\nproperty double z\nproperty double nx\n"
            "end_header\n0 0 0 1\n"}}) {
    SCOPED_TRACE(name);
    EXPECT_FALSE(read_mesh(file(name, text)).has_given_normals());
  }
  // With faces the file's normals are not kept: a mesh's come from its faces.
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"faces.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + ply_head +
                             "element face 1\nproperty list uchar int vertex_indices\n"
                             "end_header\n" +
                             rows + "3 0 1 2\n"},
           {"faces.off", "NOFF\n3 1 0\n" + rows + "3 0 1 2\n"}}) {
    SCOPED_TRACE(name);
    const Mesh m = read_mesh(file(name, text));
    EXPECT_EQ(m.num_faces(), 1);
    EXPECT_FALSE(m.has_given_normals());
  }
  const Mesh skipped = read_mesh(file("nan_n.pwn", "0 0 0 0 0 1\n1 nan 0 0 1 0\n2 0 1 1 0 0\n"),
                                 nullptr, {.skip_invalid = true});
  ASSERT_EQ(skipped.given_normals().rows(), 2);
  EXPECT_EQ(Vec3(skipped.given_normals().row(1).transpose()), Vec3(1, 0, 0));
}

void MeshIo::expect_errors(const std::vector<BadFile>& cases) const {
  for (const BadFile& c : cases) {
    SCOPED_TRACE(c.name);
    expect_read_error(file(c.name, c.content), c.parts);
  }
}

TEST_F(MeshIo, FileLevelErrors) {
  expect_read_error(path("missing.off"), {"no such file"});
  fs::create_directory(path("dir.off"));
  expect_read_error(path("dir.off"), {"cannot read", "is a directory"});
  expect_read_error(file("mesh.stl", "solid x\n"), {"unknown extension '.stl'"});
  expect_read_error(file("mesh", "OFF\n"), {"no file extension"});
}

// 4 vertices, 12 bytes a line: long enough for the header-size check to pass.
const char* const kTetBody = "0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n0.0 0.0 1.0\n";

TEST_F(MeshIo, MalformedOffFiles) {
  const std::string tet = kTetBody;
  const std::vector<BadFile> cases = {
      {"header.off", "OFX\n4 1 0\n" + tet + "3 0 1 2\n", {"bad OFF header", "'OFX'"}},
      {"empty.off", "", {"bad OFF header", "empty"}},
      {"counts.off", "OFF\n4 1\n" + tet + "3 0 1 2\n", {"line 2", "expected 3 counts"}},
      {"count_word.off", "OFF\nfour 1 0\n" + tet + "3 0 1 2\n", {"vertex count 'four'"}},
      {"binary.off", "OFF BINARY\n\0\0\0\4", {"binary OFF is not supported"}},
      {"skel.off", "SKEL\n1 0\n0 0 0\n", {"SKEL"}},
      {"truncated.off",
       "OFF\n4 4 0\n" + tet + "3 0 1 2\n3 0 3 1\n",
       {"truncated OFF body", "after 2 of 4 faces"}},
      {"short_face.off", "OFF\n4 1 0\n" + tet + "3 0 1\n", {"line 7", "face 0 declares 3"}},
      {"range.off",
       "OFF\n4 2 0\n" + tet + "3 0 1 2\n3 0 1 7\n",
       {"line 8", "face 1 references vertex 7, out of range [0, 4)"}},
      {"negative.off", "OFF\n4 1 0\n" + tet + "3 0 -1 2\n", {"negative vertex index -1"}},
      {"fraction.off", "OFF\n4 1 0\n" + tet + "3 0 1.7 2\n", {"vertex index '1.7'"}},
      {"nan.off",
       "OFF\n4 1 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n3 0 1 2\n",
       {"line 5", "vertex 2 has a non-finite coordinate 'nan'"}},
      {"overflow.off",
       "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1e999 0\n0 0 1\n3 0 1 2\n",
       {"vertex 2 has a non-finite coordinate '1e999'"}},
      {"word.off",
       "OFF\n4 1 0\n0 0 0\n1 abc 0\n0 1 0\n0 0 1\n3 0 1 2\n",
       {"line 4", "vertex 1: non-numeric token 'abc'"}},
      {"glued.off",
       "OFF\n4 1 0\n0 0 0x\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
       {"non-numeric token '0x'"}},
      {"few_coords.off",
       "OFF\n4 1 0\n0.0 0.0\n1.0 0.0 0.0\n0 1 0\n0 0 1\n3 0 1 2\n",
       {"vertex 0 has 2 numbers"}},
      {"two_gon.off",
       "OFF\n4 1 0\n" + tet + "2 0 1\n",
       {"no faces left after dropping all 1 (1 with fewer than 3 vertices)"}},
      {"repeat.off",
       "OFF\n4 2 0\n" + tet + "3 0 1 1\n0\n",
       {"no faces left after dropping all 2 (1 with fewer than 3 vertices, 1 with a repeated "
        "vertex index)"}},
      {"extra_vertex.off",
       "OFF\n3 1 0\n" + tet + "3 0 1 2\n",
       {"line 6", "face 0: vertex count '0.0'", "declares 3 vertices: wrong counts"}},
      {"extra_integer_vertex.off",
       "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
       {"line 6", "face 0 has 2 values after its indices", "wrong counts"}},
      {"missing_vertex.off",
       "OFF\n5 1 0\n" + tet + "3 0 1 2\n",
       {"truncated OFF body", "after 0 of 1 faces"}},
      {"extra_face.off",
       "OFF\n4 1 0\n" + tet + "3 0 1 2\n3 0 2 3\n",
       {"line 8", "data after the last", "wrong counts"}},
      {"face_junk.off",
       "OFF\n4 1 0\n" + tet + "3 0 1 2 7 7\n",
       {"line 7", "face 0 has 2 values after its indices"}},
      {"no_vertices.off", "OFF\n0 0 0\n", {"empty mesh", "no vertices"}},
      {"absurd.off",
       "OFF\n1000000000000 1 0\n0.0 0.0 0\n3 0 0 0\n",
       {"1000000000000 vertices", "more than a 40-byte file can hold"}},
      {"absurd_faces.off", "OFF\n4 2000000000 0\n" + tet, {"2000000000 faces", "more than"}},
      {"absurd_face_size.off",
       "OFF\n4 1 0\n" + tet + "1000000000000 0 1 2\n",
       {"face 0 declares 1000000000000 vertices but lists 3"}},
      {"junk_after_counts.off", "OFF\n4 1 0 x\n" + tet + "3 0 1 2\n", {"line 2"}},
  };
  expect_errors(cases);
  EXPECT_EQ(fs::file_size(path("absurd.off")), 40u);
}

TEST_F(MeshIo, MalformedObjFiles) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::vector<BadFile> cases = {
      {"zero.obj", v + "f 0 1 2\n", {"line 4", "vertex index 0 is invalid"}},
      {"range.obj", v + "f 1 2 3\nf 1 2 4\n", {"line 5", "face 1 references vertex 4"}},
      {"relative.obj", v + "f 1 2 -4\n", {"relative vertex index -4"}},
      {"word.obj", v + "f 1 2 x\n", {"vertex index 'x' is not an integer"}},
      {"two_gon.obj", v + "f 1 2\nf\n", {"no faces left", "2 with fewer than 3 vertices"}},
      {"nan.obj",
       "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n",
       {"vertex 1 has a non-finite coordinate 'inf'"}},
      {"coord.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", {"vertex 1 has 2 coordinates"}},
      {"statement.obj", v + "l 1 2\nf 1 2 3\n", {"unsupported OBJ statement 'l'"}},
      {"no_faces.obj", v, {"empty mesh", "no faces"}},
      {"empty.obj", "# nothing\n", {"empty mesh", "no vertices"}},
  };
  expect_errors(cases);
}

std::string ascii_ply(const std::string& vertex_props, const std::string& face_prop,
                      unsigned long long nv, int nf, const std::string& body) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(nv) + "\n" + vertex_props +
         "element face " + std::to_string(nf) + "\n" + face_prop + "end_header\n" + body;
}

TEST_F(MeshIo, MalformedPlyFiles) {
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const std::string list = "property list uchar int vertex_indices\n";
  const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";

  // Binary PLY with a NaN coordinate (decoded by the reader, refused when the mesh is built).
  Bytes nan;
  nan.s = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + xyz + "element face 1\n" +
          list + "end_header\n";
  nan.le(0.f).le(0.f).le(0.f).le(std::numeric_limits<float>::quiet_NaN()).le(0.f).le(0.f);
  nan.le(0.f).le(1.f).le(0.f).le(std::uint8_t{3}).le(0).le(1).le(2);
  // Binary PLY whose face list claims 2^31 - 1 entries (CGAL would resize to 8 GB first).
  Bytes huge_list;
  huge_list.s = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + xyz +
                "element face 1\nproperty list int int vertex_indices\nend_header\n";
  for (int i = 0; i < 9; ++i) huge_list.le(static_cast<float>(i % 2));
  huge_list.le(std::numeric_limits<std::int32_t>::max()).le(0).le(1).le(2);
  // Binary PLY with a negative index and one with a truncated body.
  Bytes negative;
  negative.s = nan.s.substr(0, nan.s.find("end_header\n") + 11);
  for (int i = 0; i < 9; ++i) negative.le(static_cast<float>(i % 2));
  negative.le(std::uint8_t{3}).le(0).le(-2).le(2);
  const std::string truncated = negative.s.substr(0, negative.s.size() - 6);
  // Binary PLY with 5 bytes after the declared elements (a trailing newline alone is accepted).
  Bytes trailing;
  trailing.s = negative.s.substr(0, negative.s.size() - 13);
  trailing.le(std::uint8_t{3}).le(0).le(1).le(2).le(std::uint8_t{3}).le(0);

  const std::vector<BadFile> cases = {
      {"magic.ply", "plx\nformat ascii 1.0\nend_header\n", {"first line is not 'ply'"}},
      {"format.ply", "ply\nformat utf8 1.0\nend_header\n", {"line 2", "unknown format 'utf8'"}},
      {"no_end.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz, {"no end_header"}},
      {"type.ply",
       ascii_ply(xyz + "property float128 w\n", list, 3, 1, verts + "3 0 1 2\n"),
       {"line 7", "unknown property type 'float128'"}},
      {"no_z.ply",
       ascii_ply("property float x\nproperty float y\n", list, 3, 1, "0 0\n1 0\n0 1\n3 0 1 2\n"),
       {"no 'z'"}},
      {"int_x.ply",
       ascii_ply("property int x\nproperty float y\nproperty float z\n", list, 3, 1,
                 verts + "3 0 1 2\n"),
       {"property 'x' must be float or double"}},
      {"ushort_list.ply",
       ascii_ply(xyz, "property list uchar ushort vertex_indices\n", 3, 1, verts + "3 0 1 2\n"),
       {"no 'vertex_indices' list of int or uint"}},
      {"uchar_259.ply",
       ascii_ply(xyz, list, 3, 1, verts + "259 0 1 2\n"),
       {"line 13", "'259' of property 'vertex_indices' is not a valid uchar"}},
      {"uint_minus.ply",
       ascii_ply(xyz, "property list uchar uint vertex_indices\n", 3, 1, verts + "3 0 -1 2\n"),
       {"'-1' of property 'vertex_indices' is not a valid uint"}},
      {"negative.ply",
       ascii_ply(xyz, list, 3, 1, verts + "3 0 -1 2\n"),
       {"face 0 has a negative vertex index -1"}},
      {"range.ply",
       ascii_ply(xyz, list, 3, 1, verts + "3 0 1 3\n"),
       {"face 0 references vertex 3, out of range [0, 3)"}},
      {"nan.ply",
       ascii_ply(xyz, list, 3, 1, "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
       {"line 11", "vertex 1 has a non-finite coordinate 'nan'"}},
      {"float_overflow.ply",
       ascii_ply(xyz, list, 3, 1, "0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n"),
       {"vertex 1 has a non-finite coordinate '1e39'"}},
      {"word.ply",
       ascii_ply(xyz, list, 3, 1, "0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n"),
       {"vertex 1: non-numeric token 'zero'"}},
      {"two_gon.ply",
       ascii_ply(xyz, list, 3, 1, verts + "2 0 1\n"),
       {"no faces left", "1 with fewer than 3 vertices"}},
      {"trailing.ply",
       ascii_ply(xyz, list, 3, 1, verts + "3 0 1 2\n3 0 1 2\n"),
       {"line 14", "data '3' after the last element", "wrong counts"}},
      {"trailing_binary.ply", trailing.s, {"5 bytes after the last element", "wrong counts"}},
      {"giant_list.ply",
       ascii_ply(xyz, "property list int int vertex_indices\n", 3, 1, verts + "1000000000 0 1 2\n"),
       {"truncated PLY data", "face 0 of 1"}},
      {"truncated_ascii.ply",
       ascii_ply(xyz, list, 3, 2, verts + "3 0 1 2\n3 0 1\n"),
       {"truncated PLY data", "face 1 of 2"}},
      {"absurd.ply",
       ascii_ply(xyz, list, 1000000000000ULL, 1, verts + "3 0 1 2\n"),
       {"1000000000000 'vertex'", "more than the 26-byte data section can hold"}},
      {"nan_binary.ply", nan.s, {"vertex 1 has a non-finite coordinate"}},
      {"huge_list.ply", huge_list.s, {"truncated PLY data", "face 0 of 1"}},
      {"negative_binary.ply", negative.s, {"face 0 has a negative vertex index -2"}},
      {"truncated_binary.ply", truncated, {"truncated PLY data", "face 0 of 1"}},
  };
  expect_errors(cases);
}

// ---- dropped faces, skipped vertices ----------------------------------------------------------

// The tetrahedron of kTetBody with outward faces.
const char* const kTetFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

TEST_F(MeshIo, FacesWithFewVerticesOrRepeatedIndicesAreDroppedAndCounted) {
  FaceMatrix tet(4, 3);
  tet << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  // OFF: a 2-gon, an empty face, a 1-gon with a color, a triangle and a quad repeating a vertex.
  const std::string off =
      file("d.off", "OFF\n4 9 0\n" + std::string(kTetBody) + "2 0 1\n" +
                        "3 0 2 1\n0\n1 3 7\n3 0 1 3\n3 2 2 3\n3 0 3 2\n" + "4 0 1 2 1\n3 1 2 3\n");
  // OBJ: a lone "f", a 2-gon, a repeated index written two ways (1 and -4 are vertex 0).
  const std::string obj = file("d.obj",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf\nf 1 3 2\nf 1 2\n"
                               "f 1 2 4\nf 1 4 -4\nf 1 4 3\nf 2 3 4\n");
  // ASCII PLY: a 0-gon and a repeated index.
  const std::string ply =
      file("d.ply",
           ascii_ply("property double x\nproperty double y\nproperty double z\n",
                     "property list uchar int vertex_indices\n", 4, 6,
                     std::string(kTetBody) + "0\n3 0 2 1\n3 0 1 3\n3 3 3 3\n3 0 3 2\n3 1 2 3\n"));
  // Binary PLY: a 1-gon and a repeated index.
  Bytes bin;
  bin.s =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\n"
      "property double y\nproperty double z\nelement face 6\n"
      "property list uchar int vertex_indices\nend_header\n";
  const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& x : xyz) bin.le(x[0]).le(x[1]).le(x[2]);
  bin.le(std::uint8_t{1}).le(2);
  for (int f = 0; f < 4; ++f) {
    bin.le(std::uint8_t{3}).le(tet(f, 0)).le(tet(f, 1)).le(tet(f, 2));
    if (f == 1) bin.le(std::uint8_t{3}).le(0).le(2).le(0);
  }
  bin.s += "\n";  // a trailing newline is harmless
  const std::string binary = file("b.ply", bin.s);

  struct Expected {
    std::string path;
    int few, repeated;
  } cases[] = {{off, 3, 2}, {obj, 2, 1}, {ply, 1, 1}, {binary, 1, 1}};
  for (const Expected& c : cases) {
    SCOPED_TRACE(c.path);
    MeshReadReport report;
    const Mesh m = read_mesh(c.path, &report);
    EXPECT_EQ(m.faces(), tet);
    EXPECT_EQ(m.num_vertices(), 4);
    EXPECT_EQ(report.polygons_read, 4);
    EXPECT_EQ(report.triangles, 4);
    EXPECT_EQ(report.faces_with_few_vertices, c.few);
    EXPECT_EQ(report.faces_with_repeated_index, c.repeated);
    EXPECT_EQ(report.faces_dropped(), c.few + c.repeated);
    EXPECT_EQ(report.vertices_skipped, 0);
    EXPECT_TRUE(report.source_vertex.empty());
    const std::vector<std::string> w = read_warnings(c.path, report);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], c.path + ": dropped " + std::to_string(c.few + c.repeated) + " faces (" +
                        std::to_string(c.few) + " with fewer than 3 vertices, " +
                        std::to_string(c.repeated) + " with a repeated vertex index)");
  }
  // Many empty faces: shorter than a triangle line, but not a truncated file.
  MeshReadReport empty_faces;
  const Mesh e = read_mesh(file("e.off", "OFF\n3 5 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0\n0\n0\n0\n"),
                           &empty_faces);
  EXPECT_EQ(e.num_faces(), 1);
  EXPECT_EQ(empty_faces.faces_with_few_vertices, 4);
  // A clean file has no warnings.
  MeshReadReport clean;
  read_mesh(file("clean.off", "OFF\n4 4 0\n" + std::string(kTetBody) + kTetFaces), &clean);
  EXPECT_EQ(clean.faces_dropped(), 0);
  EXPECT_TRUE(read_warnings("clean.off", clean).empty());
}

TEST_F(MeshIo, NonFiniteCoordinatesAreRefusedOrSkipped) {
  // Vertex 1 is NaN (or Inf); faces 0, 1 and 3 of the tetrahedron use it, face 2 (0 3 2) not.
  const std::string off =
      file("n.off", "OFF\n4 4 0\n0 0 0\n1 nan 0\n0 1 0\n0 0 1\n" + std::string(kTetFaces));
  const std::string obj = file("n.obj",
                               "v 0 0 0\nv -inf 0 0\nv 0 1 0\nv 0 0 1\n"
                               "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const std::string ply =
      file("n.ply", ascii_ply("property float x\nproperty float y\nproperty float z\n",
                              "property list uchar int vertex_indices\n", 4, 4,
                              "0 0 0\n1 1e39 0\n0 1 0\n0 0 1\n" + std::string(kTetFaces)));
  Bytes bin;
  bin.s =
      "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\n"
      "property double y\nproperty double z\nelement face 4\n"
      "property list uchar int vertex_indices\nend_header\n";
  const double inf = std::numeric_limits<double>::infinity();
  const double xyz[4][3] = {{0, 0, 0}, {1, 0, inf}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& x : xyz) bin.be(x[0]).be(x[1]).be(x[2]);
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) bin.be(std::uint8_t{3}).be(f[0]).be(f[1]).be(f[2]);
  const std::string binary = file("n_binary.ply", bin.s);

  for (const std::string& p : {off, obj, ply, binary}) {
    SCOPED_TRACE(p);
    expect_read_error(p, {"vertex 1 has a non-finite coordinate", "--skip-invalid"});
    MeshReadReport report;
    MeshReadOptions options;
    options.skip_invalid = true;
    const Mesh m = read_mesh(p, &report, options);
    ASSERT_EQ(m.num_vertices(), 3);
    ASSERT_EQ(m.num_faces(), 1);
    // Renumbered in file order: 0 -> 0, 2 -> 1, 3 -> 2; face (0 3 2) becomes (0 2 1).
    EXPECT_EQ(m.face_vertex(0, 0), 0);
    EXPECT_EQ(m.face_vertex(0, 1), 2);
    EXPECT_EQ(m.face_vertex(0, 2), 1);
    EXPECT_EQ(m.vertices()(1, 1), 1.0);
    EXPECT_EQ(m.vertices()(2, 2), 1.0);
    EXPECT_EQ(report.vertices_in_file, 4);
    EXPECT_EQ(report.vertices_skipped, 1);
    EXPECT_EQ(report.faces_skipped, 3);
    EXPECT_EQ(report.polygons_read, 1);
    EXPECT_EQ(report.skipped_vertices, std::vector<int>{1});
    EXPECT_EQ(report.source_vertex, (std::vector<int>{0, 2, 3}));
    const std::vector<std::string> w = read_warnings(p, report);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], p + ": skipped 1 vertex with a NaN/Inf coordinate (file vertex 1) and the 3 "
                        "faces using it; 3 of 4 vertices kept, renumbered in file order");
  }

  // Every face uses a skipped vertex, or every vertex is skipped: an empty mesh is an error.
  MeshReadOptions skip;
  skip.skip_invalid = true;
  // Many skipped vertices: the warning lists the first five.
  std::string many = "OFF\n9 2 0\n0 0 0\n1 0 0\n0 1 0\n";
  for (int i = 0; i < 6; ++i) many += "nan 0 0\n";
  MeshReadReport many_report;
  const std::string many_path = file("many.off", many + "3 0 1 2\n3 3 4 5\n");
  EXPECT_EQ(read_mesh(many_path, &many_report, skip).num_vertices(), 3);
  EXPECT_EQ(read_warnings(many_path, many_report),
            std::vector<std::string>{many_path +
                                     ": skipped 6 vertices with a NaN/Inf coordinate (file vertex "
                                     "3, 4, 5, 6, 7, ...) and the 1 face using them; 3 of 9 "
                                     "vertices kept, renumbered in file order"});
  const std::string all_faces =
      file("all_faces.off", "OFF\n4 1 0\n0 0 0\n1 nan 0\n0 1 0\n0 0 1\n3 0 1 2\n");
  try {
    read_mesh(all_faces, nullptr, skip);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no faces left after dropping all 1 (1 using a NaN/Inf "
                                         "vertex)"),
              std::string::npos)
        << e.what();
  }
  const std::string all_vertices =
      file("all_vertices.obj", "v nan 0 0\nv 1 inf 0\nv 0 1 -inf\nf 1 2 3\n");
  try {
    read_mesh(all_vertices, nullptr, skip);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("all 3 vertices have a non-finite coordinate"),
              std::string::npos)
        << e.what();
  }
  // A non-finite normal is still an error with skip_invalid (it is not a coordinate).
  try {
    read_mesh(file("normal.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 nan 1\n0 1 0 0 0 1\n3 0 1 2\n"),
              nullptr, skip);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 1 has a non-finite value 'nan'"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(MeshIo, WrittenCommentsAreSkippedByTheReader) {
  const Mesh m = awkward_tetrahedron();
  const std::vector<std::string> comments = {"first: 3 of 4", "second"};
  write_mesh(path("c.off"), m, {}, comments);
  write_mesh(path("c.ply"), m, {{"k", {1, 2, 3, 4}, false}}, comments);
  EXPECT_EQ(slurp(path("c.off")).rfind("OFF\n# first: 3 of 4\n# second\n4 4 0\n", 0), 0u);
  EXPECT_NE(slurp(path("c.ply")).find("comment first: 3 of 4\ncomment second\n"),
            std::string::npos);
  expect_bit_identical_mesh(read_mesh(path("c.off")), m);
  expect_bit_identical_mesh(read_mesh(path("c.ply")), m);
  EXPECT_THROW(write_mesh(path("d.off"), m, {}, {"two\nlines"}), UsageError);
  EXPECT_EQ(listing(), (std::vector<std::string>{"c.off", "c.ply"}));
}

// The fuzz seed corpus and the inputs that once crashed a reader (tests/corpus/): every file is
// either read or refused with an InputError, never anything else; the "broken_" files are
// refused, the others read (the "defect_" ones with a warning: a face dropped, or an OBJ cut
// after a whole line, which has no counts to tell). Under `make test-sanitize` this also replays
// the fuzz regressions with ASan/UBSan (e.g. a color-map index 1e300 that CGAL's OFF scanner cast
// to int).
TEST(MeshIoCorpus, SeedsReadOrRefuseCleanlyAndRegressionsStayFixed) {
  const fs::path corpus = fs::path(CURVBENCH_SOURCE_DIR) / "tests" / "corpus";
  int read = 0, refused = 0;
  for (const char* folder : {"off", "obj", "ply", "regressions"}) {
    for (const auto& entry : fs::directory_iterator(corpus / folder)) {
      const std::string path = entry.path().string();
      const bool broken = entry.path().filename().string().starts_with("broken_");
      try {
        const Mesh mesh = read_mesh(path);
        EXPECT_FALSE(broken) << path << " was read";
        EXPECT_GT(mesh.num_faces(), 0) << path;
        ++read;
      } catch (const InputError& e) {
        EXPECT_TRUE(broken || std::string(folder) == "regressions") << path << ": " << e.what();
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        ++refused;
      }
    }
  }
  EXPECT_GE(read, 20);
  EXPECT_GE(refused, 20);
}

}  // namespace
}  // namespace curvbench

namespace curvbench {
namespace {

// The binary PLY reader copies runs of triangles a window at a time and hands the first record
// that is not a valid triangle to the per-face path: a strip of 10000 triangles with a quad at
// face 9000 reads as the same mesh from little- and big-endian binary and from ASCII; a bad index
// or a truncation past the first windows is reported at its face, as on the per-face path.
TEST_F(MeshIo, BinaryPlyTriangleRunsThenOtherFaces) {
  constexpr int kColumns = 5002, kFaces = 10000;  // a strip 2 x kColumns, kFaces triangles
  const int n = 2 * kColumns;
  const auto header = [&](const char* format, int faces) {
    return std::string("ply\nformat ") + format + " 1.0\nelement vertex " + std::to_string(n) +
           "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
           std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
  };
  // Faces: triangles (i, i + 1, i + 2) alternating orientation along the strip, except face 9000,
  // a quad, and 9001, dropped to keep the count.
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < kFaces; ++f) {
    const int c = f / 2;
    if (f == 9001) continue;
    if (f == 9000)
      faces.push_back({2 * c, 2 * c + 2, 2 * c + 3, 2 * c + 1});
    else if (f % 2 == 0)
      faces.push_back({2 * c, 2 * c + 2, 2 * c + 1});
    else
      faces.push_back({2 * c + 1, 2 * c + 2, 2 * c + 3});
  }
  const int count = static_cast<int>(faces.size());
  Bytes le, be;
  std::string ascii = header("ascii", count);
  le.s = header("binary_little_endian", count);
  be.s = header("binary_big_endian", count);
  for (int v = 0; v < n; ++v) {
    const double x = v / 2, y = v % 2, z = 0.25 * (v % 7);
    le.le(x).le(y).le(z);
    be.be(x).be(y).be(z);
    ascii += std::to_string(v / 2) + " " + std::to_string(v % 2) + " " +
             std::to_string(0.25 * (v % 7)) + "\n";
  }
  for (const auto& face : faces) {
    le.le(static_cast<std::uint8_t>(face.size()));
    be.be(static_cast<std::uint8_t>(face.size()));
    ascii += std::to_string(face.size());
    for (const int i : face) {
      le.le(static_cast<std::int32_t>(i));
      be.be(static_cast<std::int32_t>(i));
      ascii += " " + std::to_string(i);
    }
    ascii += "\n";
  }
  const Mesh a = read_mesh(file("a.ply", ascii));
  const Mesh l = read_mesh(file("le.ply", le.s));
  const Mesh b = read_mesh(file("be.ply", be.s));
  EXPECT_EQ(a.num_faces(), kFaces);  // the quad fan-triangulated
  EXPECT_EQ(l.faces(), a.faces());
  EXPECT_EQ(b.faces(), a.faces());
  EXPECT_EQ(l.vertices(), a.vertices());
  EXPECT_EQ(b.vertices(), a.vertices());

  // A bad index in face 7000, and a file cut in face 8000 (after the first windows).
  const std::size_t body = header("binary_little_endian", count).size() + 24 * std::size_t(n);
  std::string bad = le.s;
  const std::int32_t out_of_range = n + 5, negative = -7;
  std::memcpy(bad.data() + body + 13 * 7000 + 5, &out_of_range, 4);
  std::string neg = le.s;
  std::memcpy(neg.data() + body + 13 * 7000 + 9, &negative, 4);
  expect_errors({
      {"range.ply", bad, {"face 7000 references vertex " + std::to_string(n + 5)}},
      {"negative.ply", neg, {"face 7000 has a negative vertex index -7"}},
  });
  std::string cut = le.s.substr(0, body + 13 * 8000 + 6);
  cut.replace(cut.find("element face " + std::to_string(count)),
              std::string("element face " + std::to_string(count)).size(), "element face 8001");
  expect_errors({{"cut.ply", cut, {"truncated PLY data", "face 8000 of 8001"}}});
}

}  // namespace
}  // namespace curvbench
