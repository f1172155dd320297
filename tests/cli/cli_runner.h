// Runs build/curvbench as a child process and captures its exit code and output; and the file
// helpers of the tests that read and write its files: a fresh directory, a file's bytes, writing
// a file, every file under a directory.
#pragma once

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace curvbench::testing {

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr interleaved
};

inline CliResult run_cli(const std::string& args) {
  const std::string cmd = std::string(CURVBENCH_BINARY_DIR) + "/curvbench " + args + " 2>&1";
  CliResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) r.output.append(buf, n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// A fresh, empty directory under the system temp dir, unique per test process (ctest runs the
/// tests of one fixture as parallel processes, so the name alone is not enough).
inline std::filesystem::path fresh_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("curvbench_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The bytes of a file (empty if it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Writes `text` to the file `p`, creating its directory first.
inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

/// Every file under `dir` (path relative to `dir` -> bytes), skipping the paths that start with
/// one of `skipped_prefixes`.
inline std::map<std::string, std::string> files_under(
    const std::filesystem::path& dir, const std::vector<std::string>& skipped_prefixes) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string rel = std::filesystem::relative(entry.path(), dir).string();
    bool skipped = !entry.is_regular_file();
    for (const std::string& prefix : skipped_prefixes) skipped |= rel.rfind(prefix, 0) == 0;
    if (!skipped) files[rel] = slurp(entry.path());
  }
  return files;
}

}  // namespace curvbench::testing
