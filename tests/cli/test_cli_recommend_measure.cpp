// `curvbench recommend --measure`: the advice measured on the mesh is printed per quantity with
// its predicted error and its parts, the printed command runs its curvature choice, JSON carries
// it, and a results folder without advice cases is a one-line error (exit 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;
using testing::fresh_dir;
using testing::run_cli;

const std::string kResults = std::string(CURVBENCH_SOURCE_DIR) + "/results";

// The text after `prefix` on the line that starts with it ("" when none).
std::string measure_line(const std::string& output, const std::string& prefix, size_t from = 0) {
  const size_t at = output.find("\n" + prefix, from);
  if (at == std::string::npos) return "";
  const size_t end = output.find('\n', at + 1);
  return output.substr(at + 1 + prefix.size(), end - at - 1 - prefix.size());
}

TEST(CliRecommendMeasure, PrintsTheMeasuredChoicePerQuantityAndRunsTheCurvaturesOne) {
  const fs::path dir = fresh_dir("recommend_measure");
  const std::string mesh = (dir / "t.off").string();
  ASSERT_EQ(run_cli("mesh --family torus-unstructured --level 1 --noise-order 2 --output " + mesh)
                .exit_code,
            0);
  const auto r = run_cli("recommend " + mesh + " --measure --threads 2 --results " + kResults);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const size_t measured = r.output.find("\nmeasured:   on this mesh");
  ASSERT_NE(measured, std::string::npos) << r.output;
  const std::string normals = measure_line(r.output, "normals:    ", measured);
  const std::string curvatures = measure_line(r.output, "curvatures: ", measured);
  EXPECT_NE(normals.find("predicted RMS normal error"), std::string::npos) << r.output;
  EXPECT_NE(curvatures.find("predicted relative L2 error in H"), std::string::npos) << r.output;
  EXPECT_NE(curvatures.find("bias part"), std::string::npos) << r.output;
  // What the measurement did on the swept meshes, its worst regret short even where the best
  // case was exact to round-off (2e12 for the normals of the anisotropic torus): "2.4e+12", as the
  // report prints it.
  const size_t worst = r.output.find("worst ", measured);
  ASSERT_NE(worst, std::string::npos) << r.output;
  EXPECT_LE(r.output.find(' ', worst + 6) - (worst + 6), 8u) << r.output.substr(worst, 40);
  // The case of the curvatures' line is the one the command runs.
  const size_t tick = curvatures.find('`');
  const std::string label = curvatures.substr(tick + 1, curvatures.find('`', tick + 1) - tick - 1);
  const std::string run = measure_line(r.output, "run:        ");
  const std::string method = label.substr(0, label.find(' '));
  std::string lower_method;
  for (char c : method) lower_method += static_cast<char>(std::tolower(c));
  EXPECT_NE(run.find("--method " + lower_method), std::string::npos) << label << " | " << run;
  // ... with its radius ("LHF-2 rings=3" -> --rings 3; "ICC ball-factor=2" -> --ball-factor 2).
  const size_t eq = label.find('=');
  if (eq != std::string::npos) {
    const std::string flag = "--" + label.substr(label.find(' ') + 1, eq - label.find(' ') - 1) +
                             " " + label.substr(eq + 1);
    EXPECT_NE(run.find(flag), std::string::npos) << label << " | " << run;
  }

  const auto j = run_cli("recommend " + mesh + " --measure --format json --results " + kResults);
  ASSERT_EQ(j.exit_code, 0) << j.output;
  EXPECT_NE(j.output.find("\"measured_advice\": {\"perturbation_over_h\": "), std::string::npos);
  EXPECT_NE(j.output.find("\"H\": {\"label\": \"" + label + "\""), std::string::npos) << j.output;
  const std::string normal_label = normals.substr(
      normals.find('`') + 1, normals.find('`', normals.find('`') + 1) - normals.find('`') - 1);
  EXPECT_NE(j.output.find("\"normal\": {\"label\": \"" + normal_label + "\""), std::string::npos)
      << j.output;
}

TEST(CliRecommendMeasure, NeedsTheAdviceCases) {
  const fs::path dir = fresh_dir("recommend_measure_no_cases");
  fs::copy_file(kResults + "/recommendations.csv", dir / "recommendations.csv");
  const std::string mesh = (dir / "t.off").string();
  ASSERT_EQ(run_cli("mesh --family torus-unstructured --level 1 --output " + mesh).exit_code, 0);
  const auto r = run_cli("recommend " + mesh + " --measure --results " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("measure: no advice_cases.csv beside"), std::string::npos) << r.output;
  // --threads belongs to --measure.
  EXPECT_EQ(run_cli("recommend " + mesh + " --threads 2 --results " + dir.string()).exit_code, 2);
  // Without --measure the same folder still advises (the class table).
  EXPECT_EQ(run_cli("recommend " + mesh + " --results " + dir.string()).exit_code, 0);
}

}  // namespace
}  // namespace curvbench
