#include "harness/run/external_estimator.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <sstream>
#include <thread>

#include "harness/model/score.h"
#include "mesh/io.h"

namespace curvbench {

namespace fs = std::filesystem;

namespace {

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

// The last `n` non-empty lines of a file, joined with " | " (a one-line error message).
std::string tail_lines(const fs::path& p, int n) {
  std::string text;
  try {
    text = read_file(p.string());
  } catch (const InputError&) {
    return "";
  }
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  std::string out;
  for (size_t i = lines.size() > static_cast<size_t>(n) ? lines.size() - n : 0; i < lines.size();
       ++i)
    out += (out.empty() ? "" : " | ") + lines[i];
  return out;
}

// A fresh private folder for one run; removed by the destructor.
struct TempFolder {
  fs::path path;
  TempFolder() {
    static std::atomic<int> counter{0};
    path = fs::temp_directory_path() /
           ("curvbench-external-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

}  // namespace

std::vector<std::string> files_named_in(const std::string& command) {
  std::vector<std::string> out;
  std::istringstream in(command);
  for (std::string word; in >> word;) {
    if (word.size() >= 2 && (word.front() == '\'' || word.front() == '"') &&
        word.back() == word.front())
      word = word.substr(1, word.size() - 2);
    std::error_code ec;
    if (word.find('{') == std::string::npos && fs::is_regular_file(word, ec)) out.push_back(word);
  }
  return out;
}

ExternalResult run_external_estimator(const Mesh& mesh, const ExternalRun& run) {
  const std::string who = run.case_name + ": external command";
  TempFolder tmp;
  const fs::path mesh_path = tmp.path / "mesh.ply", out_path = tmp.path / "estimates.csv",
                 err_path = tmp.path / "stderr.txt";
  write_mesh(mesh_path.string(), mesh);  // positions and faces only
  const std::string command =
      replace_all(replace_all(run.command, "{mesh}", shell_quoted(mesh_path.string())), "{out}",
                  shell_quoted(out_path.string()));
  const double limit = run.timeout_seconds > 0 ? run.timeout_seconds : kDefaultExternalTimeout;

  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) throw ExternalEstimatorError(who + ": cannot start (fork failed)");
  if (pid == 0) {
    // Own process group, so that a time-out kills the shell and everything it started.
    ::setpgid(0, 0);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int null = ::open("/dev/null", O_RDWR);
    if (err >= 0) ::dup2(err, 2);
    if (null >= 0) {
      ::dup2(null, 0);
      ::dup2(err >= 0 ? err : null, 1);  // stdout with stderr: both help to diagnose a failure
    }
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  int status = 0;
  bool timed_out = false;
  for (auto wait = std::chrono::microseconds(200);;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) throw ExternalEstimatorError(who + ": lost the child process");
    if (std::chrono::duration<double>(clock::now() - t0).count() > limit) {
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      timed_out = true;
      break;
    }
    std::this_thread::sleep_for(wait);
    wait = std::min(wait * 2, std::chrono::microseconds(20000));
  }
  ExternalResult result;
  result.seconds = std::chrono::duration<double>(clock::now() - t0).count();
  const std::string quoted = "'" + run.command + "'";
  auto stderr_part = [&] {
    const std::string t = tail_lines(err_path, 5);
    return t.empty() ? std::string(" (no output)") : "; its output ends: " + t;
  };
  if (timed_out) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", limit);
    throw ExternalEstimatorError(who + " " + quoted + " exceeded its time limit of " + buf +
                                 " s and was killed" + stderr_part());
  }
  if (WIFSIGNALED(status))
    throw ExternalEstimatorError(who + " " + quoted + " was killed by signal " +
                                 std::to_string(WTERMSIG(status)) + stderr_part());
  if (WIFEXITED(status) && WEXITSTATUS(status) == kExternalSkipExitCode) {
    const std::string reason = tail_lines(err_path, 1);
    throw ExternalEstimatorUnavailable(
        who + " " + quoted + " says it cannot run here (exit code " +
            std::to_string(kExternalSkipExitCode) + ")" + stderr_part(),
        reason.empty() ? "exit code " + std::to_string(kExternalSkipExitCode) + ", no message"
                       : reason);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw ExternalEstimatorError(who + " " + quoted + " failed with exit code " +
                                 std::to_string(WEXITSTATUS(status)) + stderr_part());
  std::error_code ec;
  if (!fs::is_regular_file(out_path, ec))
    throw ExternalEstimatorError(who + " " + quoted + " exited 0 but wrote no {out} file" +
                                 stderr_part());
  try {
    EstimateTable t = read_estimate_csv(out_path.string(), mesh.num_vertices());
    result.estimates = std::move(t.estimates);
    result.quantities = std::move(t.quantities);
  } catch (const InputError& e) {
    // The temporary path means nothing once removed: name it {out}.
    throw ExternalEstimatorError(who + " " + quoted + " wrote a bad " +
                                 replace_all(e.what(), out_path.string(), "{out}"));
  }
  return result;
}

}  // namespace curvbench
