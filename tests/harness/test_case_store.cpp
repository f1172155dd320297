// The per-case result store (case_store.h): the input hash changes with every setting that
// determines a case's rows and with the code version, and with nothing else; stored rows come
// back exactly; stale, corrupt or truncated files are not reused; an interrupted in-process run
// resumes to the rows of an uninterrupted one. Also SOURCE_DATE_EPOCH and the temp-file sweep.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>

#include "core/build_info.h"
#include "harness/run/case_store.h"
#include "harness/model/results_table.h"
#include "harness/run/runner.h"
#include "mesh/io.h"
#include "methods/option_schema.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::fresh_dir;

Experiment base_experiment() {
  Experiment e;
  e.name = "store";
  e.title = "Store test";
  e.section = "5.2";
  e.meshes = {{"bump-48", {1, 2}}};
  ExperimentMethod lhf;
  lhf.spec = "lhf-2";
  ExperimentMethod xu;
  xu.spec = "xu-2";
  e.methods = {lhf, xu};
  e.panels = {{"p-n", "Normals.", Quantity::normal, Norm::L2},
              {"p-h", "Mean curvature.", Quantity::H, Norm::Linf}};
  return e;
}

RunCase first_case(const Experiment& e) {
  return {&e, &e.meshes[0], 1, &e.methods[0]};
}

std::string text_of(const std::vector<ErrorRow>& rows) {
  return error_csv_text(rows, "#");
}

TEST(Fnv1a64, KnownValuesAndChaining) {
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ULL);
  EXPECT_EQ(fnv1a64("bar", fnv1a64("foo")), fnv1a64("foobar"));
  EXPECT_EQ(hex64(0xaf63dc4c8601ec8cULL), "af63dc4c8601ec8c");
  EXPECT_EQ(hex64(1), "0000000000000001");
}

TEST(CaseHash, ChangesWithEverySettingAndTheCodeVersionOnly) {
  const Experiment base = base_experiment();
  const std::string version = "curvbench test-version";
  const std::uint64_t h0 = case_hash(first_case(base), version);
  EXPECT_EQ(case_hash(first_case(base_experiment()), version), h0);  // stable

  // Each mutation of an input must give a hash different from the base and from each other.
  std::vector<std::pair<std::string, std::function<void(Experiment&)>>> mutations = {
      {"experiment", [](Experiment& e) { e.name = "other"; }},
      {"family", [](Experiment& e) { e.meshes[0].family = "bump-irregular"; }},
      {"noise order", [](Experiment& e) { e.noise_order = 3; }},
      {"noise seed", [](Experiment& e) { e.noise_seed = 2; }},
      {"noisy", [](Experiment& e) { e.noisy = true; }},
      {"vertex set", [](Experiment& e) { e.vertex_set = VertexSet::interior; }},
      {"spec", [](Experiment& e) { e.methods[0].spec = "lhf-3"; }},
      {"label", [](Experiment& e) { e.methods[0].label = "LHF-2 variant"; }},
      {"method vertex set (default value)",
       [](Experiment& e) { e.methods[0].has_vertex_set = true; }},
      {"method vertex set",
       [](Experiment& e) {
         e.methods[0].has_vertex_set = true;
         e.methods[0].vertex_set = VertexSet::interior;
       }},
      {"qr-tol by one ulp",
       [](Experiment& e) { e.methods[0].options.qr_tolerance = 1.0000000000000002e-3; }},
      {"panel quantity", [](Experiment& e) { e.panels[1].quantity = Quantity::K; }},
      {"panel norm", [](Experiment& e) { e.panels[0].norm = Norm::Linf; }},
      {"extra measure",
       [](Experiment& e) {
         e.panels.push_back({"p-k", "K.", Quantity::K, Norm::L2});
       }},
  };
  // Every option of the table that changes the results, set away from its default.
  for (const OptionInfo& option : estimator_option_schema()) {
    if (option.role != OptionRole::result) continue;
    std::string value;
    switch (option.type) {
      case OptionType::boolean:
        value = option.default_text == "yes" ? "no" : "yes";
        break;
      case OptionType::integer:
        value = std::to_string(std::stoi(option.default_text) + 1);
        break;
      case OptionType::real:
        value = std::to_string(std::stod(option.default_text) + 0.5);
        break;
      case OptionType::choice:
        value = option.choices.at(1);
        break;
      case OptionType::text:
        value = "knn=12";
        break;
    }
    mutations.emplace_back(option.name, [name = option.name, value](Experiment& e) {
      set_option(e.methods[0].options, name, value);
    });
  }
  std::map<std::uint64_t, std::string> seen{{h0, "base"}};
  for (const auto& [what, mutate] : mutations) {
    Experiment e = base_experiment();
    mutate(e);
    const std::uint64_t h = case_hash(first_case(e), version);
    const auto [it, fresh] = seen.emplace(h, what);
    EXPECT_TRUE(fresh) << what << " gives the hash of " << it->second;
  }
  // The level and the code version.
  const Experiment e = base_experiment();
  EXPECT_NE(case_hash({&e, &e.meshes[0], 2, &e.methods[0]}, version), h0);
  EXPECT_NE(case_hash(first_case(e), version + "-dirty exe 1234"), h0);

  // Titles, captions, panel ids, source and the other methods do not change the rows.
  Experiment cosmetic = base_experiment();
  cosmetic.title = "Another title";
  cosmetic.section = "5.3";
  cosmetic.source = "/elsewhere/store.exp";
  cosmetic.panels[0].caption = "Another caption.";
  cosmetic.panels[0].id = "q-n";
  cosmetic.methods[1].spec = "lop-2";
  cosmetic.panels.push_back({"p-n2", "Normals again.", Quantity::normal, Norm::L2});
  EXPECT_EQ(case_hash(first_case(cosmetic), version), h0);
}

TEST(CaseStore, RoundTripAndRejectsStaleCorruptOrTruncatedFiles) {
  const auto dir = fresh_dir("case_store_roundtrip");
  const Experiment e = base_experiment();
  const RunCase c = first_case(e);
  MeshCache meshes;
  const std::vector<ErrorRow> rows = run_case(c, meshes, 1);
  ASSERT_EQ(rows.size(), 2u);

  const CaseStore store(dir.string(), "version-1");
  EXPECT_FALSE(store.load(c).has_value());  // nothing stored yet
  store.save(c, rows);
  EXPECT_EQ(fs::path(store.path(c)).parent_path(), dir / "store");
  const auto back = store.load(c);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(text_of(*back), text_of(rows));  // every field, doubles bit for bit (%.17g)
  // The estimation time measured for the case comes back with it.
  EXPECT_GT(rows.front().seconds, 0.0);
  for (const auto& r : *back) EXPECT_EQ(r.seconds, rows.front().seconds);
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();

  // Another code version, or another case under the same file name: stale.
  EXPECT_FALSE(CaseStore(dir.string(), "version-2").load(c).has_value());
  Experiment other = base_experiment();
  other.noise_order = 3;
  EXPECT_EQ(store.path(first_case(other)), store.path(c));
  EXPECT_FALSE(store.load(first_case(other)).has_value());

  // One digit changed in an error value: the content hash no longer matches.
  const std::string good = read_file(store.path(c));
  std::string bad = good;
  const auto at = bad.rfind(",0.");
  ASSERT_NE(at, std::string::npos);
  bad[at + 3] = bad[at + 3] == '1' ? '2' : '1';
  write_file_atomic(store.path(c), bad);
  EXPECT_FALSE(store.load(c).has_value());
  // Truncated (what a non-atomic write killed half way would leave), or empty.
  write_file_atomic(store.path(c), good.substr(0, good.size() / 2));
  EXPECT_FALSE(store.load(c).has_value());
  write_file_atomic(store.path(c), "");
  EXPECT_FALSE(store.load(c).has_value());
  write_file_atomic(store.path(c), good);
  EXPECT_TRUE(store.load(c).has_value());
}

// A method that computes only some of the panel's quantities (an outside estimator without
// normals, like VTK's) stores fewer rows than panel measures: the case is reused, not stale (it
// was recomputed by every run, and --report-only failed on it). A duplicated measure is corrupt.
TEST(CaseStore, FewerRowsThanPanelMeasuresAreACompleteCase) {
  const auto dir = fresh_dir("case_store_fewer_rows");
  const Experiment e = base_experiment();
  const RunCase c = first_case(e);
  MeshCache meshes;
  std::vector<ErrorRow> rows = run_case(c, meshes, 1);
  ASSERT_EQ(rows.size(), 2u);
  rows.erase(rows.begin());  // H only, as from an estimator without normals
  const CaseStore store(dir.string(), "version-1");
  store.save(c, rows);
  const auto back = store.load(c);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(text_of(*back), text_of(rows));
  rows.push_back(rows.front());  // the same measure twice
  store.save(c, rows);
  EXPECT_FALSE(store.load(c).has_value());
}

TEST(CaseStore, VariantsOfOneMethodGetTheirOwnFilesAndPruneRemovesOrphans) {
  const auto dir = fresh_dir("case_store_prune");
  Experiment e = base_experiment();
  e.methods[1] = e.methods[0];
  e.methods[1].options.include_centre = false;  // same spec, another option
  const CaseStore store(dir.string(), "v");
  const std::vector<Experiment> experiments{e};  // cases point into it: keep it alive
  const auto cases = expand_cases(experiments);
  ASSERT_EQ(cases.size(), 4u);
  std::set<std::string> paths;
  for (const auto& c : cases) paths.insert(store.path(c));
  EXPECT_EQ(paths.size(), 4u);

  std::vector<ErrorRow> fake(2);
  for (const auto& c : cases) store.save(c, fake);
  write_file_atomic((dir / "store" / "removed-case.csv").string(), "x\n");
  write_file_atomic((dir / "store" / "notes.txt").string(), "kept\n");
  EXPECT_EQ(store.prune(cases), 1);
  EXPECT_FALSE(fs::exists(dir / "store" / "removed-case.csv"));
  EXPECT_TRUE(fs::exists(dir / "store" / "notes.txt"));
  for (const auto& p : paths) EXPECT_TRUE(fs::exists(p)) << p;
}

TEST(RunExperiments, StoppedRunResumesToTheRowsOfAnUninterruptedOne) {
  const auto dir = fresh_dir("case_store_resume");
  const std::vector<Experiment> exps = {base_experiment()};
  RunOptions plain;
  plain.threads = 1;
  const RunSummary reference = run_experiments(exps, plain);
  EXPECT_EQ(reference.total, 4);
  EXPECT_EQ(reference.computed, 4);
  EXPECT_FALSE(reference.interrupted);

  RunOptions stored = plain;
  stored.store_dir = (dir / ".cache").string();
  int polls = 0;
  stored.stop = [&polls] { return ++polls >= 2; };  // stop after the second case
  const RunSummary first = run_experiments(exps, stored);
  EXPECT_TRUE(first.interrupted);
  EXPECT_EQ(first.computed, 2);
  EXPECT_EQ(first.reused, 0);
  EXPECT_EQ(first.rows.size(), 4u);  // 2 cases x 2 measures

  stored.stop = nullptr;
  std::vector<bool> reused;
  stored.progress = [&reused](const RunProgress& p) { reused.push_back(p.reused); };
  const RunSummary second = run_experiments(exps, stored);
  EXPECT_FALSE(second.interrupted);
  EXPECT_EQ(second.reused, 2);
  EXPECT_EQ(second.computed, 2);
  EXPECT_EQ(reused, (std::vector<bool>{true, true, false, false}));
  EXPECT_EQ(second.rows[0].seconds, first.rows[0].seconds);  // a reused case keeps its time
  EXPECT_EQ(text_of(second.rows), text_of(reference.rows));

  stored.force = true;
  const RunSummary forced = run_experiments(exps, stored);
  EXPECT_EQ(forced.reused, 0);
  EXPECT_EQ(forced.computed, 4);
  EXPECT_EQ(text_of(forced.rows), text_of(reference.rows));
}

TEST(BuildInfo, SourceDateEpochFixesTheTimestamp) {
  const char* old = std::getenv("SOURCE_DATE_EPOCH");
  const std::string saved = old ? old : "";
  setenv("SOURCE_DATE_EPOCH", "0", 1);
  EXPECT_EQ(utc_timestamp(), "1970-01-01T00:00:00Z");
  setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  EXPECT_EQ(utc_timestamp(), "2023-11-14T22:13:20Z");
  EXPECT_NE(provenance_comment().find(", generated 2023-11-14T22:13:20Z"), std::string::npos);
  for (const char* invalid : {"", "-5", "12abc", "1e9", "99999999999999999999999"}) {
    setenv("SOURCE_DATE_EPOCH", invalid, 1);
    EXPECT_GE(utc_timestamp(), "2024") << invalid;  // the current time
  }
  if (old)
    setenv("SOURCE_DATE_EPOCH", saved.c_str(), 1);
  else
    unsetenv("SOURCE_DATE_EPOCH");
}

TEST(TempFiles, SweepRemovesOnlyFilesOfDeadWriters) {
  const auto dir = fresh_dir("case_store_sweep");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) _exit(0);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);  // now a pid no process has
  const std::string dead = std::to_string(child), alive = std::to_string(getpid());
  fs::create_directories(dir / "sub");
  for (const auto& name : {"a.csv.tmp." + dead, "sub/b.png.tmp." + dead, "c.csv.tmp." + alive,
                           std::string("d.tmp.notapid"), std::string("e.csv")})
    std::ofstream(dir / name) << "x";
  EXPECT_EQ(remove_stale_temp_files(dir.string()), 2);
  EXPECT_FALSE(fs::exists(dir / ("a.csv.tmp." + dead)));
  EXPECT_FALSE(fs::exists(dir / "sub" / ("b.png.tmp." + dead)));
  EXPECT_TRUE(fs::exists(dir / ("c.csv.tmp." + alive)));
  EXPECT_TRUE(fs::exists(dir / "d.tmp.notapid"));
  EXPECT_TRUE(fs::exists(dir / "e.csv"));
  EXPECT_EQ(remove_stale_temp_files((dir / "missing").string()), 0);
  EXPECT_EQ(temp_path("x/y.csv"), "x/y.csv.tmp." + alive);
}

}  // namespace
}  // namespace curvbench
