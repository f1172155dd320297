// Mesh file input (contract in io.h).
//
// Reading: read_mesh picks the reader by extension and hands it the file: binary PLY read in
// blocks, anything else mapped into memory (or read) whole (read_off.cpp, read_obj.cpp,
// read_ply.cpp: one validating pass each, which builds the polygon
// soup as it goes and reports the first problem with its line or element number; see
// read_soup.h), frees the file's bytes, and turns the soup into a Mesh (soup_to_mesh.cpp:
// defects dropped and counted, --skip-invalid, fan triangulation). CGAL's readers are not used:
// they serve as a differential oracle in tests/mesh/test_io_oracle.cpp and in fuzz/.
// This file: the dispatcher, the file's bytes, and the helpers the readers share (io_detail).
// Writing: write_mesh.cpp.
#include "mesh/io.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/huge_pages.h"
#include "core/text.h"
#include "mesh/read_soup.h"

namespace curvbench {

namespace io_detail {

// ---- errors ------------------------------------------------------------------------------------

void fail(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

void fail_line(const std::string& path, std::size_t line, const std::string& what) {
  fail(path, "line " + std::to_string(line) + ": " + what);
}

std::string quote(std::string_view token) {
  std::string out = "'";
  const std::size_t n = std::min<std::size_t>(token.size(), 40);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    out += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
  }
  if (token.size() > n) out += "...";
  return out + "'";
}

void check_face_index(const std::string& path, std::size_t line, unsigned long long face,
                      long long index, unsigned long long num_vertices) {
  if (index < 0)
    fail_line(
        path, line,
        "face " + std::to_string(face) + " has a negative vertex index " + std::to_string(index));
  if (static_cast<unsigned long long>(index) >= num_vertices)
    fail_line(path, line,
              "face " + std::to_string(face) + " references vertex " + std::to_string(index) +
                  ", out of range [0, " + std::to_string(num_vertices) + ")");
}

void check_not_empty(const std::string& path, unsigned long long vertices,
                     unsigned long long faces) {
  (void)faces;  // none: a point set
  if (vertices == 0) fail(path, "empty mesh: no vertices");
}

// ---- numbers -----------------------------------------------------------------------------------

namespace {

/// `token` without a leading '+' (as the stream extraction allows); empty if it is not a number
/// start ("+-1" or "+").
std::string_view unsigned_plus(std::string_view token) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return {};
  }
  return token;
}

// One real number token as a double or a float (std::from_chars, no locale).
template <class Real>
Number parse_real(std::string_view token, Real* value) {
  const std::string_view s = unsigned_plus(token);
  if (s.empty()) return Number::kBad;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), *value);
  if (ec == std::errc::invalid_argument || ptr != s.data() + s.size()) return Number::kBad;
  if (ec == std::errc::result_out_of_range) {
    // from_chars does not say which way; strtod/strtof return +-HUGE_VAL on overflow, a tiny
    // value on underflow (which the stream extraction accepts).
    const std::string text(s);
    if constexpr (std::is_same_v<Real, float>)
      *value = std::strtof(text.c_str(), nullptr);
    else
      *value = std::strtod(text.c_str(), nullptr);
    return std::isinf(*value) ? Number::kOverflow : Number::kOk;
  }
  return Number::kOk;
}

}  // namespace

Number parse_double(std::string_view token, double* value) {
  return parse_real(token, value);
}

Number parse_float(std::string_view token, float* value) {
  return parse_real(token, value);
}

bool parse_integer(std::string_view token, long long* value) {
  const std::string_view s = unsigned_plus(token);
  if (s.empty()) return false;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), *value);
  return ec == std::errc() && ptr == s.data() + s.size();
}

bool parse_count(std::string_view token, unsigned long long* value) {
  if (token.empty() || !std::isdigit(static_cast<unsigned char>(token.front()))) return false;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return ec == std::errc() && ptr == token.data() + token.size();
}

}  // namespace io_detail

namespace {

namespace fs = std::filesystem;
using namespace io_detail;

/// The bytes of a file for a reader: a regular file is mapped read-only into memory (no copy,
/// no zero-filled buffer), anything else (a pipe, an empty file, a failed mapping) is read by
/// read_file. (A file truncated by another process while it is mapped would raise SIGBUS; the
/// readers never write to it.)
class FileBytes {
 public:
  explicit FileBytes(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat info;
    if (fd >= 0 && ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
      const auto size = static_cast<std::size_t>(info.st_size);
      void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
      if (p != MAP_FAILED) {
        ::madvise(p, size, MADV_SEQUENTIAL);
        map_ = p;
        size_ = size;
      }
    }
    if (fd >= 0) ::close(fd);
    if (map_ == nullptr) text_ = read_file(path);  // and its precise errors
  }
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;
  ~FileBytes() {
    if (map_ != nullptr) ::munmap(map_, size_);
  }

  std::string_view bytes() const {
    return map_ != nullptr ? std::string_view(static_cast<const char*>(map_), size_)
                           : std::string_view(text_);
  }

 private:
  void* map_ = nullptr;
  std::size_t size_ = 0;
  std::string text_;
};

}  // namespace

// ---- file input --------------------------------------------------------------------------------

std::string read_file(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) fail(path, "no such file");
  if (ec) fail(path, "cannot access file (" + ec.message() + ")");
  if (st.type() == fs::file_type::directory) fail(path, "cannot read: is a directory");

  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) fail(path, std::string("cannot read file (") + std::strerror(errno) + ")");
  // A regular file is read in one call into a string of its size; whatever else (a pipe, a file
  // that grows meanwhile) in blocks after it.
  std::string data;
  struct stat info;
  if (::fstat(::fileno(f), &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
    data.resize(static_cast<std::size_t>(info.st_size));
    data.resize(std::fread(data.data(), 1, data.size(), f));
  }
  char buffer[1 << 16];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof(buffer), f)) > 0) data.append(buffer, got);
  const bool error = std::ferror(f) != 0;
  const int err = errno;
  std::fclose(f);
  if (error) fail(path, std::string("cannot read file (") + std::strerror(err) + ")");
  return data;
}

Mesh read_mesh(const std::string& path, MeshReadReport* report, const MeshReadOptions& options) {
  const std::string format = lower_extension(path);
  const bool points = format == "xyz" || format == "pts" || format == "pwn";
  if (format != "off" && format != "obj" && format != "ply" && !points)
    fail(path, format.empty() ? "no file extension (expected .off, .obj, .ply, .xyz, .pts or .pwn)"
                              : "unknown extension '." + format +
                                    "' (expected .off, .obj, .ply, .xyz, .pts or .pwn)");

  Soup soup;
  // Binary PLY is read from the file in blocks (read_binary_ply_file); everything else from the
  // whole file mapped into memory.
  bool read = false;
  if (format == "ply") {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat info;
    if (fd >= 0 && ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
      try {
        read = read_binary_ply_file(path, fd, static_cast<unsigned long long>(info.st_size),
                                    options.skip_invalid, &soup);
      } catch (...) {
        ::close(fd);
        throw;
      }
    }
    if (fd >= 0) ::close(fd);
  }
  if (!read) {
    const FileBytes file(path);
    const std::string_view text = file.bytes();
    if (format == "off")
      soup = read_off(path, text, options.skip_invalid);
    else if (format == "obj")
      soup = read_obj(path, text, options.skip_invalid);
    else if (points)
      soup = read_xyz(path, text, options.skip_invalid);
    else
      soup = read_ply(path, text, options.skip_invalid);
  }  // the file's bytes are freed here, before the mesh is built
  return soup_to_mesh(path, format, std::move(soup), report);
}

std::vector<std::string> read_warnings(const std::string& path, const MeshReadReport& report) {
  std::vector<std::string> out;
  const auto plural = [](int k, const char* one, const char* many) {
    return std::to_string(k) + " " + (k == 1 ? one : many);
  };
  if (report.faces_dropped() > 0) {
    std::string w = path + ": dropped " + plural(report.faces_dropped(), "face", "faces") + " (";
    if (report.faces_with_few_vertices > 0)
      w += std::to_string(report.faces_with_few_vertices) + " with fewer than 3 vertices";
    if (report.faces_with_few_vertices > 0 && report.faces_with_repeated_index > 0) w += ", ";
    if (report.faces_with_repeated_index > 0)
      w += std::to_string(report.faces_with_repeated_index) + " with a repeated vertex index";
    out.push_back(w + ")");
  }
  if (report.vertices_skipped > 0) {
    std::string w = path + ": skipped " + plural(report.vertices_skipped, "vertex", "vertices") +
                    " with a NaN/Inf coordinate (";
    const std::size_t shown = std::min<std::size_t>(report.skipped_vertices.size(), 5);
    for (std::size_t i = 0; i < shown; ++i)
      w += (i == 0 ? "file vertex " : ", ") + std::to_string(report.skipped_vertices[i]);
    if (report.skipped_vertices.size() > shown) w += ", ...";
    w += ") and the " + plural(report.faces_skipped, "face", "faces") + " using " +
         (report.vertices_skipped == 1 ? "it; " : "them; ") +
         std::to_string(report.vertices_in_file - report.vertices_skipped) + " of " +
         std::to_string(report.vertices_in_file) + " vertices kept, renumbered in file order";
    out.push_back(w);
  }
  return out;
}

}  // namespace curvbench
