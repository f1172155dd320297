// Mesh file input and output (contract in io.h).
//
// Reading: read_mesh picks the reader by extension and hands it the file: binary PLY read in
// blocks, anything else mapped into memory (or read) whole (read_off.cpp, read_obj.cpp,
// read_ply.cpp: one validating pass each, which builds the polygon
// soup as it goes and reports the first problem with its line or element number; see
// read_soup.h), frees the file's bytes, and turns the soup into a Mesh here (soup_to_mesh:
// defects dropped and counted, --skip-invalid, fan triangulation). CGAL's readers are not used:
// they serve as a differential oracle in tests/mesh/test_io_oracle.cpp and in fuzz/.
//
// Writing goes through the project's atomic file writer (core/atomic_file.h): a temporary file
// in the target directory renamed into place, so a failure never leaves a partial file behind.
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
  if (vertices == 0) fail(path, "empty mesh: no vertices");
  if (faces == 0) fail(path, "empty mesh: no faces");
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

// ---- soup -> mesh ------------------------------------------------------------------------------

/// True if the k-gon p[0..k) names a vertex twice. O(k log k).
bool has_repeated_index(const std::int32_t* p, std::size_t k, std::vector<std::int32_t>& scratch) {
  if (k == 3) return p[0] == p[1] || p[1] == p[2] || p[0] == p[2];
  scratch.assign(p, p + k);
  std::sort(scratch.begin(), scratch.end());
  return std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end();
}

/// Builds the Mesh from a reader's soup: drops polygons with fewer than 3 vertices or a repeated
/// index; refuses non-finite coordinates or, with skip_invalid, drops those vertices and the
/// polygons using them and renumbers; fan-triangulates (v0, vi, vi+1) the rest.
/// Takes the soup by value and frees it before the Mesh builds its adjacency (peak memory). The
/// usual file (triangles, every vertex finite) becomes the Mesh without a copy.
Mesh soup_to_mesh(const std::string& path, const std::string& format, Soup soup,
                  MeshReadReport* report) {
  const std::size_t n = soup.num_vertices();
  const std::size_t num_polygons = soup.num_polygons();
  if (n == 0) fail(path, "empty mesh: no vertices");
  if (num_polygons == 0) fail(path, "empty mesh: no faces");
  if (n > kMaxCount) fail(path, "too many vertices");
  const double* xyz = soup.xyz.data();

  // Vertices to skip: non-finite tokens seen by the text readers and non-finite values decoded
  // from binary PLY (or made by a homogeneous OFF division). `skip` is made on the first one.
  std::vector<unsigned char> skip;
  if (!soup.nonfinite.empty()) {
    skip.assign(n, 0);
    for (const unsigned long long v : soup.nonfinite) skip[v] = 1;
  }
  std::vector<int> skipped;
  for (std::size_t v = 0; v < n; ++v) {
    const double* q = xyz + 3 * v;
    if ((skip.empty() || !skip[v]) && std::isfinite(q[0]) && std::isfinite(q[1]) &&
        std::isfinite(q[2]))
      continue;
    if (!soup.skip_invalid) {
      std::ostringstream msg;
      msg << "vertex " << v << " has a non-finite coordinate (" << q[0] << ", " << q[1] << ", "
          << q[2] << ")" << kSkipHint;
      fail(path, msg.str());
    }
    if (skip.empty()) skip.assign(n, 0);
    skip[v] = 1;
    skipped.push_back(static_cast<int>(v));
  }
  // New index of each kept vertex (file order).
  std::vector<int> index;
  std::vector<int> source;
  int kept_vertices = static_cast<int>(n);
  if (!skipped.empty()) {
    index.assign(n, -1);
    kept_vertices = 0;
    for (std::size_t v = 0; v < n; ++v)
      if (!skip[v]) index[v] = kept_vertices++;
    if (kept_vertices == 0)
      fail(path, "empty mesh: all " + std::to_string(n) + " vertices have a non-finite coordinate");
    source.reserve(static_cast<std::size_t>(kept_vertices));
    for (std::size_t v = 0; v < n; ++v)
      if (!skip[v]) source.push_back(static_cast<int>(v));
  }
  const auto new_index = [&](std::int32_t v) { return index.empty() ? v : index[v]; };

  // Classify the polygons (the same test again when copying them, instead of a stored fate).
  enum Fate : unsigned char { kKeep, kFew, kSkipped, kRepeated };
  std::vector<std::int32_t> scratch;
  const auto fate = [&](const std::int32_t* p, std::size_t k) {
    // (Every index was checked by the reader: 0 <= p[i] < n.)
    if (k < 3) return kFew;
    if (!skipped.empty() && std::any_of(p, p + k, [&](std::int32_t i) { return skip[i] != 0; }))
      return kSkipped;
    if (has_repeated_index(p, k, scratch)) return kRepeated;
    return kKeep;
  };
  unsigned long long triangles = 0;
  int kept = 0, triangulated = 0, few = 0, repeated = 0, faces_skipped = 0;
  for (std::size_t f = 0; f < num_polygons; ++f) {
    const std::size_t k = soup.polygon_size(f);
    switch (fate(soup.indices.data() + soup.polygon_begin(f), k)) {
      case kFew:
        ++few;
        break;
      case kSkipped:
        ++faces_skipped;
        break;
      case kRepeated:
        ++repeated;
        break;
      case kKeep:
        ++kept;
        triangles += k - 2;
        if (k > 3) ++triangulated;
    }
  }
  if (triangles > kMaxCount) fail(path, "too many triangles after fan triangulation");
  if (kept == 0) {
    std::string why;
    for (const auto& [k, what] : {std::pair{few, "with fewer than 3 vertices"},
                                  std::pair{repeated, "with a repeated vertex index"},
                                  std::pair{faces_skipped, "using a NaN/Inf vertex"}})
      if (k > 0) why += (why.empty() ? "" : ", ") + std::to_string(k) + " " + what;
    fail(path, "empty mesh: no faces left after dropping all " + std::to_string(num_polygons) +
                   " (" + why + ")");
  }

  VertexMatrix V;
  if (skipped.empty()) {
    V = soup.xyz.take();
  } else {
    V.resize(kept_vertices, 3);
    for (std::size_t v = 0; v < n; ++v) {
      if (skip[v]) continue;
      const Eigen::Index r = new_index(static_cast<std::int32_t>(v));
      V(r, 0) = xyz[3 * v];
      V(r, 1) = xyz[3 * v + 1];
      V(r, 2) = xyz[3 * v + 2];
    }
  }
  soup.xyz.release();
  // Fan triangulation (v0, vi, vi+1) of each kept polygon.
  FaceMatrix F;
  if (soup.all_triangles() && static_cast<std::size_t>(kept) == num_polygons && index.empty()) {
    F = soup.indices.take();
  } else {
    F.resize(static_cast<Eigen::Index>(triangles), 3);
    advise_huge_pages(F.data(), sizeof(int) * static_cast<std::size_t>(F.size()));
    Eigen::Index t = 0;
    for (std::size_t f = 0; f < num_polygons; ++f) {
      const std::int32_t* p = soup.indices.data() + soup.polygon_begin(f);
      const std::size_t k = soup.polygon_size(f);
      if (fate(p, k) != kKeep) continue;
      for (std::size_t i = 1; i + 1 < k; ++i, ++t) {
        F(t, 0) = new_index(p[0]);
        F(t, 1) = new_index(p[i]);
        F(t, 2) = new_index(p[i + 1]);
      }
    }
  }
  soup.indices.release();
  std::vector<std::size_t>().swap(soup.starts);

  Mesh mesh(std::move(V), std::move(F), path);
  if (report != nullptr) {
    *report = MeshReadReport{};
    report->format = format;
    report->polygons_read = kept;
    report->polygons_triangulated = triangulated;
    report->triangles = static_cast<int>(triangles);
    report->faces_with_few_vertices = few;
    report->faces_with_repeated_index = repeated;
    report->vertices_in_file = static_cast<int>(n);
    report->vertices_skipped = static_cast<int>(skipped.size());
    report->faces_skipped = faces_skipped;
    report->skipped_vertices = std::move(skipped);
    report->source_vertex = std::move(source);
  }
  return mesh;
}

// ---- file output -------------------------------------------------------------------------------

/// Appends `v` as "%.17g" would print it in the C locale.
void append_double(std::string& out, double v) {
  char buf[32];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::general, 17);
  out.append(buf, ptr);
}

template <typename T>
void append_le(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

/// One value per vertex in every property (names and values are checked by PlyWriter).
void check_properties(const Mesh& mesh, const std::vector<VertexProperty>& properties) {
  for (const VertexProperty& p : properties)
    if (p.values.size() != static_cast<std::size_t>(mesh.num_vertices()))
      throw UsageError("vertex property '" + p.name + "' has " + std::to_string(p.values.size()) +
                       " values for " + std::to_string(mesh.num_vertices()) + " vertices");
}

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
  if (format != "off" && format != "obj" && format != "ply")
    fail(path, format.empty()
                   ? "no file extension (expected .off, .obj or .ply)"
                   : "unknown extension '." + format + "' (expected .off, .obj or .ply)");

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

namespace {

void check_comments(const std::vector<std::string>& comments) {
  for (const std::string& c : comments)
    if (c.find_first_of("\r\n") != std::string::npos)
      throw UsageError("file comment '" + c + "' is not a single line");
}

}  // namespace

void write_off(const std::string& path, const Mesh& mesh,
               const std::vector<std::string>& comments) {
  check_comments(comments);
  AtomicFile file(path);
  file.buffer() += "OFF\n";
  for (const std::string& c : comments) file.buffer() += "# " + c + "\n";
  file.buffer() +=
      std::to_string(mesh.num_vertices()) + " " + std::to_string(mesh.num_faces()) + " 0\n";
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    std::string& out = file.buffer();
    for (int c = 0; c < 3; ++c) {
      append_double(out, mesh.vertices()(v, c));
      out += c < 2 ? ' ' : '\n';
    }
  }
  for (int f = 0; f < mesh.num_faces(); ++f)
    file.buffer() += "3 " + std::to_string(mesh.face_vertex(f, 0)) + " " +
                     std::to_string(mesh.face_vertex(f, 1)) + " " +
                     std::to_string(mesh.face_vertex(f, 2)) + "\n";
  file.commit();
}

struct PlyWriter::Impl {
  AtomicFile file;
  const Mesh& mesh;
  std::vector<Property> properties;
  int written = 0;

  Impl(const std::string& path, const Mesh& m, std::vector<Property> p)
      : file(path), mesh(m), properties(std::move(p)) {}
};

PlyWriter::PlyWriter(const std::string& path, const Mesh& mesh, std::vector<Property> properties,
                     const std::vector<std::string>& comments) {
  std::vector<std::string> names = {"x", "y", "z"};
  for (const Property& p : properties) {
    if (p.name.empty() ||
        std::any_of(p.name.begin(), p.name.end(), [](char c) { return c <= ' ' || c >= 0x7f; }))
      throw UsageError("vertex property name '" + p.name + "' is empty or not a printable word");
    if (std::find(names.begin(), names.end(), p.name) != names.end())
      throw UsageError("vertex property '" + p.name + "' given twice (or clashes with x/y/z)");
    names.push_back(p.name);
  }
  check_comments(comments);
  impl_ = std::make_unique<Impl>(path, mesh, std::move(properties));
  std::string& header = impl_->file.buffer();
  header += "ply\nformat binary_little_endian 1.0\ncomment written by curvbench\n";
  for (const std::string& c : comments) header += "comment " + c + "\n";
  header += "element vertex " + std::to_string(mesh.num_vertices()) + "\n";
  header += "property double x\nproperty double y\nproperty double z\n";
  for (const Property& p : impl_->properties)
    header += std::string("property ") + (p.integer ? "int " : "double ") + p.name + "\n";
  header += "element face " + std::to_string(mesh.num_faces()) + "\n";
  header += "property list uchar int vertex_indices\nend_header\n";
}

PlyWriter::~PlyWriter() = default;

void PlyWriter::write_vertices(int first, int count, const double* values) {
  Impl& w = *impl_;
  if (first != w.written || count < 0 || first + count > w.mesh.num_vertices())
    throw std::logic_error("PlyWriter::write_vertices: vertices out of order");
  const std::size_t P = w.properties.size();
  for (int i = 0; i < count; ++i) {
    const double* row = values + static_cast<std::size_t>(i) * P;
    for (std::size_t p = 0; p < P; ++p) {
      const double x = row[p];
      if (w.properties[p].integer &&
          !(x >= std::numeric_limits<std::int32_t>::min() &&
            x <= std::numeric_limits<std::int32_t>::max() && std::trunc(x) == x))
        throw UsageError("integer vertex property '" + w.properties[p].name + "' has value " +
                         std::to_string(x) + " at vertex " + std::to_string(first + i) +
                         ", not a 32-bit integer");
    }
  }
  const std::size_t record = 24 + [&] {
    std::size_t bytes = 0;
    for (const Property& p : w.properties) bytes += p.integer ? 4 : 8;
    return bytes;
  }();
  std::string block;
  block.reserve(record * static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const int v = first + i;
    for (int c = 0; c < 3; ++c) append_le(block, w.mesh.vertices()(v, c));
    const double* row = values + static_cast<std::size_t>(i) * P;
    for (std::size_t p = 0; p < P; ++p) {
      if (w.properties[p].integer)
        append_le(block, static_cast<std::int32_t>(row[p]));
      else
        append_le(block, row[p]);
    }
  }
  w.file.append(block);
  w.written += count;
}

void PlyWriter::commit() {
  Impl& w = *impl_;
  if (w.written != w.mesh.num_vertices())
    throw std::logic_error("PlyWriter::commit: " + std::to_string(w.written) + " of " +
                           std::to_string(w.mesh.num_vertices()) + " vertices written");
  std::string block;
  const int m = w.mesh.num_faces();
  constexpr int kFaces = 1 << 16;
  for (int f0 = 0; f0 < m; f0 += kFaces) {
    block.clear();
    for (int f = f0; f < std::min(m, f0 + kFaces); ++f) {
      append_le(block, static_cast<std::uint8_t>(3));
      for (int k = 0; k < 3; ++k)
        append_le(block, static_cast<std::int32_t>(w.mesh.face_vertex(f, k)));
    }
    w.file.append(block);
  }
  w.file.commit();
}

void write_ply(const std::string& path, const Mesh& mesh,
               const std::vector<VertexProperty>& properties,
               const std::vector<std::string>& comments) {
  check_properties(mesh, properties);
  std::vector<PlyWriter::Property> types;
  for (const VertexProperty& p : properties) types.push_back({p.name, p.integer});
  PlyWriter writer(path, mesh, std::move(types), comments);
  // Rows of property values, a block of vertices at a time.
  const int n = mesh.num_vertices();
  const std::size_t P = properties.size();
  constexpr int kBlock = 1 << 16;
  std::vector<double> rows;
  for (int first = 0; first < n; first += kBlock) {
    const int count = std::min(kBlock, n - first);
    rows.resize(static_cast<std::size_t>(count) * P);
    for (int i = 0; i < count; ++i)
      for (std::size_t p = 0; p < P; ++p)
        rows[static_cast<std::size_t>(i) * P + p] =
            properties[p].values[static_cast<std::size_t>(first + i)];
    writer.write_vertices(first, count, rows.data());
  }
  writer.commit();
}

void write_mesh(const std::string& path, const Mesh& mesh,
                const std::vector<VertexProperty>& properties,
                const std::vector<std::string>& comments) {
  const std::string ext = lower_extension(path);
  if (ext == "ply") {
    write_ply(path, mesh, properties, comments);
  } else if (ext == "off") {
    if (!properties.empty())
      throw UsageError(path + ": OFF cannot store vertex properties; write .ply instead");
    write_off(path, mesh, comments);
  } else {
    throw UsageError(path + ": cannot write extension '." + ext + "' (expected .off or .ply)");
  }
}

}  // namespace curvbench
