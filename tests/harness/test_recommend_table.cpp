// The recommendations table read back and the advice (harness/report/recommend_table.h): a table
// written by write_recommendations_csv reads back to the same picks; the committed table's case
// labels resolve to the method and radius its own columns name; truncated, foreign and
// inconsistent tables fail naming the file and line; a label becomes the estimate flags and a
// runnable, quoted command line; method auto takes only the run options.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/text.h"
#include "harness/model/experiment.h"
#include "harness/report/recommend_table.h"
#include "mesh/io.h"
#include "meshgen/generate.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

const std::string kCommitted = std::string(CURVBENCH_SOURCE_DIR) + "/results/recommendations.csv";

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A table of every cell with the given best label ("" for a row "not swept").
std::string table_text(const std::string& (*label)(const std::string&, double)) {
  std::string t =
      "# test table\nquality,sigma_over_h,status,experiment,family,level,vertices,h,noise,quantity,"
      "norm,cases,best_label,best_error,best_seconds,cheapest_label,cheapest_error,"
      "cheapest_seconds\n";
  for (const std::string& q : quality_classes())
    for (double s : recommendation_noise_levels()) {
      const std::string& l = label(q, s);
      t += q + "," + format_g(s) +
           (l.empty() ? ",not swept" + std::string(15, ',') + "\n"
                      : ",swept,sweep-test,fam," + std::string("2,500,0.05,none,H,L2,9,") + l +
                            ",0.001,0.01,,,\n");
    }
  return t;
}

const std::string& lhf_everywhere(const std::string&, double) {
  static const std::string l = "LHF-2 rings=3";
  return l;
}

TEST(RecommendTable, WrittenTableReadsBackToTheSamePicks) {
  // Two cases of one method on the well-shaped torus without noise: rings=2 is the best, the
  // fixed Meyer the cheapest within 2x.
  std::vector<ErrorRow> rows;
  for (const auto& [method, error] : {std::pair<std::string, double>{"LHF-2 rings=2", 1e-3},
                                      {"LHF-2 rings=3", 3e-3},
                                      {"Meyer", 1.5e-3}}) {
    ErrorRow r;
    r.experiment = "sweep-test";
    r.family = "torus-unstructured";
    r.level = 2;
    r.vertices = 5000;
    r.h = 0.05;
    r.method = method;
    r.noise = "none";
    r.quantity = "H";
    r.norm = "L2";
    r.error = error;
    type_columns(r);  // as reading the CSV does
    rows.push_back(r);
  }
  const std::vector<TimingRow> timings{
      {"sweep-test", "torus-unstructured", "LHF-2 rings=2", 2, 5000, 0.02},
      {"sweep-test", "torus-unstructured", "Meyer", 2, 5000, 0.001}};
  const fs::path dir = testing::fresh_dir("recommend_table");
  write_recommendations_csv((dir / "recommendations.csv").string(), recommendations(rows, timings));
  const RecommendationTable t = read_recommendations_csv(dir.string());
  EXPECT_EQ(t.name, (dir / "recommendations.csv").string());
  EXPECT_EQ(t.provenance.rfind("curvbench ", 0), 0u) << t.provenance;
  ASSERT_EQ(t.rows.size(), quality_classes().size() * recommendation_noise_levels().size());
  const RecommendationRow& r = t.rows[0];
  EXPECT_EQ(r.quality, "well-shaped");
  EXPECT_EQ(r.sigma_over_h, 0.0);
  ASSERT_TRUE(r.swept);
  EXPECT_EQ(r.best_label, "LHF-2 rings=2");
  EXPECT_EQ(r.best_error, 1e-3);
  EXPECT_EQ(r.best_seconds, 0.02);
  EXPECT_EQ(r.cheapest_label, "Meyer");
  EXPECT_EQ(r.cheapest_error, 1.5e-3);
  EXPECT_EQ(r.family, "torus-unstructured");
  EXPECT_EQ(r.level, 2);
  EXPECT_EQ(r.vertices, 5000);
  EXPECT_EQ(r.cases, 3);
  for (size_t i = 1; i < t.rows.size(); ++i) EXPECT_FALSE(t.rows[i].swept) << i;
  fs::remove_all(dir);
}

// Every swept row of the committed table: its best label resolves to the method, parameter and
// radius of its own best_method, best_parameter and best_radius columns.
TEST(RecommendTable, CommittedLabelsResolveToTheirOwnColumns) {
  const RecommendationTable t = parse_recommendations_csv(read_file(kCommitted), kCommitted);
  const CsvTable raw = read_csv_table(kCommitted);
  const size_t cm = raw.col("best_method"), cp = raw.col("best_parameter"),
               cr = raw.col("best_radius");
  ASSERT_EQ(t.rows.size(), raw.rows.size());
  int swept = 0;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    if (!t.rows[i].swept) continue;
    ++swept;
    const EstimatorChoice c = estimator_choice(t.rows[i].best_label);
    EXPECT_EQ(c.method, lower(raw.text(i, cm))) << t.rows[i].best_label;
    const std::string parameter = raw.text(i, cp) == "fixed" ? "" : raw.text(i, cp);
    EXPECT_EQ(c.parameter, parameter) << t.rows[i].best_label;
    if (!parameter.empty()) {
      EXPECT_EQ(c.radius, raw.number(i, cr)) << t.rows[i].best_label;
    }
  }
  EXPECT_GT(swept, 0);
}

// The advice runs a case label as the whole estimator: in both radius sweeps (the trimmed one
// `make experiments` runs and the full one), every method's label resolves to an estimator with
// the same options as the method line's, and the experiment adds none (no noisy, no radius
// scaling).
TEST(RecommendTable, SweepLabelsAreTheWholeEstimator) {
  for (const char* file :
       {"/experiments/sweep-radius.exp", "/experiments/sweeps/sweep-radius.exp"}) {
    const Experiment e = parse_experiment(std::string(CURVBENCH_SOURCE_DIR) + file);
    EXPECT_FALSE(e.noisy) << file;
    EXPECT_EQ(e.radius_c, 0.0) << file;
    ASSERT_FALSE(e.methods.empty()) << file;
    for (const ExperimentMethod& m : e.methods) {
      const auto line = make_estimator(m.spec, m.options);
      const std::string label = m.label.empty() ? line->label() : m.label;
      const EstimatorChoice c = estimator_choice(label);
      const auto chosen = make_estimator(c.method, c.options);
      EXPECT_EQ(chosen->label(), line->label()) << file << ": " << label;
      for (const OptionInfo& o : estimator_option_schema())
        EXPECT_EQ(option_text(chosen->options(), o), option_text(line->options(), o))
            << file << ": " << label << ": " << o.name;
    }
  }
}

// The default table of a build-tree program is the source tree's; an installed one looks in
// PREFIX/share/curvbench first (tests/install/downstream.sh runs that).
TEST(RecommendTable, BuildTreeDefaultIsTheSourceTreeTable) {
  const std::vector<std::string> paths = recommendations_search_paths();
  ASSERT_FALSE(paths.empty());
  EXPECT_TRUE(fs::equivalent(paths.back(), kCommitted));
  for (size_t i = 0; i + 1 < paths.size(); ++i)
    EXPECT_NE(paths[i].find("/share/curvbench/recommendations.csv"), std::string::npos) << paths[i];
  EXPECT_TRUE(fs::equivalent(default_recommendations_path(), kCommitted));
  EXPECT_EQ(default_recommendations().name, default_recommendations_path());
  EXPECT_EQ(recommendations_provenance(kCommitted).rfind("curvbench ", 0), 0u);
}

void expect_bad(const std::string& text, const std::string& words) {
  try {
    (void)parse_recommendations_csv(text, "t.csv");
    ADD_FAILURE() << "no error for: " << words;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(RecommendTable, BadTablesNameFileAndProblem) {
  const std::string good = table_text(&lhf_everywhere);
  EXPECT_EQ(parse_recommendations_csv(good, "t.csv").rows.size(), 12u);
  EXPECT_EQ(parse_recommendations_csv(good, "t.csv").provenance, "test table");
  // Truncated in a row: another field count; at a row's end: a missing cell.
  expect_bad(good.substr(0, good.size() - 20), "t.csv:14: expected 18 fields");
  const std::string without_last = good.substr(0, good.rfind('\n', good.size() - 2) + 1);
  expect_bad(without_last, "no row for quality irregular at sigma/h 0.1");
  expect_bad("", "empty file");
  // Foreign: another CSV of the results folder.
  expect_bad("# x\nexperiment,family,level,method\na,b,1,c\n", "no column 'quality'");
  // Inconsistent rows.
  std::string twice = good + "well-shaped,0,not swept,,,,,,,,,,,,,,,\n";
  expect_bad(twice, "t.csv:15: a second row for quality well-shaped at sigma/h 0");
  std::string s = good;
  s.replace(s.find("well-shaped,0.01"), 16, "well-shaped,0.02");
  expect_bad(s, "t.csv:4: sigma_over_h 0.02 is not a noise level");
  s = good;
  s.replace(s.find("irregular,0,"), 12, "smooth,0,");
  expect_bad(s, "quality 'smooth' is not one of well-shaped, isosurface, irregular");
  s = good;
  s.replace(s.find(",swept,"), 7, ",maybe,");
  expect_bad(s, "t.csv:3: status 'maybe'");
  s = good;
  s.replace(s.find("LHF-2 rings=3"), 13, "Nonesuch rings=3");
  expect_bad(s, "t.csv:3: case 'Nonesuch rings=3' is no estimator curvbench estimate runs");
  s = good;
  s.replace(s.find("0.001"), 5, "tiny!");
  expect_bad(s, "t.csv:3: 'tiny!' is not a number");
}

TEST(RecommendTable, LabelsBecomeEstimateFlags) {
  EstimatorChoice c = estimator_choice("LHF-4 rings=2");
  EXPECT_EQ(c.method, "lhf-4");
  EXPECT_EQ(c.parameter, "rings");
  EXPECT_EQ(c.radius, 2.0);
  EXPECT_EQ(c.options.rings, 2.0);
  EXPECT_EQ(c.flags(), (std::vector<std::string>{"--method", "lhf-4", "--rings", "2"}));
  EXPECT_EQ(c.text(), "LHF-4, rings 2");
  c = estimator_choice("Normal-cycle ball-factor=1.5");
  EXPECT_EQ(c.options.ball_factor, 1.5);
  EXPECT_EQ(c.flags(),
            (std::vector<std::string>{"--method", "normal-cycle", "--ball-factor", "1.5"}));
  c = estimator_choice("Rusinkiewicz");
  EXPECT_EQ(c.flags(), (std::vector<std::string>{"--method", "rusinkiewicz"}));
  EXPECT_TRUE(std::isnan(c.radius));
  EXPECT_THROW((void)estimator_choice("Nonesuch"), UsageError);
  EXPECT_THROW((void)estimator_choice("LHF-2 interp"), UsageError);         // a custom label
  EXPECT_THROW((void)estimator_choice("LHF-2 ball-factor=2"), UsageError);  // not LHF's option
}

TEST(RecommendTable, CommandLineIsQuotedForTheShell) {
  EXPECT_EQ(shell_quote("/tmp/a-b_c.off"), "/tmp/a-b_c.off");
  EXPECT_EQ(shell_quote("my mesh.off"), "'my mesh.off'");
  EXPECT_EQ(shell_quote("it's.off"), "'it'\\''s.off'");
  EXPECT_EQ(shell_quote("$HOME"), "'$HOME'");
  EXPECT_EQ(shell_quote(""), "''");
  EXPECT_EQ(advice_output_path("meshes/bunny.off"), "meshes/bunny.curvatures.csv");
  EXPECT_EQ(advice_output_path("bunny"), "bunny.curvatures.csv");
  EXPECT_EQ(estimate_command("curvbench", "my mesh.ply", estimator_choice("ICC ball-factor=4"),
                             true, "my mesh.curvatures.csv"),
            "curvbench estimate 'my mesh.ply' --method icc --ball-factor 4 --skip-invalid "
            "--output 'my mesh.curvatures.csv'");
  // The command runs in a shell as printed: the quoted words come back whole.
  const fs::path dir = testing::fresh_dir("recommend_quote");
  const std::string word = (dir / "it's a $mesh").string();
  const auto r = testing::run_cli("mesh --family torus-structured --level 1 --output " +
                                  shell_quote(word + ".off"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(word + ".off"));
  fs::remove_all(dir);
}

TEST(RecommendTable, AutoTakesOnlyTheRunOptions) {
  const EstimatorChoice c = estimator_choice("Jet-2 rings=4");
  EstimatorOptions given;
  given.threads = 1;
  given.kernel = Kernel::scalar;
  const EstimatorOptions o = auto_options(c, given, false);
  EXPECT_EQ(o.rings, 4.0);
  EXPECT_EQ(o.threads, 1);
  EXPECT_EQ(o.kernel, Kernel::scalar);
  given.ball_factor = 2;
  try {
    (void)auto_options(c, given, false);
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--ball-factor cannot be given"), std::string::npos)
        << e.what();
  }
  try {
    (void)auto_options(c, given, true);
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("ball_factor cannot be given"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(is_auto_method("Auto"));
  EXPECT_FALSE(is_auto_method("autox"));
}

const std::string& by_cell(const std::string& q, double s) {
  static const std::string none, a = "LHF-2 rings=1", b = "Jet-2 rings=4", c = "ICC ball-factor=2";
  if (s == 0.01) return none;
  return q == "well-shaped" ? (s == 0 ? a : b) : c;
}

TEST(RecommendTable, AdviceIsTheRowOfTheMeshClassAndNoise) {
  const RecommendationTable t = parse_recommendations_csv(table_text(&by_cell), "t.csv");
  MeshSpec spec;
  spec.family = "torus-unstructured";
  spec.level = 2;
  const Mesh mesh = generate_mesh(spec).mesh;
  Advice a = advise(mesh, std::nan(""), t);  // noise-free: estimated near 0
  EXPECT_EQ(a.mesh_class.quality, "well-shaped");
  EXPECT_TRUE(a.noise_estimated);
  EXPECT_EQ(a.noise_level, 0.0);
  ASSERT_TRUE(a.has_choice);
  EXPECT_EQ(a.choice.label, "LHF-2 rings=1");
  EXPECT_EQ(a.vertices, mesh.num_vertices());
  a = advise(mesh, 0.2, t);
  EXPECT_FALSE(a.noise_estimated);
  EXPECT_EQ(a.choice.label, "Jet-2 rings=4");
  a = advise(mesh, 0.012, t);  // level 0.01: not swept
  EXPECT_EQ(a.noise_level, 0.01);
  EXPECT_FALSE(a.has_choice);
  EXPECT_EQ(advice_text(a, "m.off", "").find("run:"), std::string::npos);
  EXPECT_NE(advice_text(a, "m.off", "").find("no sweep ran for well-shaped meshes at sigma/h 0.01"),
            std::string::npos);
  EXPECT_NE(advice_json(a, "m.off", "").find("\"method\": null"), std::string::npos);
  EXPECT_EQ(advice_csv(a).substr(advice_csv(a).find('\n') + 1),
            "well-shaped,0.01,not swept" + std::string(15, ',') + "\n");
  EXPECT_THROW((void)advise(mesh, -1.0, t), UsageError);
}

}  // namespace
}  // namespace curvbench
