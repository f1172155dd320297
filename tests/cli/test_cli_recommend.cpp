// `curvbench recommend`: the three families' level-2 meshes classify as their quality classes, a
// given --noise picks the nearest level's row, the printed command runs as printed from another
// folder with the default table, `estimate --method auto` runs the same estimator, --format csv
// and json, and the one-line errors (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

#include "core/text.h"
#include "harness/model/mesh_features.h"
#include "harness/report/advice.h"
#include "mesh/io.h"
#include "tests/cli/cli_runner.h"
#include "tests/mesh/crease_test_meshes.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::fresh_dir;
using testing::run_cli;
using testing::slurp;

const std::string kCommitted = std::string(CURVBENCH_SOURCE_DIR) + "/results/recommendations.csv";
const std::string kBinary = std::string(CURVBENCH_BINARY_DIR) + "/curvbench";

// A recommendations.csv whose best case names its cell: LHF-2 for well-shaped, Jet-2 for
// isosurface, Quadric for irregular, rings 1, 3, 4 at sigma/h 0, 0.03, 0.1; 0.01 not swept.
void write_table(const fs::path& dir) {
  std::ofstream out(dir / "recommendations.csv");
  out << "# test table\nquality,sigma_over_h,status,experiment,family,level,vertices,h,noise,"
         "quantity,norm,cases,best_label,best_error,best_seconds,cheapest_label,cheapest_error,"
         "cheapest_seconds\n";
  for (const auto& [q, m] : {std::pair<std::string, std::string>{"well-shaped", "LHF-2"},
                             {"isosurface", "Jet-2"},
                             {"irregular", "Quadric"}})
    for (const auto& [s, rings] : {std::pair<std::string, std::string>{"0", "1"},
                                   {"0.01", ""},
                                   {"0.03", "3"},
                                   {"0.1", "4"}}) {
      out << q << ',' << s;
      if (rings.empty())
        out << ",not swept" << std::string(15, ',') << "\n";
      else
        out << ",swept,sweep-test,fam,2,500,0.05,none,H,L2,9," << m << " rings=" << rings
            << ",0.00123,0.01,,,\n";
    }
}

std::string off_of(const fs::path& dir, const std::string& family) {
  const std::string path = (dir / (family + ".off")).string();
  const auto r = run_cli("mesh --family " + family + " --level 2 --output " + path);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return path;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

TEST(CliRecommend, FamiliesClassifyAndNoiseGivenPicksTheNearestLevel) {
  const auto dir = fresh_dir("recommend");
  write_table(dir);
  const std::string results = " --results " + dir.string();
  for (const auto& [family, quality, method] : {std::tuple<std::string, std::string, std::string>{
                                                    "torus-unstructured", "well-shaped", "LHF-2"},
                                                {"torus-iso-projected", "isosurface", "Jet-2"},
                                                {"bump-irregular", "irregular", "Quadric"}}) {
    const std::string mesh = off_of(dir, family);
    auto r = run_cli("recommend " + mesh + results);  // estimated: noise-free meshes
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("class:      " + quality + " ("), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("(estimated"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("estimator:  " + method + ", rings 1; case `" + method + " rings=1`"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("error:      relative L2 error in H 1.23e-03"), std::string::npos)
        << r.output;
    EXPECT_NE(
        r.output.find("table:      " + (dir / "recommendations.csv").string() + ", test table\n"),
        std::string::npos)
        << r.output;
    EXPECT_NE(
        r.output.find(" estimate " + mesh + " --method " + lower(method) + " --rings 1 --output " +
                      dir.string() + "/" + family + ".curvatures.csv\n"),
        std::string::npos)
        << r.output;
    r = run_cli("recommend " + mesh + " --noise 0.05" + results);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("(given)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--method " + lower(method) + " --rings 3 "), std::string::npos)
        << r.output;
  }
  const std::string mesh = (dir / "torus-unstructured.off").string();
  for (const auto& [noise, rings] :
       {std::pair<std::string, std::string>{"0.004", "1"}, {"0.025", "3"}, {"0.5", "4"}}) {
    const auto r = run_cli("recommend " + mesh + " --noise " + noise + results);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("--method lhf-2 --rings " + rings + " "), std::string::npos)
        << r.output;
  }
  // A level no sweep ran: said, and no command.
  const auto r = run_cli("recommend " + mesh + " --noise 0.008" + results);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no sweep ran for well-shaped meshes at sigma/h 0.01"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("run:"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

struct Shell {
  int exit_code = -1;
  std::string out;  // stdout
};

// `command` run by sh in `dir`, stderr to dir/stderr.txt.
Shell shell_in(const fs::path& dir, const std::string& command) {
  const std::string cmd = "cd '" + dir.string() + "' && " + command + " 2> stderr.txt";
  Shell s;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return s;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) s.out.append(buf, n);
  const int status = pclose(pipe);
  s.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return s;
}

// From a folder outside the source tree, with the default table (the source tree's, for a
// build-tree curvbench) and a relative mesh path: the printed command line runs as printed,
// writes the estimates where it says, with the estimator the advice names; `estimate --method
// auto` chooses the same and writes the same bytes.
TEST(CliRecommend, PrintedCommandRunsAsPrintedAndAutoRunsTheSame) {
  const auto dir = fresh_dir("recommend_run");
  ASSERT_EQ(run_cli("mesh --family bump-irregular --level 2 --output '" +
                    (dir / "my mesh.off").string() + "'")
                .exit_code,
            0);
  const Shell r = shell_in(dir, "'" + kBinary + "' recommend 'my mesh.off'");
  ASSERT_EQ(r.exit_code, 0) << r.out << slurp(dir / "stderr.txt");
  EXPECT_NE(r.out.find("class:      irregular ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("table:      " + fs::canonical(kCommitted).string()), std::string::npos)
      << r.out;
  const auto at = r.out.find("\nrun:        ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string command = r.out.substr(at + 13, r.out.find('\n', at + 1) - at - 13);
  EXPECT_NE(command.find(" estimate 'my mesh.off' --method "), std::string::npos) << command;
  EXPECT_TRUE(command.ends_with(" --output 'my mesh.curvatures.csv'")) << command;
  // The estimator line's case (the curvatures' line's, with the advice from mesh features)
  // names the method the command runs.
  const auto curvatures = r.out.find("\ncurvatures: ");
  const auto case_at = r.out.find("; case `", curvatures == std::string::npos ? 0 : curvatures);
  ASSERT_NE(case_at, std::string::npos) << r.out;
  const std::string case_label =
      r.out.substr(case_at + 8, r.out.find('`', case_at + 8) - case_at - 8);
  const std::string label = case_label.substr(0, case_label.find(' '));
  EXPECT_NE(command.find("--method " + lower(label) + " "), std::string::npos) << r.out;

  const Shell run = shell_in(dir, command);
  const std::string err = slurp(dir / "stderr.txt");
  ASSERT_EQ(run.exit_code, 0) << err;
  EXPECT_NE(err.find("curvbench estimate: " + label + " on my mesh.off: 1089 vertices"),
            std::string::npos)
      << err;
  const std::string printed = slurp(dir / "my mesh.curvatures.csv");
  EXPECT_EQ(std::count(printed.begin(), printed.end(), '\n'), 1090);

  // --method auto: the same choice, said on stderr, the same bytes.
  const Shell autorun =
      shell_in(dir, "'" + kBinary + "' estimate 'my mesh.off' --method AUTO --output auto.csv");
  const std::string auto_err = slurp(dir / "stderr.txt");
  ASSERT_EQ(autorun.exit_code, 0) << auto_err;
  const std::string flags = command.substr(command.find("--method "),
                                           command.find(" --output") - command.find("--method "));
  EXPECT_NE(auto_err.find("--method auto chose " + flags + " (case '"), std::string::npos)
      << auto_err << "\n"
      << flags;
  EXPECT_NE(auto_err.find("irregular mesh"), std::string::npos) << auto_err;
  EXPECT_EQ(slurp(dir / "auto.csv"), printed);
  fs::remove_all(dir);
}

TEST(CliRecommend, FormatsCsvAndJson) {
  const auto dir = fresh_dir("recommend_formats");
  const std::string mesh = off_of(dir, "torus-unstructured");
  auto r = run_cli("recommend " + mesh + " --noise 0 --format csv");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The committed table's header and its well-shaped row at sigma/h 0, as written.
  std::istringstream table(slurp(kCommitted));
  std::string line, header, row;
  while (std::getline(table, line)) {
    if (line.rfind('#', 0) == 0) continue;
    if (header.empty())
      header = line;
    else if (line.rfind("well-shaped,0,", 0) == 0)
      row = line;
  }
  EXPECT_EQ(r.output, header + "\n" + row + "\n");
  r = run_cli("recommend " + mesh + " --noise 0 --format json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.rfind("{\"mesh\": \"" + mesh + "\", ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find("\"quality\": \"well-shaped\""), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\"noise\": \"given\", \"noise_level\": 0, \"swept\": true"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(" estimate " + mesh + " --method "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.back(), '\n');
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  // --help names the default table and its provenance.
  r = run_cli("recommend --help");
  EXPECT_NE(r.output.find(fs::canonical(kCommitted).string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(curvbench "), std::string::npos) << r.output;
  fs::remove_all(dir);
}

// A meshed cube (16 segments an edge): 12 x 16 sharp edges and 12 x 15 + 8 crease vertices,
// named in both formats; its noise, estimated off the creases, is 0 in both units; given, the
// second unit is sigma/h over h.
TEST(CliRecommend, CreasesAndNoiseInBothUnits) {
  const auto dir = fresh_dir("recommend_creases");
  const std::string mesh = (dir / "cube.off").string();
  const crease_test::CreasedMesh built = crease_test::meshed_cube(16);
  const Mesh& cube = built.mesh;
  write_mesh(mesh, cube);
  std::string ids;  // the crease vertices as built, as the JSON lists them
  for (int v : built.crease_vertices) ids += (ids.empty() ? "" : ", ") + std::to_string(v);
  auto r = run_cli("recommend " + mesh);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("noise:      sigma/h = 0 (estimated"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("curvature:  sigma/h^2 = 0 ("), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("creases:    192 sharp edges (face normals more than 60 degrees apart), "
                          "188 crease vertices: no smooth-surface curvature there (`--format "
                          "json` lists them, crease_vertex_ids); the noise estimate left out 188 "
                          "crease vertices and the 864 next to them\n"),
            std::string::npos)
      << r.output;
  r = run_cli("recommend " + mesh + " --format json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("\"sigma_over_h2\": 0, \"crease_angle\": 60, \"sharp_edges\": 192, "
                          "\"crease_vertices\": 188, \"noise_crease_vertices\": 188, "
                          "\"noise_near_crease_vertices\": 864, \"crease_vertex_ids\": [" +
                          ids + "], \"table\": "),
            std::string::npos)
      << r.output;
  r = run_cli("recommend " + mesh + " --noise 0.01 --format json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("\"sigma_over_h2\": " + json_number(0.01 / cube.mean_edge_length()) +
                          ", \"crease_angle\": 60, \"sharp_edges\": 192, \"crease_vertices\": "
                          "188, \"noise_crease_vertices\": 0, \"noise_near_crease_vertices\": 0,"),
            std::string::npos)
      << r.output;
  fs::remove_all(dir);
}

// With advice cases beside the table (advice_cases.csv, harness/report/advice.h): normals and
// curvatures advised separately, the cross-validated range, the command runs the curvatures'
// choice, and a feature outside the swept meshes' range is named. The cases: two swept meshes,
// one with the features of the well-shaped torus (level 2), one stretched 4 times; Meyer is
// best for normals on both, LHF-2 with 3 rings for H.
TEST(CliRecommend, PerQuantityAdviceFromFeatures) {
  const auto dir = fresh_dir("recommend_features");
  write_table(dir);
  const std::string mesh = off_of(dir, "torus-unstructured");
  const MeshFeatures torus = measure_mesh_features(read_mesh(mesh));
  MeshFeatures stretched = torus;
  stretched.anisotropy = 4.0;
  std::vector<AdviceCase> cases;
  for (const auto& [family, features] :
       {std::pair<std::string, MeshFeatures>{"fa", torus}, {"fb", stretched}})
    for (const std::string quantity : {"normal", "H"})
      for (const std::string label : {"Meyer", "LHF-2 rings=3"}) {
        AdviceCase c;
        c.experiment = "sweep-test";
        c.family = family;
        c.level = 2;
        c.features = features;
        c.quantity = quantity;
        c.label = label;
        c.error = (quantity == "normal") == (label == "Meyer") ? 0.01 : 0.05;
        cases.push_back(c);
      }
  write_advice_cases_csv((dir / "advice_cases.csv").string(), cases);
  auto r = run_cli("recommend " + mesh + " --noise 0 --results " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("coverage:   every feature within the range of the swept meshes\n"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("normals:    Meyer at its own neighbourhood (no radius option); case "
                          "`Meyer`"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("curvatures: LHF-2, rings 3; case `LHF-2 rings=3`"), std::string::npos)
      << r.output;
  // Held out, each mesh learns from the other, whose best is its own: regret 1.
  EXPECT_NE(r.output.find("1.00 to 1.00 times the best error, median 1.00"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("differ:     the normals' and the curvature's choices differ"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(" --method lhf-2 --rings 3 --output "), std::string::npos) << r.output;
  r = run_cli("recommend " + mesh + " --noise 0 --results " + dir.string() + " --format json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("\"label\": \"LHF-2 rings=3\", \"quantity\": \"H\""), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("\"out_of_range\": [], \"advice\": {\"normal\": {\"label\": "
                          "\"Meyer\""),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("\"choices_differ\": true"), std::string::npos) << r.output;

  // Swept meshes without irregular valences: the torus's 44% is out of their range.
  for (AdviceCase& c : cases) c.features.irregular_valence_share = 0.0;
  write_advice_cases_csv((dir / "advice_cases.csv").string(), cases);
  r = run_cli("recommend " + mesh + " --noise 0 --results " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("coverage:   OUTSIDE what the sweeps cover: irregular_valence_share "
                          "0.44"),
            std::string::npos)
      << r.output;
  fs::remove_all(dir);
}

// One line on stderr, exit 2.
void expect_error(const std::string& args, const std::string& words) {
  const auto r = run_cli(args);
  EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
  EXPECT_NE(r.output.find(words), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST(CliRecommend, Errors) {
  const auto dir = fresh_dir("recommend_errors");
  write_table(dir);
  const std::string results = " --results " + dir.string();
  const std::string mesh = off_of(dir, "bump-irregular");
  expect_error("recommend " + mesh + " --noise -0.1" + results, "--noise -0.1");
  const auto bad_format = run_cli("recommend " + mesh + " --format xml");
  EXPECT_EQ(bad_format.exit_code, 2) << bad_format.output;
  EXPECT_NE(bad_format.output.find("--format: xml not in"), std::string::npos) << bad_format.output;
  expect_error("recommend " + mesh + " --results " + (dir / "none").string(),
               (dir / "none" / "recommendations.csv").string() + ": not found");
  // Truncated, foreign and cut short tables, named with the line.
  const std::string committed = slurp(kCommitted);
  fs::create_directories(dir / "cut");
  std::ofstream(dir / "cut" / "recommendations.csv") << committed.substr(0, committed.size() / 2);
  expect_error("recommend " + mesh + " --results " + (dir / "cut").string(),
               (dir / "cut" / "recommendations.csv").string() + ":");
  fs::create_directories(dir / "short");
  std::ofstream(dir / "short" / "recommendations.csv")
      << committed.substr(0, committed.rfind('\n', committed.size() - 2) + 1);
  expect_error("recommend " + mesh + " --results " + (dir / "short").string(),
               (dir / "short" / "recommendations.csv").string() +
                   ": no row for quality irregular at sigma/h 0.1");
  fs::create_directories(dir / "foreign");
  std::ofstream(dir / "foreign" / "recommendations.csv")
      << slurp(std::string(CURVBENCH_SOURCE_DIR) + "/results/best_radius.csv");
  expect_error("recommend " + mesh + " --results " + (dir / "foreign").string(),
               (dir / "foreign" / "recommendations.csv").string() + ": no column 'quality'");
  expect_error("recommend " + (dir / "missing.off").string() + results, "missing.off");
  std::ofstream(dir / "tri.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_error("recommend " + (dir / "tri.off").string() + results, "cannot classify");
  // An 8 x 8 grid with a third triangle on one interior edge: non-manifold.
  std::ofstream nm(dir / "nm.off");
  nm << "OFF\n65 99 0\n";
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) nm << i << ' ' << j << " 0\n";
  nm << "0.5 0.5 1\n";
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 7; ++i) {
      const int a = 8 * j + i;
      nm << "3 " << a << ' ' << a + 1 << ' ' << a + 9 << "\n3 " << a << ' ' << a + 9 << ' ' << a + 8
         << "\n";
    }
  nm << "3 9 18 64\n";
  nm.close();
  expect_error("recommend " + (dir / "nm.off").string() + results, "non-manifold");
  // --method auto takes no estimator option but the run options, and no mesh it cannot classify.
  expect_error("estimate " + mesh + " --method auto --rings 2 --output " + (dir / "x.csv").string(),
               "--rings cannot be given");
  expect_error("estimate " + (dir / "tri.off").string() + " --method auto --output " +
                   (dir / "x.csv").string(),
               "cannot classify");
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
