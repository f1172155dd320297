// The one atomic file writer of the project: every output file (meshes, CSVs, Markdown, plots,
// timing tables) is written under a temporary name in its target folder and renamed into place
// once complete, so a reader, a failure or a killed run never sees a truncated file.
#pragma once

#include <cstddef>
#include <future>
#include <string>
#include <string_view>

namespace curvbench {

/// The temporary name under which `path` is written before the rename: "<path>.tmp.<pid>" (or
/// "<path>.<k>.tmp.<pid>" when the process already writes `path` elsewhere). Files of this form
/// left by a killed process are swept by remove_stale_temp_files (harness/model/results_table.h).
std::string temp_path(const std::string& path);

/// A file written under a unique temporary name in the target's folder (created exclusively)
/// and renamed into place by commit(); destroyed uncommitted (an exception), it removes the
/// temporary. Content goes through buffer() / append(), or is written to temporary() by other
/// code (a child process, a C stream) before commit(). Every failure throws InputError naming
/// the target: not a file name, a directory, a missing or unwritable folder, a failed write or
/// rename (with the system's reason).
class AtomicFile {
 public:
  /// `create_directories`: create the target's folder if it is missing (else that is an error).
  explicit AtomicFile(const std::string& path, bool create_directories = false);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  /// The pending bytes, to append to; written out beyond 1 MiB.
  std::string& buffer();
  /// Appends a block (written straight through when it is large).
  void append(std::string_view bytes);
  /// Appends the first `size` bytes of `block` from a background thread and returns at once,
  /// so that the caller prepares the next block while the kernel copies this one (the write of
  /// a large CSV is half its cost). One block is in flight at a time: every other call first
  /// waits for it and reports its error. Returns the buffer of the previous block (empty the
  /// first time) to be filled again, so two buffers take turns.
  std::string append_in_background(std::string block, std::size_t size);

  const std::string& temporary() const { return tmp_; }

  /// Writes what is pending, closes and renames into place.
  void commit();

 private:
  [[noreturn]] void fail_errno(const char* what) const;
  void write_all(const char* p, std::size_t n);
  void flush();
  /// Waits for the block in flight, if any; rethrows its error.
  void wait_in_flight();

  std::string path_;
  std::string tmp_;
  std::string buffer_;
  int fd_ = -1;
  bool committed_ = false;
  std::string in_flight_;  // the block being written in the background
  std::future<void> in_flight_done_;
};

/// Writes `content` to `path` atomically (AtomicFile), creating the folder if needed.
void write_file_atomic(const std::string& path, std::string_view content);

}  // namespace curvbench
