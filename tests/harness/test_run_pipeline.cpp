// run_pipeline (harness/run_pipeline.h): a full run writes every output and stores every case;
// a rerun reuses them all and writes the same bytes; report-only rebuilds the outputs from the
// store and names the missing cases of an incomplete one; a shard stores only its cases; a stop
// request leaves REPORT.md unwritten.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/errors.h"
#include "harness/model/experiment.h"
#include "harness/run_pipeline.h"
#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

Experiment tiny() {
  return parse_experiment_text(
      "title \"A pipeline test\"\nsection beyond\n"
      "mesh torus-structured levels=1,2\nmethod lhf-2\nmethod meyer\n"
      "panel pt-h \"Pipeline test. L2 errors in H.\" H L2\n",
      "pipeline-test.exp");
}

PipelineOptions options_in(const fs::path& dir) {
  PipelineOptions o;
  o.experiments = {tiny()};
  o.available = o.experiments;
  o.output = dir.string();
  o.run.threads = 1;
  o.table4_max = 16;
  o.plots = false;
  return o;
}

TEST(RunPipeline, FullRunThenRerunReusesEveryCaseWithTheSameBytes) {
  ::setenv("SOURCE_DATE_EPOCH", "1", 1);  // the same date in both runs' provenance lines
  const auto dir = testing::fresh_dir("pipeline_full");
  const PipelineResult first = run_pipeline(options_in(dir));
  EXPECT_EQ(first.status, PipelineStatus::done);
  EXPECT_EQ(first.total, 4);  // 2 levels x 2 methods
  EXPECT_EQ(first.computed, 4);
  EXPECT_EQ(first.reused, 0);
  for (const char* f :
       {"pipeline-test.csv", "rates.csv", "table2.csv", "table4.csv", "REPORT.md", "CLAIMS.md"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_EQ(first.report, (dir / "REPORT.md").string());
  const std::string csv = testing::slurp(dir / "pipeline-test.csv");
  EXPECT_NE(csv.find(",LHF-2,"), std::string::npos);
  EXPECT_NE(csv.find(",Meyer,"), std::string::npos);

  const PipelineResult again = run_pipeline(options_in(dir));
  EXPECT_EQ(again.computed, 0);
  EXPECT_EQ(again.reused, 4);
  EXPECT_EQ(testing::slurp(dir / "pipeline-test.csv"), csv);

  PipelineOptions report = options_in(dir);
  report.report_only = true;
  const PipelineResult rebuilt = run_pipeline(report);
  EXPECT_EQ(rebuilt.computed, 0);
  EXPECT_EQ(testing::slurp(dir / "pipeline-test.csv"), csv);
  ::unsetenv("SOURCE_DATE_EPOCH");
}

TEST(RunPipeline, ShardsStoreTheirCasesAndReportOnlyNamesWhatIsMissing) {
  const auto dir = testing::fresh_dir("pipeline_shards");
  PipelineOptions shard = options_in(dir);
  shard.run.shard = 1;
  shard.run.shard_count = 2;
  const PipelineResult one = run_pipeline(shard);
  EXPECT_GT(one.computed, 0);
  EXPECT_LT(one.computed, 4);
  EXPECT_FALSE(fs::exists(dir / "REPORT.md"));  // a shard writes no outputs
  EXPECT_FALSE(fs::exists(dir / "pipeline-test.csv"));
  PipelineOptions report = options_in(dir);
  report.report_only = true;
  try {
    run_pipeline(report);
    ADD_FAILURE() << "expected InputError for an incomplete store";
  } catch (const InputError& e) {
    const std::vector<std::string> missing = list_case_ids({tiny()}, 2, 2);
    ASSERT_FALSE(missing.empty());
    EXPECT_NE(std::string(e.what()).find(missing.front()), std::string::npos) << e.what();
  }
  shard.run.shard = 2;
  EXPECT_EQ(run_pipeline(shard).computed, 4 - one.computed);
  EXPECT_EQ(run_pipeline(report).status, PipelineStatus::done);
  EXPECT_TRUE(fs::exists(dir / "REPORT.md"));
}

TEST(RunPipeline, StopAfterTheFirstCaseLeavesNoReport) {
  const auto dir = testing::fresh_dir("pipeline_stop");
  PipelineOptions o = options_in(dir);
  auto finished = std::make_shared<int>(0);
  o.run.progress = [finished](const RunProgress&) { ++*finished; };
  o.run.stop = [finished] { return *finished > 0; };
  const PipelineResult r = run_pipeline(o);
  EXPECT_EQ(r.status, PipelineStatus::stopped);
  EXPECT_EQ(r.computed, 1);
  EXPECT_FALSE(fs::exists(dir / "REPORT.md"));
  EXPECT_EQ(run_pipeline(options_in(dir)).reused, 1);  // the finished case was stored
}

}  // namespace
}  // namespace curvbench
