// Outside estimators as experiment methods (`method external`, harness/run/external_estimator.h):
// the worked example (experiments/examples/, Python + numpy) runs end to end and its rows are
// what `curvbench score` gives for the script's output; failures are typed errors naming the
// case; the case store keys on the command and the script's content; a command exiting 77
// cannot run here and its method is skipped, not failed (docs/cli.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <tuple>
#include <vector>

#include "harness/model/experiment.h"
#include "harness/run/external_estimator.h"
#include "harness/model/results_table.h"
#include "harness/model/score.h"
#include "meshgen/generate.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::CliResult;
using testing::fresh_dir;
using testing::run_cli;
namespace fs = std::filesystem;

const std::string kBinary = std::string(CURVBENCH_BINARY_DIR) + "/curvbench";
const std::string kSource = CURVBENCH_SOURCE_DIR;

// Runs a shell command line; stdout and stderr together.
CliResult sh(const std::string& line) {
  CliResult r;
  FILE* pipe = popen((line + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) r.output.append(buf, n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// Why the Python example cannot run here, or "" if it can.
std::string python_missing() {
  if (!fs::exists("/usr/bin/python3")) return "/usr/bin/python3 is not installed";
  if (sh("/usr/bin/python3 -c 'import numpy'").exit_code != 0)
    return "numpy is missing for /usr/bin/python3 (Debian package python3-numpy; make deps)";
  return "";
}

int reused(const std::string& log) {
  std::smatch m;
  return std::regex_search(log, m, std::regex(R"(\[run\] reused (\d+) of)")) ? std::stoi(m[1]) : -1;
}

TEST(External, CotangentExampleRunsEndToEndAndScoresAsScoreDoes) {
  if (const std::string why = python_missing(); !why.empty()) GTEST_SKIP() << why;
  const fs::path out = fresh_dir("external_example");
  // From the repository root, as docs/cli.md says.
  const auto r = sh("cd '" + kSource + "' && '" + kBinary +
                    "' run experiments/examples/cotangent-external.exp --threads 1 "
                    "--table4-max 16 --no-plots --output '" +
                    out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("cotangent-py"), std::string::npos) << r.output;

  const auto rows = read_error_csv((out / "cotangent-external.csv").string());
  std::map<std::tuple<std::string, int, std::string>, ErrorRow> by;
  for (const auto& row : rows)
    if (row.method == "cotangent-py")
      by[std::make_tuple(row.family, row.level, row.quantity)] = row;
  ASSERT_EQ(by.size(), 12u);  // 2 families x 3 levels x (normal, H)
  auto at = [&](const std::string& family, int level, const std::string& q) -> const ErrorRow& {
    return by[std::make_tuple(family, level, q)];
  };
  // Normals converge on both meshes; the bump's boundary vertices are NaN (no full ring):
  // counted as failed, the interior scored.
  for (const char* family : {"torus-jittered", "bump-irregular"})
    EXPECT_LT(at(family, 3, "normal").error, 0.5 * at(family, 1, "normal").error) << family;
  EXPECT_EQ(at("torus-jittered", 3, "H").excluded, 0);
  const ErrorRow& bump = at("bump-irregular", 3, "H");
  EXPECT_GT(bump.excluded, 0);
  EXPECT_EQ(bump.counted + bump.excluded, bump.vertices);
  // Rates and timings like any built-in method.
  EXPECT_NE(sh("grep -c cotangent-py '" + (out / "rates.csv").string() + "'").output, "0\n");
  const auto timings = read_timing_csv((out / "timings" / "cotangent-external.csv").string());
  int timed = 0;
  for (const auto& t : timings) timed += t.method == "cotangent-py" && t.seconds > 0;
  EXPECT_EQ(timed, 6);

  // The same script on the same mesh written by `curvbench mesh`, scored by `curvbench score`.
  const fs::path mesh = out / "torus2.ply", est = out / "torus2.csv";
  ASSERT_EQ(run_cli("mesh --family torus-jittered --level 2 --output " + mesh.string()).exit_code,
            0);
  ASSERT_EQ(sh("/usr/bin/python3 '" + kSource + "/experiments/examples/cotangent_estimator.py' '" +
               mesh.string() + "' '" + est.string() + "'")
                .exit_code,
            0);
  const ScoreResult s = score_files(mesh.string(), est.string(), VertexSet::all);
  ASSERT_EQ(s.scores.size(), 2u);
  EXPECT_DOUBLE_EQ(s.scores[0].l2.value, at("torus-jittered", 2, "normal").error);
  EXPECT_DOUBLE_EQ(s.scores[1].l2.value, at("torus-jittered", 2, "H").error);
}

TEST(External, StoreKeysOnTheCommandAndTheScriptContent) {
  if (const std::string why = python_missing(); !why.empty()) GTEST_SKIP() << why;
  const fs::path dir = fresh_dir("external_store");
  const fs::path script = dir / "est.py";
  fs::copy_file(kSource + "/experiments/examples/cotangent_estimator.py", script);
  std::ofstream(dir / "ext.exp") << "mesh bump-48 levels=1\n"
                                    "method external name=mine command=\"/usr/bin/python3 "
                                 << script.string()
                                 << " {mesh} {out}\"\nmethod lhf-2\npanel p \"p\" H L2\n";
  fs::create_directories(dir / "none");
  const std::string run = "'" + kBinary + "' run '" + (dir / "ext.exp").string() +
                          "' --experiments-dir '" + (dir / "none").string() +
                          "' --threads 1 --table4-max 16 --no-plots --output '" +
                          (dir / "out").string() + "'";
  auto r = sh(run);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(reused(r.output), 0) << r.output;
  r = sh(run);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(reused(r.output), 2) << r.output;
  // Same command text, another script content: the outside estimator's case is recomputed.
  std::ofstream(script, std::ios::app) << "# changed\n";
  r = sh(run);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(reused(r.output), 1) << r.output;
  EXPECT_EQ(files_named_in("/usr/bin/python3 " + script.string() + " {mesh} {out}"),
            (std::vector<std::string>{"/usr/bin/python3", script.string()}));
}

TEST(External, FailuresAreTypedErrorsNamingTheCase) {
  const fs::path dir = fresh_dir("external_fail");
  fs::create_directories(dir / "none");  // --experiments-dir: only the file given is read
  const std::string options = "' --experiments-dir '" + (dir / "none").string() +
                              "' --table4-max 16 --no-plots --output '" + (dir / "out").string() +
                              "'";
  struct Case {
    std::string name, method, expected;
  };
  const std::vector<Case> cases = {
      {"exit", "command=\"echo boom >&2; : {mesh} {out}; exit 3\"",
       "failed with exit code 3; its output ends: boom"},
      {"slow", "command=\"sleep 30; : {mesh} {out}\" timeout=0.5",
       "exceeded its time limit of 0.5 s and was killed"},
      {"silent", "command=\": {mesh} {out}\"", "exited 0 but wrote no {out} file"},
      {"short", "command=\"printf 'vertex,H\\n0,1\\n' > {out}; : {mesh}\"",
       "wrote a bad {out}: 1 rows for a mesh of"},
  };
  for (const Case& c : cases) {
    const fs::path exp = dir / (c.name + ".exp");
    std::ofstream(exp) << "mesh bump-48 levels=1\nmethod external name=bad "
                       << c.method << "\npanel p \"p\" H L2\n";
    const auto r = sh("'" + kBinary + "' run '" + exp.string() + options);
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find("experiment " + c.name +
                            ", bump-48 level 1, method bad: external "
                            "command"),
              std::string::npos)
        << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.name << ": " << r.output;
  }
  // Experiment files that cannot name an outside estimator properly.
  for (const std::string& method :
       {std::string("method external command=\"x {mesh} {out}\""),
        std::string("method external name=a command=\"x {mesh}\""),
        std::string("method external name=a command=\"x {mesh} {out}\" timeout=0"),
        std::string("method lhf-2 command=\"x {mesh} {out}\"")}) {
    std::ofstream(dir / "parse.exp") << "mesh bump-48 levels=1\n"
                                     << method << "\npanel p \"p\" H L2\n";
    const auto r = sh("'" + kBinary + "' run '" + (dir / "parse.exp").string() + options);
    EXPECT_EQ(r.exit_code, 2) << method << ": " << r.output;
    EXPECT_NE(r.output.find("parse.exp:2"), std::string::npos) << method << ": " << r.output;
  }
}

// A command that writes vertex,H (-1 everywhere) for any mesh, with sh only: the vertex count
// from the PLY's header.
const std::string kShEstimator =
    "n=$(grep -a -m1 '^element vertex' {mesh} | cut -d' ' -f3); "
    "{ echo vertex,H; seq 0 $((n-1)) | sed 's/$/,-1/'; } > {out}";

TEST(External, ExitCode77IsUnavailableNotFailed) {
  MeshSpec spec;
  spec.family = "bump-48";
  const Mesh mesh = generate_mesh(spec).mesh;
  ExternalRun run;
  run.case_name = "unit";
  run.command = "echo starting >&2; echo 'no libfoo here' >&2; : {mesh} {out}; exit 77";
  try {
    run_external_estimator(mesh, run);
    FAIL() << "exit 77 did not throw";
  } catch (const ExternalEstimatorUnavailable& e) {
    EXPECT_EQ(e.reason(), "no libfoo here");  // the last line of its stderr
    EXPECT_NE(std::string(e.what()).find("exit code 77"), std::string::npos) << e.what();
  }
  run.command = ": {mesh} {out}; exit 77";
  try {
    run_external_estimator(mesh, run);
    FAIL() << "exit 77 did not throw";
  } catch (const ExternalEstimatorUnavailable& e) {
    EXPECT_EQ(e.reason(), "exit code 77, no message");
  }
  // Any other exit code is a failure, not a skip; the sh estimator itself works.
  run.command = ": {mesh} {out}; exit 78";
  try {
    run_external_estimator(mesh, run);
    FAIL() << "exit 78 did not throw";
  } catch (const ExternalEstimatorUnavailable&) {
    FAIL() << "exit 78 taken for a skip";
  } catch (const ExternalEstimatorError& e) {
    EXPECT_NE(std::string(e.what()).find("failed with exit code 78"), std::string::npos);
  }
  run.command = kShEstimator;
  const ExternalResult r = run_external_estimator(mesh, run);
  ASSERT_EQ(r.estimates.size(), static_cast<size_t>(mesh.num_vertices()));
  EXPECT_EQ(r.estimates.back().H, -1.0);
}

TEST(External, DescriptionIsParsedForOutsideEstimatorsOnly) {
  const Experiment e = parse_experiment_text(
      "mesh bump-48 levels=1\nmethod external name=a command=\"x {mesh} {out}\" "
      "description=\"what it does, in words\"\npanel p \"p\" H L2\n",
      "d.exp");
  ASSERT_EQ(e.methods.size(), 1u);
  EXPECT_EQ(e.methods[0].description, "what it does, in words");
  EXPECT_THROW(parse_experiment_text("mesh bump-48 levels=1\nmethod lhf-2 "
                                     "description=\"x\"\npanel p \"p\" H L2\n",
                                     "d.exp"),
               InputError);
}

// The run goes on without the method: one message, no rows, skipped.csv and REPORT.md say why;
// the skipped cases are not stored, so once the command can run a rerun computes them and the
// skip notes go away.
TEST(External, SkippedMethodLeavesTheRunGoingAndSaysWhy) {
  const fs::path dir = fresh_dir("external_skip");
  fs::create_directories(dir / "none");
  const fs::path flag = dir / "available";
  const std::string command = "test -f " + flag.string() +
                              " || { echo 'libfoo is missing, install it' >&2; exit 77; }; " +
                              kShEstimator;
  std::ofstream(dir / "skip.exp")
      << "mesh bump-48 levels=1,2\nmesh torus-structured levels=1\n"
         "method external name=gone command=\""
      << command << "\" description=\"a test estimator\"\nmethod lhf-2\npanel p \"p\" H L2\n";
  const fs::path out = dir / "out";
  const std::string run = "'" + kBinary + "' run '" + (dir / "skip.exp").string() +
                          "' --experiments-dir '" + (dir / "none").string() +
                          "' --threads 1 --table4-max 16 --no-plots --output '" + out.string() +
                          "'";
  auto count = [](const std::string& text, const std::string& what) {
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  auto r = sh(run);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Once per run, although three cases skip.
  EXPECT_EQ(count(r.output, "[run] skipped method gone: libfoo is missing, install it\n"), 1)
      << r.output;
  EXPECT_NE(r.output.find("computed 3, skipped 3 (outside estimators that cannot run here)"),
            std::string::npos)
      << r.output;
  auto rows = read_error_csv((out / "skip.csv").string());
  EXPECT_EQ(rows.size(), 3u);  // lhf-2's only
  EXPECT_TRUE(std::all_of(rows.begin(), rows.end(),
                          [](const ErrorRow& row) { return row.method == "LHF-2"; }));
  const auto skipped = read_skipped_csv((out / "skipped.csv").string());
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0].experiment, "skip");
  EXPECT_EQ(skipped[0].method, "gone");
  EXPECT_EQ(skipped[0].cases, 3);
  EXPECT_EQ(skipped[0].reason, "libfoo is missing; install it");  // commas would split the CSV
  // The experiment's page of the report (results/report/<experiment>.md) holds the notes.
  std::string report = sh("cat '" + (out / "report" / "skip.md").string() + "'").output;
  EXPECT_NE(report.find("- `gone` (outside estimator): a test estimator"), std::string::npos);
  EXPECT_NE(report.find("- `gone` was skipped (3 cases): its command cannot run here (libfoo is "
                        "missing; install it)"),
            std::string::npos)
      << report;

  // Not stored: the same run skips them again (and reuses lhf-2's).
  r = sh(run);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(reused(r.output), 3) << r.output;
  EXPECT_EQ(count(r.output, "[run] skipped method gone"), 1) << r.output;

  // Now it can run: its cases are computed and the skip notes are gone.
  std::ofstream(flag) << "yes\n";
  r = sh(run);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("skipped"), std::string::npos) << r.output;
  EXPECT_EQ(reused(r.output), 3) << r.output;
  rows = read_error_csv((out / "skip.csv").string());
  EXPECT_EQ(std::count_if(rows.begin(), rows.end(),
                          [](const ErrorRow& row) { return row.method == "gone"; }),
            3);
  EXPECT_FALSE(fs::exists(out / "skipped.csv"));
  report = sh("cat '" + (out / "report" / "skip.md").string() + "'").output;
  EXPECT_EQ(report.find("was skipped"), std::string::npos) << report;
  EXPECT_NE(report.find("- `gone` (outside estimator): a test estimator"), std::string::npos);
}

// Sharded: each shard records its skipped cases in the store, and --report-only writes the
// skipped.csv and REPORT.md notes one run writes (instead of failing on missing cases).
TEST(External, ShardedStudyReportsTheSkippedMethod) {
  const fs::path dir = fresh_dir("external_skip_shard");
  fs::create_directories(dir / "none");
  std::ofstream(dir / "skip.exp")
      << "mesh bump-48 levels=1,2\nmethod external name=gone command=\""
      << "echo 'libfoo is missing' >&2; : {mesh} {out}; exit 77"
      << "\"\nmethod lhf-2\npanel p \"p\" H L2\n";
  // A fixed date: REPORT.md's header would otherwise differ between runs a second apart.
  const std::string base = "SOURCE_DATE_EPOCH=1790000000 '" + kBinary + "' run '" +
                           (dir / "skip.exp").string() + "' --experiments-dir '" +
                           (dir / "none").string() +
                           "' --threads 1 --table4-max 16 --no-plots --no-readings";
  const fs::path single = dir / "single", sharded = dir / "sharded", store = dir / "store";
  auto r = sh(base + " --output '" + single.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* k : {"1/2", "2/2"}) {
    r = sh(base + " --output '" + sharded.string() + "' --cache '" + store.string() + "' --shard " +
           k);
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  r = sh(base + " --output '" + sharded.string() + "' --cache '" + store.string() +
         "' --report-only");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto skipped = read_skipped_csv((sharded / "skipped.csv").string());
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0].method, "gone");
  EXPECT_EQ(skipped[0].cases, 2);
  EXPECT_EQ(skipped[0].reason, "libfoo is missing");
  for (const char* name : {"skip.csv", "skipped.csv", "REPORT.md"})
    EXPECT_EQ(sh("cat '" + (sharded / name).string() + "'").output,
              sh("cat '" + (single / name).string() + "'").output)
        << name;
}

}  // namespace
}  // namespace curvbench
