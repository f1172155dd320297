// `curvbench run` interrupted by a signal and rerun: the rerun completes, reuses the cases the
// killed run finished, and its final outputs (CSVs, REPORT.md, CLAIMS.md, plots) are byte for
// byte those of an uninterrupted run. SIGINT is the clean stop (after the current case, exit
// 130); SIGKILL is a crash (nothing can run, the store and atomic writes must hold by design).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace curvbench {
namespace {

using testing::fresh_dir;
using testing::slurp;
namespace fs = std::filesystem;

// 2 meshes x 3 levels x 3 methods = 18 cases, a few seconds in all: long enough to be stopped
// in the middle, short enough for the suite.
fs::path write_resume_experiment(const fs::path& dir) {
  fs::create_directories(dir / "experiments");
  std::ofstream(dir / "experiments" / "resume.exp")
      << "title   \"Resume check\"\n"
         "section 5.2\n"
         "mesh    bump-48 levels=1,2,3\n"
         "mesh    torus-jittered levels=1,2,3\n"
         "method  lhf-2\n"
         "method  lop-2\n"
         "method  lhf-4\n"
         "panel   resume-n \"Fig. 0 (left). L2 errors in normals.\" normal L2\n"
         "panel   resume-h \"Fig. 0 (right). L2 errors in mean curvature.\" H L2\n";
  return dir / "experiments";
}

struct Child {
  pid_t pid = -1;
  fs::path log;
};

// Starts `curvbench run resume ...` with stdout+stderr in `log` and a fixed SOURCE_DATE_EPOCH.
Child start_run(const fs::path& exp_dir, const fs::path& out, const fs::path& log,
                bool force = false) {
  Child c;
  c.log = log;
  const std::string exe = std::string(CURVBENCH_BINARY_DIR) + "/curvbench";
  std::vector<std::string> args = {exe,
                                   "run",
                                   "resume",
                                   "--experiments-dir",
                                   exp_dir.string(),
                                   "--output",
                                   out.string(),
                                   "--table4-max",
                                   "32",
                                   "--threads",
                                   "1"};
  if (force) args.push_back("--force");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string l = log.string();
  c.pid = ::fork();
  if (c.pid == 0) {
    ::setenv("SOURCE_DATE_EPOCH", "1790000000", 1);
    if (!std::freopen(l.c_str(), "w", stdout)) ::_exit(126);
    ::dup2(::fileno(stdout), 2);
    ::execv(exe.c_str(), argv.data());
    ::_exit(127);
  }
  return c;
}

// Waits for the child; returns its wait status.
int wait_for(const Child& c) {
  int status = 0;
  ::waitpid(c.pid, &status, 0);
  return status;
}

// Runs to the end and returns the exit code and the log.
std::pair<int, std::string> run_to_end(const fs::path& exp_dir, const fs::path& out,
                                       const fs::path& log, bool force = false) {
  const Child c = start_run(exp_dir, out, log, force);
  const int status = wait_for(c);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(log)};
}

// Number of progress lines "[ k/ N]" in the log so far.
int cases_done(const fs::path& log) {
  const std::string text = slurp(log);
  static const std::regex line(R"(\[\s*\d+/\s*\d+\] resume )");
  return static_cast<int>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), line), std::sregex_iterator()));
}

// Starts a run and sends `sig` once `after` cases are done; returns the wait status.
int run_and_signal(const fs::path& exp_dir, const fs::path& out, const fs::path& log, int sig,
                   int after) {
  const Child c = start_run(exp_dir, out, log);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (cases_done(log) < after && std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    if (::waitpid(c.pid, &status, WNOHANG) == c.pid) return status;  // finished too early
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(c.pid, sig);
  return wait_for(c);
}

// Every file under `dir` (relative path -> bytes), skipping the case store and the measured
// estimation times (timings/: each computed case has its own; checked separately below).
std::map<std::string, std::string> outputs_without_timings(const fs::path& dir) {
  return testing::files_under(dir, {".cache", "timings"});
}

int reused_count(const std::string& log) {
  std::smatch m;
  static const std::regex re(R"(\[run\] reused (\d+) of (\d+) cases)");
  return std::regex_search(log, m, re) ? std::stoi(m[1]) : -1;
}

class CliResume : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new fs::path(fresh_dir("cli_resume"));
    exp_dir_ = new fs::path(write_resume_experiment(*root_));
    const auto [code, log] = run_to_end(*exp_dir_, *root_ / "reference", *root_ / "reference.log");
    ASSERT_EQ(code, 0) << log;
    ASSERT_EQ(reused_count(log), 0) << log;
    reference_ =
        new std::map<std::string, std::string>(outputs_without_timings(*root_ / "reference"));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*root_);
    delete reference_;
    delete exp_dir_;
    delete root_;
  }

  // The outputs of `out` are those of the uninterrupted reference run, file for file.
  static void expect_same_as_reference(const fs::path& out) {
    const auto got = outputs_without_timings(out);
    ASSERT_FALSE(reference_->empty());
    EXPECT_EQ(got.size(), reference_->size());
    for (const auto& [name, bytes] : *reference_) {
      const auto it = got.find(name);
      ASSERT_NE(it, got.end()) << name << " missing";
      EXPECT_TRUE(it->second == bytes) << name << " differs from the uninterrupted run";
    }
  }

  static fs::path* root_;
  static fs::path* exp_dir_;
  static std::map<std::string, std::string>* reference_;
};
fs::path* CliResume::root_ = nullptr;
fs::path* CliResume::exp_dir_ = nullptr;
std::map<std::string, std::string>* CliResume::reference_ = nullptr;

TEST_F(CliResume, ReferenceHasEveryOutput) {
  for (const char* f :
       {"resume.csv", "rates.csv", "table2.csv", "table4.csv", "REPORT.md", "CLAIMS.md",
        "plots/resume-n_bump-48.png", "plots/resume-h_torus-jittered.svg"})
    EXPECT_EQ(reference_->count(f), 1u) << f;
  // SOURCE_DATE_EPOCH 1790000000 = 2026-09-21T14:13:20Z is the date in every header.
  EXPECT_NE(reference_->at("resume.csv").find("2026-09-21T14:13:20Z"), std::string::npos);
}

TEST_F(CliResume, SigintStopsAfterTheCurrentCaseAndTheRerunReusesIt) {
  const auto out = *root_ / "sigint";
  const int status = run_and_signal(*exp_dir_, out, *root_ / "sigint1.log", SIGINT, 5);
  const std::string log1 = slurp(*root_ / "sigint1.log");
  ASSERT_TRUE(WIFEXITED(status)) << log1;
  ASSERT_EQ(WEXITSTATUS(status), 130) << "the run must be stopped part way\n" << log1;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(log1, m, std::regex(R"(interrupted after (\d+) of 18 cases)")))
      << log1;
  const int finished = std::stoi(m[1]);
  EXPECT_GE(finished, 5);
  EXPECT_LT(finished, 18);
  // Stopped before the combined outputs: no report, and no temporary file left.
  EXPECT_FALSE(fs::exists(out / "REPORT.md"));
  for (const auto& entry : fs::recursive_directory_iterator(out))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();

  const auto [code, log2] = run_to_end(*exp_dir_, out, *root_ / "sigint2.log");
  ASSERT_EQ(code, 0) << log2;
  EXPECT_EQ(reused_count(log2), finished) << log2;
  expect_same_as_reference(out);
}

TEST_F(CliResume, SigkillMidRunLosesOnlyTheCaseInProgress) {
  const auto out = *root_ / "sigkill";
  const int status = run_and_signal(*exp_dir_, out, *root_ / "sigkill1.log", SIGKILL, 7);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run must be killed part way\n"
                                   << slurp(*root_ / "sigkill1.log");
  const int finished_before_kill = cases_done(*root_ / "sigkill1.log");
  ASSERT_GE(finished_before_kill, 7);

  const auto [code, log2] = run_to_end(*exp_dir_, out, *root_ / "sigkill2.log");
  ASSERT_EQ(code, 0) << log2;
  // A case is stored before its progress line is printed, so every case reported done before
  // the kill is reused (and perhaps the one in progress, if it was stored just before the kill).
  EXPECT_GE(reused_count(log2), finished_before_kill) << log2;
  EXPECT_LT(reused_count(log2), 18) << log2;
  expect_same_as_reference(out);
}

TEST_F(CliResume, ForceRecomputesEverythingToTheSameBytes) {
  const auto out = *root_ / "force";
  auto [code, log] = run_to_end(*exp_dir_, out, *root_ / "force1.log");
  ASSERT_EQ(code, 0) << log;
  const std::string timings = slurp(out / "timings" / "resume.csv");
  // One row per case (header, provenance comment), each with a positive time.
  EXPECT_EQ(std::count(timings.begin(), timings.end(), '\n'), 18 + 2) << timings;
  EXPECT_EQ(timings.find(",nan,"), std::string::npos) << timings;
  // A complete rerun reuses every case, and with it the time measured when it was computed.
  std::tie(code, log) = run_to_end(*exp_dir_, out, *root_ / "force2.log");
  ASSERT_EQ(code, 0) << log;
  EXPECT_EQ(reused_count(log), 18) << log;
  expect_same_as_reference(out);
  EXPECT_EQ(slurp(out / "timings" / "resume.csv"), timings);
  // --force recomputes every case and still gives the same bytes.
  std::tie(code, log) = run_to_end(*exp_dir_, out, *root_ / "force3.log", /*force=*/true);
  ASSERT_EQ(code, 0) << log;
  EXPECT_EQ(reused_count(log), 0) << log;
  expect_same_as_reference(out);
}

}  // namespace
}  // namespace curvbench
