// Internal to the mesh readers (not installed): the polygon soup each format reader builds in its
// single validating pass, and the text-scanning and error helpers the readers share.
//
// read_mesh (io.cpp) picks the reader by extension (read_off.cpp, read_obj.cpp, read_ply.cpp),
// hands it the whole file, and turns the soup into a Mesh (soup_to_mesh: polygons with fewer than
// 3 vertices or a repeated index dropped, --skip-invalid, fan triangulation). Every reader refuses
// header counts the file cannot hold before anything is sized by them, and checks every index
// against the vertex count, so the soup it returns is safe to index.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace curvbench::io_detail {

/// Mesh indexes with int: no count in a file may exceed this.
constexpr unsigned long long kMaxCount =
    static_cast<unsigned long long>(std::numeric_limits<int>::max());

constexpr const char* kSkipHint = " (--skip-invalid drops such vertices)";

/// Vertices (x, y, z as read) and polygons (vertex indices, each checked < num_vertices()).
struct Soup {
  std::vector<double> xyz;                    ///< 3 per vertex
  std::vector<std::int32_t> indices;          ///< all polygons' indices, in file order
  std::vector<std::size_t> starts = {0};      ///< polygon f is indices[starts[f], starts[f + 1])
  bool skip_invalid = false;                  ///< MeshReadOptions::skip_invalid
  std::vector<unsigned long long> nonfinite;  ///< vertices with a non-finite text token, increasing

  std::size_t num_vertices() const { return xyz.size() / 3; }
  std::size_t num_polygons() const { return starts.size() - 1; }
  void end_polygon() { starts.push_back(indices.size()); }

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

// ---- errors ------------------------------------------------------------------------------------

[[noreturn]] void fail(const std::string& path, const std::string& what);
[[noreturn]] void fail_line(const std::string& path, std::size_t line, const std::string& what);

/// A token from the file, quoted for a one-line message: non-printable bytes become '?', long
/// tokens are cut.
std::string quote(std::string_view token);

/// Refuses a negative or out-of-range index of face `face` (on `line`).
void check_face_index(const std::string& path, std::size_t line, unsigned long long face,
                      long long index, unsigned long long num_vertices);

/// Refuses a soup without vertices or polygons.
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
