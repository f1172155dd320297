// Internal to the mesh readers (not installed): the polygon soup each format reader builds in its
// single validating pass, and the text-scanning and error helpers the readers share.
//
// read_mesh (io.cpp) picks the reader by extension (read_off.cpp, read_obj.cpp, read_ply.cpp),
// hands it the whole file, and turns the soup into a Mesh (soup_to_mesh: polygons with fewer than
// 3 vertices or a repeated index dropped, --skip-invalid, fan triangulation). Every reader refuses
// header counts the file cannot hold before anything is sized by them, and checks every index
// against the vertex count, so the soup it returns is safe to index.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/huge_pages.h"
#include "core/types.h"
#include "mesh/io.h"
#include "mesh/mesh.h"

namespace curvbench::io_detail {

/// Mesh indexes with int: no count in a file may exceed this.
constexpr unsigned long long kMaxCount =
    static_cast<unsigned long long>(std::numeric_limits<int>::max());

constexpr const char* kSkipHint = " (--skip-invalid drops such vertices)";

/// A growable flat array kept in the storage of an m x 3 row-major Eigen matrix (VertexMatrix,
/// FaceMatrix), so that the Mesh takes it over without a copy (take()). Storage of 4 MiB or more
/// is advised to huge pages (core/huge_pages.h) and never zero-filled.
template <typename T>
class FlatRows {
 public:
  using Matrix = Eigen::Matrix<T, Eigen::Dynamic, 3, Eigen::RowMajor>;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const T* data() const { return m_.data(); }
  const T& operator[](std::size_t i) const { return m_.data()[i]; }
  T& operator[](std::size_t i) { return m_.data()[i]; }

  void reserve(std::size_t n) {
    if (n > capacity()) grow_to(n);
  }
  void push_back(T x) {
    if (size_ == capacity()) grow_to(std::max<std::size_t>(2 * capacity(), 48));
    m_.data()[size_++] = x;
  }
  void append(const T* first, std::size_t k) {
    if (size_ + k > capacity()) grow_to(std::max(size_ + k, 2 * capacity()));
    std::copy(first, first + k, m_.data() + size_);
    size_ += k;
  }
  /// The first size() / 3 rows as a matrix (without a copy when the storage fits); leaves this
  /// empty.
  Matrix take() {
    const auto rows = static_cast<Eigen::Index>(size_ / 3);
    if (m_.rows() != rows) m_.conservativeResize(rows, 3);
    size_ = 0;
    return std::move(m_);
  }
  /// Frees the storage.
  void release() {
    m_ = Matrix();
    size_ = 0;
  }

 private:
  std::size_t capacity() const { return static_cast<std::size_t>(m_.size()); }
  void grow_to(std::size_t n) {
    Matrix bigger(static_cast<Eigen::Index>((n + 2) / 3), 3);
    advise_huge_pages(bigger.data(), sizeof(T) * static_cast<std::size_t>(bigger.size()));
    std::copy(m_.data(), m_.data() + size_, bigger.data());
    m_.swap(bigger);
  }

  Matrix m_;
  std::size_t size_ = 0;
};

/// Vertices (x, y, z as read) and polygons (vertex indices, each checked < num_vertices()).
struct Soup {
  FlatRows<double> xyz;  ///< 3 per vertex
  /// The normals the file gives (nx ny nz, 3 per vertex, as read), or empty: it gives none.
  FlatRows<double> normals;
  FlatRows<std::int32_t> indices;  ///< all polygons' indices, in file order
  /// Polygon f is indices[starts[f], starts[f + 1]); empty while every polygon is a triangle
  /// (polygon f is then indices[3 f, 3 f + 3)), which saves a word per face on the usual file.
  std::vector<std::size_t> starts;
  std::size_t polygons = 0;
  bool skip_invalid = false;                  ///< MeshReadOptions::skip_invalid
  std::vector<unsigned long long> nonfinite;  ///< vertices with a non-finite text token, increasing

  std::size_t num_vertices() const { return xyz.size() / 3; }
  std::size_t num_polygons() const { return polygons; }
  bool all_triangles() const { return starts.empty(); }
  std::size_t polygon_begin(std::size_t f) const { return starts.empty() ? 3 * f : starts[f]; }
  std::size_t polygon_size(std::size_t f) const {
    return starts.empty() ? 3 : starts[f + 1] - starts[f];
  }
  /// Ends the polygon whose indices were appended since the last call.
  void end_polygon() {
    ++polygons;
    if (starts.empty()) {
      if (indices.size() == 3 * polygons) return;
      // The first polygon that is not a triangle: the starts of the triangles before it.
      starts.reserve(polygons + 1);
      for (std::size_t f = 0; f < polygons; ++f) starts.push_back(3 * f);
    }
    starts.push_back(indices.size());
  }

  /// Appends `count` triangles (3 indices each, already checked) while every polygon so far is a
  /// triangle (all_triangles()): the same soup as end_polygon() after each.
  void add_triangles(const std::int32_t* corners, std::size_t count) {
    indices.append(corners, 3 * count);
    polygons += count;
  }

  /// Records that vertex `v` has a non-finite coordinate token; false if not skipping (the caller
  /// then throws). The coordinate is stored as 0; the vertex is dropped later.
  bool skip(unsigned long long v) {
    if (!skip_invalid) return false;
    if (nonfinite.empty() || nonfinite.back() != v) nonfinite.push_back(v);
    return true;
  }
};

/// The readers: `text` is the whole file, `path` names it in messages. Each throws InputError
/// on the first problem (see io.h).
Soup read_off(const std::string& path, std::string_view text, bool skip_invalid);
Soup read_obj(const std::string& path, std::string_view text, bool skip_invalid);
Soup read_ply(const std::string& path, std::string_view text, bool skip_invalid);
/// .xyz, .pts, .pwn point sets (read_xyz.cpp): points, and their normals where given.
Soup read_xyz(const std::string& path, std::string_view text, bool skip_invalid);

/// Builds the Mesh from a reader's soup (soup_to_mesh.cpp): drops polygons with fewer than 3
/// vertices or a repeated index; refuses non-finite coordinates or, with skip_invalid (as the
/// reader was told), drops those vertices and the polygons using them and renumbers;
/// fan-triangulates (v0, vi, vi+1) the rest. `format` names the reader in messages; `report`
/// (may be null) receives the counts.
Mesh soup_to_mesh(const std::string& path, const std::string& format, Soup soup,
                  MeshReadReport* report);

/// Binary PLY straight from an open file (`fd`, `size` bytes), read in blocks through a small
/// buffer instead of the whole file in memory; the same soup and the same errors as read_ply on
/// the file's bytes. Returns false, reading nothing into `soup`, when the file is not binary PLY
/// with its header in the first 64 KiB: the caller then uses read_ply.
bool read_binary_ply_file(const std::string& path, int fd, unsigned long long size,
                          bool skip_invalid, Soup* soup);

// ---- errors ------------------------------------------------------------------------------------

[[noreturn]] void fail(const std::string& path, const std::string& what);
[[noreturn]] void fail_line(const std::string& path, std::size_t line, const std::string& what);

/// A token from the file, quoted for a one-line message: non-printable bytes become '?', long
/// tokens are cut.
std::string quote(std::string_view token);

/// Refuses a negative or out-of-range index of face `face` (on `line`).
void check_face_index(const std::string& path, std::size_t line, unsigned long long face,
                      long long index, unsigned long long num_vertices);

/// Refuses a soup without vertices (a soup without polygons is a point set).
void check_not_empty(const std::string& path, unsigned long long vertices,
                     unsigned long long faces);

// ---- text scanning -----------------------------------------------------------------------------

inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// Splits `line` at blanks into views.
inline void split(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  std::size_t i = 0;
  const std::size_t n = line.size();
  for (;;) {
    while (i < n && is_blank(line[i])) ++i;
    if (i == n) return;
    const std::size_t j = i;
    while (i < n && !is_blank(line[i])) ++i;
    tokens.push_back(line.substr(j, i - j));
  }
}

/// Drops everything from the first '#' on.
inline std::string_view strip_comment(std::string_view line) {
  const std::size_t pos = line.find('#');
  return pos == std::string_view::npos ? line : line.substr(0, pos);
}

/// Iterates the '\n'-separated lines of a text, counting them from 1.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}

  bool next(std::string_view* line) {
    if (pos_ >= text_.size()) return false;
    const std::size_t end = text_.find('\n', pos_);
    const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
    *line = text_.substr(pos_, stop - pos_);
    pos_ = end == std::string_view::npos ? text_.size() : end + 1;
    ++number_;
    return true;
  }

  /// Next line with at least one token after comment stripping; false at the end of the text.
  bool next_tokens(std::vector<std::string_view>& tokens, bool comments) {
    std::string_view line;
    while (next(&line)) {
      split(comments ? strip_comment(line) : line, tokens);
      if (!tokens.empty()) return true;
    }
    return false;
  }

  std::size_t number() const { return number_; }  ///< number of the line last returned
  std::size_t offset() const { return pos_; }     ///< offset just past that line

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

enum class Number { kOk, kBad, kOverflow };

/// Parses a whole token as a double like `std::istream >> double` would (optional '+', decimal or
/// scientific; an underflow gives the tiny or zero value strtod gives). "nan"/"inf" parse to
/// non-finite values, which the callers reject. kOverflow: beyond the double range.
Number parse_double(std::string_view token, double* value);

/// The same for a float (`std::istream >> float`, as CGAL reads a PLY float property): the
/// decimal rounded once, to float. kOverflow: beyond the float range.
Number parse_float(std::string_view token, float* value);

/// Parses a whole token as a decimal integer (optional sign).
bool parse_integer(std::string_view token, long long* value);

/// Parses a header count: a non-negative integer, digits only.
bool parse_count(std::string_view token, unsigned long long* value);

}  // namespace curvbench::io_detail
