#include "core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "core/errors.h"

namespace curvbench {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

}  // namespace

std::string temp_path(const std::string& path) {
  return path + ".tmp." + std::to_string(::getpid());
}

AtomicFile::AtomicFile(const std::string& path, bool create_directories) : path_(path) {
  const fs::path target(path);
  if (target.filename().empty()) fail(path, "cannot write: not a file name");
  std::error_code ec;
  if (fs::is_directory(target, ec)) fail(path, "cannot write: is a directory");
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (create_directories) fs::create_directories(dir, ec);  // a failure shows in open() below
  // The usual name, or a numbered one if this process is already writing the same path.
  for (int k = 0; fd_ < 0; ++k) {
    tmp_ = k == 0 ? temp_path(path) : temp_path(path + "." + std::to_string(k));
    fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ >= 0 || (errno == EEXIST && k < 1000)) continue;
    const int err = errno;
    if (err == ENOENT || err == ENOTDIR)
      fail(path, "cannot write: directory '" + dir.string() + "' does not exist");
    if (err == EACCES || err == EPERM || err == EROFS)
      fail(path, "cannot write: directory '" + dir.string() + "' is not writable (" +
                     std::strerror(err) + ")");
    fail(path, std::string("cannot write (") + std::strerror(err) + ")");
  }
}

AtomicFile::~AtomicFile() {
  if (in_flight_done_.valid()) in_flight_done_.wait();  // its error no longer matters
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) ::unlink(tmp_.c_str());
}

void AtomicFile::wait_in_flight() {
  if (in_flight_done_.valid()) in_flight_done_.get();
}

std::string AtomicFile::append_in_background(std::string block, std::size_t size) {
  wait_in_flight();
  flush();  // what is pending goes first
  std::string done = std::move(in_flight_);
  in_flight_ = std::move(block);
  in_flight_done_ =
      std::async(std::launch::async, [this, size] { write_all(in_flight_.data(), size); });
  return done;
}

std::string& AtomicFile::buffer() {
  wait_in_flight();
  if (buffer_.size() > kFlushBytes) flush();
  return buffer_;
}

void AtomicFile::append(std::string_view bytes) {
  wait_in_flight();
  if (buffer_.size() + bytes.size() <= kFlushBytes) {
    buffer_.append(bytes);
    return;
  }
  flush();
  write_all(bytes.data(), bytes.size());
}

void AtomicFile::commit() {
  wait_in_flight();
  flush();
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail_errno("cannot write");
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail_errno("cannot rename into place");
  committed_ = true;
}

void AtomicFile::fail_errno(const char* what) const {
  fail(path_, std::string(what) + " (" + std::strerror(errno) + ")");
}

void AtomicFile::write_all(const char* p, std::size_t left) {
  while (left > 0) {
    const ssize_t w = ::write(fd_, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      fail_errno("cannot write");
    }
    p += w;
    left -= static_cast<std::size_t>(w);
  }
}

void AtomicFile::flush() {
  write_all(buffer_.data(), buffer_.size());
  buffer_.clear();
}

void write_file_atomic(const std::string& path, std::string_view content) {
  AtomicFile file(path, true);
  file.append(content);
  file.commit();
}

}  // namespace curvbench
