// Hostile input for `curvbench info` and `curvbench estimate` (docs/robustness.md): one case
// per kind of bad input. Refused input: exit code 2, one line "curvbench: error: FILE: ..."
// naming the line or element and the problem, no output file (or temporary) left behind.
// Defective but readable meshes: the run completes (exit 0), `info` reports the defect's count,
// and in the estimate's CSV a vertex with status failed/excluded has NaN in every value while
// every other vertex has finite values and a unit normal. Nothing may crash (exit code 1 or a
// signal) in any case.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::fresh_dir;
using testing::run_cli;

// ---- building meshes ---------------------------------------------------------------------------

/// A polygon soup written as OFF (indices may be anything; nothing is validated here).
struct Soup {
  std::vector<std::array<double, 3>> v;
  std::vector<std::vector<long long>> f;

  int vertex(double x, double y, double z) {
    v.push_back({x, y, z});
    return static_cast<int>(v.size()) - 1;
  }

  /// n x n grid over [x0, x0 + 2] x [-1, 1] on z = 0.25 (x'^2 - 0.5 y^2), x' = x - x0 - 1,
  /// triangulated ccw from +z. Returns the index of its first vertex; vertex (i, j) is
  /// first + i * n + j (i along x).
  int grid(int n, double x0 = -1.0) {
    const int first = static_cast<int>(v.size());
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double x = -1.0 + 2.0 * i / (n - 1), y = -1.0 + 2.0 * j / (n - 1);
        vertex(x0 + 1.0 + x, y, 0.25 * (x * x - 0.5 * y * y));
      }
    for (int i = 0; i + 1 < n; ++i)
      for (int j = 0; j + 1 < n; ++j) {
        const long long a = first + i * n + j;
        f.push_back({a, a + n, a + n + 1});
        f.push_back({a, a + n + 1, a + 1});
      }
    return first;
  }

  /// On a 5 x 5 grid(): two zero-area faces, one flat (a triangle on boundary edge 0 -> 5, y = -1,
  /// whose third vertex is the edge midpoint) and one collapsed to a point (on vertex 12 and two
  /// duplicates of it).
  void add_zero_area_faces() {
    const int m = vertex(0.5 * (v[0][0] + v[5][0]), -1.0, 0.5 * (v[0][2] + v[5][2]));
    f.push_back({5, 0, m});
    const int d1 = vertex(v[12][0], v[12][1], v[12][2]);
    const int d2 = vertex(v[12][0], v[12][1], v[12][2]);
    f.push_back({12, d1, d2});
  }

  std::string off() const {
    std::ostringstream s;
    s.precision(17);
    s << "OFF\n" << v.size() << " " << f.size() << " 0\n";
    for (const auto& p : v) s << p[0] << " " << p[1] << " " << p[2] << "\n";
    for (const auto& face : f) {
      s << face.size();
      for (const long long i : face) s << " " << i;
      s << "\n";
    }
    return s.str();
  }
};

// ---- running -----------------------------------------------------------------------------------

class CliHostile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(std::string("hostile_") +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(dir_ / name, std::ios::binary) << content;
    return (dir_ / name).string();
  }

  std::set<std::string> listing() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.insert(e.path().filename().string());
    return names;
  }

  /// Runs and checks that nothing crashed.
  static CliResult run(const std::string& args) {
    const CliResult r = run_cli(args);
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 2) << args << "\n" << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << args << "\n" << r.output;
    return r;
  }

  /// `info` and `estimate` (CSV and PLY output) must refuse `path`: exit 2, one line naming the
  /// file and containing every part, no file written.
  void expect_refused(const std::string& path, const std::vector<std::string>& parts,
                      const std::string& options = "") const {
    const std::set<std::string> before = listing();
    const std::string commands[] = {
        "info " + options + " " + path,
        "estimate " + options + " " + path + " --method lhf-2 --output " +
            (dir_ / "o.csv").string(),
        "estimate " + options + " " + path + " --method lhf-2 --output " +
            (dir_ / "o.ply").string(),
    };
    for (const std::string& c : commands) {
      SCOPED_TRACE(c);
      const CliResult r = run(c);
      EXPECT_EQ(r.exit_code, 2) << r.output;
      EXPECT_EQ(r.output.rfind("curvbench: error: " + path + ": ", 0), 0u) << r.output;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
      for (const std::string& p : parts)
        EXPECT_NE(r.output.find(p), std::string::npos) << "missing '" << p << "' in " << r.output;
      EXPECT_EQ(listing(), before) << "a file was left behind";
    }
  }

  /// `info` on `path` must succeed; returns its output (stdout and stderr).
  std::string info(const std::string& path, const std::string& options = "") const {
    const CliResult r = run("info " + options + " " + path);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return r.output;
  }

  struct Rows {
    std::vector<std::string> vertex;  // the "vertex" column
    std::vector<std::string> status;
    std::string output;  // of the run
  };

  /// `estimate --method method` on `path` must succeed; checks every CSV row: failed/excluded
  /// rows have NaN in all 13 values, the others finite values and a unit normal.
  Rows estimate(const std::string& path, const std::string& method,
                const std::string& options = "") const {
    const fs::path out = dir_ / ("est_" + method + ".csv");
    const CliResult r = run("estimate " + options + " " + path + " --method " + method +
                            " --output " + out.string());
    Rows rows;
    rows.output = r.output;
    EXPECT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(out);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::vector<std::string> cells;
      std::stringstream ss(line);
      std::string cell;
      while (std::getline(ss, cell, ',')) cells.push_back(cell);
      if (cells.size() != 17) {
        ADD_FAILURE() << method << ": bad row " << line;
        continue;
      }
      rows.vertex.push_back(cells[0]);
      rows.status.push_back(cells[16]);
      const bool none = cells[16] == "failed" || cells[16] == "excluded";
      double n2 = 0.0;
      for (int c = 1; c <= 13; ++c) {
        double x = 0.0;
        const auto [ptr, ec] =
            std::from_chars(cells[c].data(), cells[c].data() + cells[c].size(), x);
        const bool parsed = ec == std::errc() && ptr == cells[c].data() + cells[c].size();
        if (none) {
          EXPECT_EQ(cells[c], "nan") << method << " " << path << ": row " << line;
        } else {
          EXPECT_TRUE(parsed && std::isfinite(x)) << method << " " << path << ": row " << line;
          if (c <= 3) n2 += x * x;
        }
      }
      if (!none) {
        EXPECT_NEAR(n2, 1.0, 1e-9) << method << " " << path << ": row " << line;
      }
    }
    return rows;
  }

  /// estimate() with LHF-2, Xu and jet fitting; returns LHF-2's rows.
  Rows estimate_all(const std::string& path, const std::string& options = "") const {
    const Rows lhf = estimate(path, "lhf-2", options);
    for (const char* m : {"xu", "jet"}) {
      const Rows r = estimate(path, m, options);
      EXPECT_EQ(r.status.size(), lhf.status.size()) << m;
    }
    return lhf;
  }

  fs::path dir_;
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

int count(const std::vector<std::string>& v, const std::string& x) {
  return static_cast<int>(std::count(v.begin(), v.end(), x));
}

const char* const kTet = "0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n0.0 0.0 1.0\n";
const char* const kTetFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

// ---- refused input -----------------------------------------------------------------------------

TEST_F(CliHostile, MissingOrUnreadableFile) {
  expect_refused((dir_ / "missing.off").string(), {"no such file"});
  fs::create_directory(dir_ / "folder.off");
  expect_refused((dir_ / "folder.off").string(), {"is a directory"});
  const std::string locked = write("locked.off", std::string("OFF\n4 4 0\n") + kTet + kTetFaces);
  fs::permissions(locked, fs::perms::none);
  if (::geteuid() != 0)  // root reads it anyway
    expect_refused(locked, {"cannot read file", "Permission denied"});
}

TEST_F(CliHostile, UnknownExtension) {
  expect_refused(write("mesh.stl", "solid x\nendsolid x\n"), {"unknown extension '.stl'"});
  expect_refused(write("mesh", "OFF\n"), {"no file extension"});
}

TEST_F(CliHostile, TruncatedOrMalformedHeader) {
  const std::string tet = std::string(kTet) + kTetFaces;
  expect_refused(write("empty.off", ""), {"bad OFF header", "empty"});
  expect_refused(write("keyword_only.off", "OFF\n"), {"no vertex/face/edge counts"});
  expect_refused(write("keyword.off", "OFX\n4 4 0\n" + tet), {"line 1", "'OFX'"});
  expect_refused(write("counts.off", "OFF\n4 4\n" + tet), {"line 2", "expected 3 counts"});
  expect_refused(write("header.ply", "ply\nformat ascii 1.0\nelement vertex 4\n"),
                 {"no end_header"});
  expect_refused(write("format.ply", "ply\nformat utf8 1.0\nend_header\n"),
                 {"line 2", "unknown format 'utf8'"});
}

TEST_F(CliHostile, TruncatedOrMalformedBody) {
  expect_refused(write("cut.off", std::string("OFF\n4 4 0\n") + kTet + "3 0 2 1\n3 0 1"),
                 {"truncated OFF body", "the file ends inside face 1 (line 8)"});
  expect_refused(write("short.off", std::string("OFF\n4 4 0\n") + kTet + "3 0 2 1\n"),
                 {"truncated OFF body", "after 1 of 4 faces"});
  expect_refused(
      write("bad_vertex.off", "OFF\n4 4 0\n0.0 0.0 0.0\n1.0 0.0\n0.0 1.0 0.0\n0.0 0.0 1.0\n" +
                                  std::string(kTetFaces)),
      {"line 4", "vertex 1 has 2 numbers"});
  expect_refused(write("cut.obj", "v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n"),
                 {"line 3", "vertex 2 has 2 coordinates"});
}

TEST_F(CliHostile, WrongCounts) {
  expect_refused(write("more_faces.off", std::string("OFF\n4 3 0\n") + kTet + kTetFaces),
                 {"line 10", "data after the last of the 4 vertices and 3 faces", "wrong counts"});
  expect_refused(write("fewer_vertices.off", std::string("OFF\n3 4 0\n") + kTet + kTetFaces),
                 {"line 6", "face 0", "declares 3 vertices: wrong counts"});
  expect_refused(write("more_vertices.off", std::string("OFF\n5 4 0\n") + kTet + kTetFaces),
                 {"truncated OFF body", "after 3 of 4 faces"});
  expect_refused(
      write("counts.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n"),
      // The 4th vertex line is read as face 0: a 0-gon "0" followed by "0 1".
      {"line 13", "data '0' after the last element", "wrong counts"});
}

TEST_F(CliHostile, IndexOutOfRange) {
  expect_refused(write("range.off", std::string("OFF\n4 4 0\n") + kTet + "3 0 2 1\n3 0 1 4\n" +
                                        "3 0 3 2\n3 1 2 3\n"),
                 {"line 8", "face 1 references vertex 4, out of range [0, 4)"});
  expect_refused(write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 9\n"),
                 {"line 5", "face 1 references vertex 9 (1-based), but the file has 3 vertices"});
}

TEST_F(CliHostile, NegativeIndex) {
  expect_refused(write("negative.off", std::string("OFF\n4 4 0\n") + kTet + "3 0 2 1\n3 0 -1 3\n" +
                                           "3 0 3 2\n3 1 2 3\n"),
                 {"line 8", "face 1 has a negative vertex index -1"});
  expect_refused(write("negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -5\n"),
                 {"line 4", "relative vertex index -5 refers before the first vertex"});
}

TEST_F(CliHostile, NonNumericToken) {
  expect_refused(
      write("word.off", "OFF\n4 4 0\n0 0 0\n1 zero 0\n0 1 0\n0 0 1\n" + std::string(kTetFaces)),
      {"line 4", "vertex 1: non-numeric token 'zero'"});
  expect_refused(write("index.off", std::string("OFF\n4 4 0\n") + kTet + "3 0 2 x\n" +
                                        "3 0 1 3\n3 0 3 2\n3 1 2 3\n"),
                 {"line 7", "face 0: vertex index 'x' is not an integer"});
  expect_refused(write("count.off", std::string("OFF\nfour 4 0\n") + kTet + kTetFaces),
                 {"line 2", "vertex count 'four'"});
}

// NaN or Inf at the centre (vertex 12) of a 5 x 5 grid: refused, or with --skip-invalid dropped
// with its 6 faces; the output has the other 24 vertices with their file indices.
TEST_F(CliHostile, NanOrInfCoordinates) {
  for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
    SCOPED_TRACE(bad);
    Soup s;
    s.grid(5);
    std::string text = s.off();
    // Vertex 12 is line 15 of the file; replace its z.
    std::istringstream in(text);
    std::string line, out;
    for (int n = 1; std::getline(in, line); ++n)
      out += (n == 15 ? "0 0 " + std::string(bad) : line) + "\n";
    const std::string p = write(std::string("grid_") + bad + ".off", out);
    expect_refused(p,
                   {"line 15", "vertex 12 has a non-finite coordinate '" + std::string(bad) + "'",
                    "--skip-invalid"});

    const std::string text_info = info(p, "--skip-invalid");
    EXPECT_TRUE(contains(text_info,
                         "vertices:              24 (24 of 25 in the file; 1 with a "
                         "NaN/Inf coordinate skipped)"))
        << text_info;
    EXPECT_TRUE(contains(text_info, "faces:                 26\n")) << text_info;
    EXPECT_TRUE(contains(text_info, "boundary loops:        2\n")) << text_info;  // a hole now
    EXPECT_TRUE(contains(text_info, "curvbench: warning: " + p +
                                        ": skipped 1 vertex with a NaN/Inf coordinate (file vertex "
                                        "12) and the 6 faces using it"))
        << text_info;
    const Rows rows = estimate_all(p, "--skip-invalid");
    ASSERT_EQ(rows.vertex.size(), 24u);
    EXPECT_EQ(rows.vertex[11], "11");
    EXPECT_EQ(rows.vertex[12], "13");  // file index, not row index
    EXPECT_EQ(rows.vertex[23], "24");
    EXPECT_TRUE(contains(rows.output, "skipped 1 vertex")) << rows.output;
  }
  // PLY output carries the file index and says so in its header.
  Soup s;
  s.grid(5);
  s.v[3][0] = std::numeric_limits<double>::quiet_NaN();
  const std::string p = write("nan3.off", s.off());
  const fs::path ply = dir_ / "out.ply";
  ASSERT_EQ(
      run("estimate --skip-invalid " + p + " --method lhf-2 --output " + ply.string()).exit_code,
      0);
  std::ifstream in(ply, std::ios::binary);
  const std::string head((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(contains(head,
                       "comment --skip-invalid: 1 of 25 input vertices (NaN/Inf "
                       "coordinates) and 3 faces dropped; source_vertex = index in the "
                       "input file\n"))
      << head.substr(0, 600);
  EXPECT_TRUE(contains(head, "property int source_vertex\n"));
  EXPECT_TRUE(contains(head, "element vertex 24\n"));
}

// ---- repaired input ----------------------------------------------------------------------------

TEST_F(CliHostile, PolygonsAreFanTriangulated) {
  // A 3 x 3 grid of quads, one written as a pentagon with a midpoint on an edge, as OBJ.
  std::string obj;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      obj += "v " + std::to_string(i) + " " + std::to_string(j) + " " +
             std::to_string(0.1 * (i * i - j * j)) + "\n";
  obj += "v 0.5 0 -0.025\n";  // 17: on edge 1-5 (0-based 0-4)
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int a = 1 + 4 * i + j;
      if (i == 0 && j == 0)
        obj += "f 1 17 5 6 2\n";
      else
        obj += "f " + std::to_string(a) + " " + std::to_string(a + 4) + " " +
               std::to_string(a + 5) + " " + std::to_string(a + 1) + "\n";
    }
  const std::string p = write("quads.obj", obj);
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "faces:                 19 (9 polygons fan-triangulated)")) << text;
  EXPECT_TRUE(contains(text, "polygons triangulated: 9\n")) << text;
  const Rows rows = estimate_all(p);
  EXPECT_EQ(rows.status.size(), 17u);
}

TEST_F(CliHostile, DegenerateAndRepeatedFacesAreDroppedWithAWarning) {
  Soup s;
  s.grid(5);
  s.f.push_back({0, 1});        // 2-gon
  s.f.push_back({});            // 0-gon
  s.f.push_back({3, 3, 4});     // repeated index
  s.f.push_back({5, 6, 7, 6});  // repeated, not adjacent
  const std::string p = write("degenerate.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "curvbench: warning: " + p +
                                 ": dropped 4 faces (2 with fewer than 3 vertices, 2 with a "
                                 "repeated vertex index)\n"))
      << text;
  EXPECT_TRUE(contains(text,
                       "faces dropped:         4 (2 with fewer than 3 vertices, 2 with a "
                       "repeated vertex index, 0 using a skipped vertex)"))
      << text;
  EXPECT_TRUE(contains(text, "faces:                 32\n")) << text;
  const Rows rows = estimate_all(p);
  EXPECT_EQ(count(rows.status, "ok"), 25);
  EXPECT_TRUE(contains(rows.output, "dropped 4 faces")) << rows.output;
}

// ---- defective meshes: the run completes
// ---------------------------------------------------------

TEST_F(CliHostile, ZeroAreaFaces) {
  Soup s;
  s.grid(5);
  s.add_zero_area_faces();
  const std::string p = write("zero_area.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "zero-area faces:       2\n")) << text;
  EXPECT_TRUE(contains(text, "duplicate vertices:    2\n")) << text;
  estimate_all(p);
}

TEST_F(CliHostile, DuplicateVertices) {
  // Two 5 x 5 grids side by side: the seam column exists twice (5 duplicate vertices).
  Soup s;
  s.grid(5, -1.0);
  s.grid(5, 1.0);
  const std::string p = write("seam.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "duplicate vertices:    5\n")) << text;
  EXPECT_TRUE(contains(text, "components:            2\n")) << text;
  const Rows rows = estimate_all(p);
  EXPECT_EQ(count(rows.status, "ok"), 50);
}

TEST_F(CliHostile, DuplicateFaces) {
  Soup s;
  s.grid(5);
  s.f.push_back(s.f[10]);                               // same orientation
  s.f.push_back({s.f[20][2], s.f[20][1], s.f[20][0]});  // reversed
  const std::string p = write("dup_faces.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "duplicate faces:       2\n")) << text;
  EXPECT_TRUE(contains(text, "non-manifold edges:    6\n")) << text;
  estimate_all(p);
}

TEST_F(CliHostile, IsolatedVertices) {
  Soup s;
  s.grid(5);
  const int a = s.vertex(5, 5, 5);
  const int b = s.vertex(0, 0, 0.5);
  const std::string p = write("isolated.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "isolated vertices:     2\n")) << text;
  for (const char* m : {"lhf-2", "xu", "jet"}) {
    const Rows rows = estimate(p, m);
    ASSERT_EQ(rows.status.size(), 27u);
    for (const int v : {a, b})
      EXPECT_TRUE(rows.status[v] == "failed" || rows.status[v] == "excluded")
          << m << " vertex " << v << ": " << rows.status[v];
  }
}

TEST_F(CliHostile, NonManifoldEdges) {
  // A fin standing on interior edge 6-12 (shared by two grid faces) and a second one on the
  // same edge: edge 6-12 has four faces.
  Soup s;
  s.grid(5);
  const int t1 = s.vertex(s.v[6][0], s.v[6][1], 1.0);
  const int t2 = s.vertex(s.v[12][0], s.v[12][1], -1.0);
  s.f.push_back({6, 12, t1});
  s.f.push_back({12, 6, t2});
  const std::string p = write("fin.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "non-manifold edges:    1\n")) << text;
  EXPECT_TRUE(contains(text, "non-manifold vertices: 2\n")) << text;
  estimate_all(p);
}

TEST_F(CliHostile, NonManifoldVertices) {
  // Bow ties: a triangle touching grid corner 0 only, and one touching interior vertex 12 only.
  Soup s;
  s.grid(5);
  const int a = s.vertex(-2, -1, 0), b = s.vertex(-2, -2, 0);
  s.f.push_back({0, a, b});
  const int c = s.vertex(0, 0, 1), d = s.vertex(0.5, 0, 1);
  s.f.push_back({12, c, d});
  const std::string p = write("bowtie.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "non-manifold vertices: 2\n")) << text;
  EXPECT_TRUE(contains(text, "non-manifold edges:    0\n")) << text;
  EXPECT_TRUE(contains(text, "components:            1\n")) << text;
  estimate_all(p);
}

TEST_F(CliHostile, SeveralComponents) {
  Soup s;
  s.grid(5, -1.0);
  s.grid(4, 3.0);
  const int a = s.vertex(10, 0, 0), b = s.vertex(11, 0, 0), c = s.vertex(10, 1, 0);
  s.f.push_back({a, b, c});  // a lone triangle: too few points for any fit
  const std::string p = write("pieces.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "components:            3\n")) << text;
  const Rows rows = estimate_all(p);
  ASSERT_EQ(rows.status.size(), 44u);
  EXPECT_EQ(count(rows.status, "ok"), 41);
}

TEST_F(CliHostile, InconsistentOrientation) {
  Soup s;
  s.grid(5);
  for (const int f : {9, 10, 20}) std::swap(s.f[f][1], s.f[f][2]);
  const std::string p = write("flipped.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "orientation:           inconsistent (")) << text;
  estimate_all(p);
}

TEST_F(CliHostile, OpenBoundaries) {
  // A 6 x 6 grid with a hole: two interior faces removed (two boundary loops).
  Soup s;
  s.grid(6);
  s.f.erase(s.f.begin() + 24, s.f.begin() + 26);
  const std::string p = write("holes.off", s.off());
  const std::string text = info(p);
  EXPECT_TRUE(contains(text, "boundary loops:        2\n")) << text;
  EXPECT_TRUE(contains(text, "boundary edges:        24\n")) << text;
  estimate_all(p);
  // Xu excludes the boundary vertices (20 outer, 4 around the hole) and computes the others.
  const Rows xu = estimate(p, "xu");
  EXPECT_EQ(count(xu.status, "excluded"), 24);
  EXPECT_EQ(count(xu.status, "ok"), 12);
}

TEST_F(CliHostile, AllDefectsAtOnceEveryMethod) {
  // One mesh with a zero-area face, duplicate vertices, a bow tie, an isolated vertex, a lone
  // triangle, a fin on a non-manifold edge, a flipped face and an open boundary, through every
  // method: the contract (NaN exactly in failed/excluded rows) must hold for all of them.
  Soup s;
  s.grid(5);
  s.add_zero_area_faces();
  const int a = s.vertex(-2, -1, 0), b = s.vertex(-2, -2, 0);
  s.f.push_back({0, a, b});
  const int isolated = s.vertex(5, 5, 5);
  const int t = s.vertex(10, 0, 0);
  s.vertex(11, 0, 0);
  s.vertex(10, 1, 0);
  s.f.push_back({t, t + 1, t + 2});
  s.f.push_back({6, 12, s.vertex(s.v[6][0], s.v[6][1], 1.0)});
  std::swap(s.f[30][1], s.f[30][2]);
  const std::string p = write("sink.off", s.off());
  const std::string text = info(p);
  for (const char* line :
       {"zero-area faces:       2\n", "duplicate vertices:    2\n", "non-manifold edges:    1\n",
        "non-manifold vertices: 3\n", "isolated vertices:     1\n", "components:            2\n",
        "boundary loops:        3\n", "orientation:           inconsistent ("})
    EXPECT_TRUE(contains(text, line)) << line << "\n" << text;
  for (const char* method : {"lhf-2", "lhf-4", "lop-2", "xu", "lscm-2", "lscm-fast-2", "jet-2"}) {
    const Rows rows = estimate(p, method);
    ASSERT_EQ(rows.status.size(), 35u) << method;
    EXPECT_TRUE(rows.status[isolated] == "failed" || rows.status[isolated] == "excluded") << method;
  }
}

// ---- adversarial sizes -------------------------------------------------------------------------

TEST_F(CliHostile, HugeHeaderCounts) {
  const std::string tet = std::string(kTet) + kTetFaces;
  expect_refused(write("huge.off", "OFF\n1000000000000 4 0\n" + tet),
                 {"1000000000000 vertices", "more than a", "-byte file can hold"});
  expect_refused(write("huge_faces.off", "OFF\n4 2147483648 0\n" + tet),
                 {"2147483648 faces", "more than a"});
  expect_refused(write("huge.ply",
                       "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                       "property float x\nproperty float y\nproperty float z\nelement face 1\n"
                       "property list uchar int vertex_indices\nend_header\n" +
                           std::string(64, '\0')),
                 {"1000000000000 'vertex'", "more than the 64-byte data section can hold"});
}

TEST_F(CliHostile, GiantPolygon) {
  expect_refused(write("giant.off", std::string("OFF\n4 1 0\n") + kTet + "1000000000 0 1 2\n"),
                 {"line 7", "face 0 declares 1000000000 vertices but lists 3"});
  std::string bin =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uint int vertex_indices\nend_header\n" +
      std::string(36, '\0');
  const unsigned char len[4] = {0x00, 0xca, 0x9a, 0x3b};  // 10^9, little endian
  bin.append(reinterpret_cast<const char*>(len), 4);
  bin += std::string(12, '\0');
  expect_refused(write("giant.ply", bin), {"truncated PLY data", "face 0 of 1"});
}

}  // namespace
}  // namespace curvbench
