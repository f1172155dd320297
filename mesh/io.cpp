// Mesh file input and output (contract in io.h).
//
// Reading holds the whole file in memory and makes two passes over it:
//   1. A validating pre-read of our own (check_off / check_obj / check_ply). It walks the whole
//      file without ever allocating by a declared count, refuses headers that declare more
//      elements than the file could hold, and reports the first problem with its line number (or
//      element number for binary PLY): bad header, truncated body, data after the declared
//      elements (wrong counts), non-numeric token, non-finite coordinate (recorded instead with
//      skip_invalid), negative or out-of-range index.
//   2. CGAL::IO::read_OFF / read_OBJ / read_PLY into a polygon soup (points + index lists), which
//      soup_to_mesh filters (polygons with fewer than 3 vertices or a repeated index dropped;
//      skipped vertices and their polygons dropped) and fan-triangulates into a Mesh.
// The pre-read exists because CGAL 5.5's readers accept much malformed input silently and
// allocate by header counts before reading (see the notes above each check_* function); after it
// has passed, CGAL only sees input it handles correctly.
//
// Writing goes to a temporary file in the target directory that is renamed into place, so a
// failure never leaves a partial file behind.
#include "mesh/io.h"

#include <fcntl.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <unistd.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Simple_cartesian.h>
#include <algorithm>
#include <atomic>
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
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

#include "core/errors.h"
#include "core/text.h"

namespace curvbench {

namespace {

namespace fs = std::filesystem;

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Polygon = std::vector<std::size_t>;

constexpr unsigned long long kMaxCount =
    static_cast<unsigned long long>(std::numeric_limits<int>::max());  // Mesh indexes with int

// ---- errors ------------------------------------------------------------------------------------

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

[[noreturn]] void fail_line(const std::string& path, std::size_t line, const std::string& what) {
  fail(path, "line " + std::to_string(line) + ": " + what);
}

/// A token from the file, quoted for a one-line message: non-printable bytes become '?', long
/// tokens are cut.
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

// ---- text scanning -----------------------------------------------------------------------------

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// Splits `line` at blanks into views.
void split(std::string_view line, std::vector<std::string_view>& tokens) {
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
std::string_view strip_comment(std::string_view line) {
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

/// Whitespace-separated tokens across lines (PLY ASCII data ignores line structure).
class Tokens {
 public:
  Tokens(std::string_view text, std::size_t pos, std::size_t line)
      : text_(text), pos_(pos), line_(line) {}

  bool next(std::string_view* token) {
    const std::size_t n = text_.size();
    while (pos_ < n && (is_blank(text_[pos_]) || text_[pos_] == '\n')) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ == n) return false;
    const std::size_t start = pos_;
    while (pos_ < n && !is_blank(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    *token = text_.substr(start, pos_ - start);
    return true;
  }

  std::size_t line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t pos_;
  std::size_t line_;
};

enum class Number { kOk, kBad, kOverflow };

/// Parses a whole token as a double like `std::istream >> double` would (optional '+', decimal or
/// scientific). "nan"/"inf" parse to non-finite values, which the callers reject: the C++
/// stream extraction CGAL uses cannot read them. kOverflow: beyond the double range.
Number parse_double(std::string_view token, double* value) {
  std::string_view s = token;
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && s.front() == '-') return Number::kBad;
  }
  if (s.empty()) return Number::kBad;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), *value);
  if (ec == std::errc::invalid_argument || ptr != s.data() + s.size()) return Number::kBad;
  if (ec == std::errc::result_out_of_range) {
    // from_chars does not say which way; strtod returns +-HUGE_VAL on overflow, a tiny value on
    // underflow (which the stream extraction accepts).
    *value = std::strtod(std::string(s).c_str(), nullptr);
    return std::isinf(*value) ? Number::kOverflow : Number::kOk;
  }
  return Number::kOk;
}

/// Parses a whole token as a decimal integer (optional sign).
bool parse_integer(std::string_view token, long long* value) {
  std::string_view s = token;
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && s.front() == '-') return false;
  }
  if (s.empty()) return false;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), *value);
  return ec == std::errc() && ptr == s.data() + s.size();
}

/// Parses a header count: a non-negative integer, digits only.
bool parse_count(std::string_view token, unsigned long long* value) {
  if (token.empty() || !std::isdigit(static_cast<unsigned char>(token.front()))) return false;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return ec == std::errc() && ptr == token.data() + token.size();
}

// Soup sizes found by a pre-read.
struct SoupCounts {
  unsigned long long vertices = 0;
  unsigned long long faces = 0;
};

/// Non-finite coordinates met by a pre-read. With skip_invalid they are recorded instead of
/// refused: the vertex (to be dropped with its faces) and the token's bytes in the text, which
/// read_mesh overwrites with "0" before CGAL reads it (CGAL's stream extraction cannot parse
/// "nan" or "inf" and would fail the whole file).
// (offset, length) of a stretch of the file text.
using TextSpan = std::pair<std::size_t, std::size_t>;

// The span from the start of token `first` to the end of token `last` (views into text).
TextSpan token_span(std::string_view text, std::string_view first, std::string_view last) {
  const auto begin = static_cast<std::size_t>(first.data() - text.data());
  return {begin, static_cast<std::size_t>(last.data() + last.size() - text.data()) - begin};
}

struct NonFinite {
  bool skip_invalid = false;
  std::vector<unsigned long long> vertices;  // increasing, no repeats
  std::vector<TextSpan> spans;               // the tokens in the text

  /// Records vertex `v`'s coordinate `token` (a view into `text`); false if not skipping.
  bool skip(std::string_view text, std::string_view token, unsigned long long v) {
    if (!skip_invalid) return false;
    if (vertices.empty() || vertices.back() != v) vertices.push_back(v);
    spans.push_back(token_span(text, token, token));
    return true;
  }
};

constexpr const char* kSkipHint = " (--skip-invalid drops such vertices)";

void check_not_empty(const std::string& path, const SoupCounts& counts) {
  if (counts.vertices == 0) fail(path, "empty mesh: no vertices");
  if (counts.faces == 0) fail(path, "empty mesh: no faces");
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

// ---- OFF pre-read ------------------------------------------------------------------------------
//
// CGAL 5.5's read_OFF (File_scanner_OFF) reads the header counts into int and resizes the point
// and polygon vectors to them before reading a single vertex; parses every body line as doubles
// and stops silently at the first non-number ("0 0 0x" is accepted); casts face sizes and indices
// from double to size_t (a size "3.9" or an index "1.7" is truncated, a huge size is resized to
// before the line is checked); ignores extra indices; accepts faces with 0, 1 or 2 vertices; reads
// binary OFF without the per-face color count of the Geomview format (every face after the first
// is misread); reads STOFF texture coordinates through uninitialized members; and converts color
// entries without range checks (a color-map index 1e300 is cast to int: undefined behaviour;
// found by fuzzing, tests/corpus/regressions/off_*color*). Colors are not used by curvbench, so
// the pre-read records where they are (`colors`) and read_mesh blanks them out before CGAL reads.

struct OffLayout {
  bool colors = false;
  bool normals = false;
  bool homogeneous = false;
};

OffLayout parse_off_keyword(const std::string& path, std::size_t line, std::string_view keyword) {
  // [ST][C][N][4][n]OFF, in this order, as File_header_OFF scans it.
  OffLayout layout;
  std::string_view k = keyword;
  bool textures = false, n_dimensional = false;
  if (k.starts_with("ST")) textures = true, k.remove_prefix(2);
  if (k.starts_with("C")) layout.colors = true, k.remove_prefix(1);
  if (k.starts_with("N")) layout.normals = true, k.remove_prefix(1);
  if (k.starts_with("4")) layout.homogeneous = true, k.remove_prefix(1);
  if (k.starts_with("n")) n_dimensional = true, k.remove_prefix(1);
  if (k == "SKEL") fail_line(path, line, "bad OFF header: SKEL files hold no surface");
  if (k != "OFF")
    fail_line(path, line,
              "bad OFF header: expected OFF (or COFF, NOFF, 4OFF, ...), found " + quote(keyword));
  if (textures)
    fail_line(path, line,
              "bad OFF header: texture coordinates (" + quote(keyword) + ") are not supported");
  if (n_dimensional)
    fail_line(
        path, line,
        "bad OFF header: nOFF (arbitrary dimension, " + quote(keyword) + ") is not supported");
  return layout;
}

SoupCounts check_off(const std::string& path, std::string_view text, NonFinite& nonfinite,
                     std::vector<TextSpan>& colors) {
  Lines lines(text);
  std::vector<std::string_view> tok;
  if (!lines.next_tokens(tok, true)) fail(path, "bad OFF header: the file is empty");
  const OffLayout layout = parse_off_keyword(path, lines.number(), tok[0]);

  // The counts follow the keyword, on the same line or on the next non-blank line.
  std::vector<std::string_view> counts(tok.begin() + 1, tok.end());
  if (counts.empty()) {
    if (!lines.next_tokens(tok, true)) fail(path, "bad OFF header: no vertex/face/edge counts");
    counts = tok;
  }
  if (counts[0] == "BINARY")
    fail_line(path, lines.number(), "binary OFF is not supported (use ASCII OFF or PLY)");
  if (counts.size() != 3)
    fail_line(path, lines.number(),
              "bad OFF header: expected 3 counts (vertices faces edges), found " +
                  std::to_string(counts.size()) + " numbers");
  SoupCounts n;
  long long edges;
  if (!parse_count(counts[0], &n.vertices))
    fail_line(
        path, lines.number(),
        "bad OFF header: vertex count " + quote(counts[0]) + " is not a non-negative integer");
  if (!parse_count(counts[1], &n.faces))
    fail_line(path, lines.number(),
              "bad OFF header: face count " + quote(counts[1]) + " is not a non-negative integer");
  if (!parse_integer(counts[2], &edges) || edges < std::numeric_limits<int>::min() ||
      edges > std::numeric_limits<int>::max())
    fail_line(path, lines.number(),
              "bad OFF header: edge count " + quote(counts[2]) + " is not an integer");

  // Refuse counts the file cannot hold before anything is sized by them: a vertex line takes at
  // least 6 bytes ("0 0 0\n"), a face line at least 2 (the empty face "0\n", dropped later); the
  // last newline may miss. (The walk below then finds every declared line before CGAL sizes its
  // arrays by the counts, so CGAL's allocations stay proportional to the file's size.)
  const unsigned long long body = text.size() - lines.offset() + 1;
  if (n.vertices > body || n.faces > body || 6 * n.vertices + 2 * n.faces > body)
    fail(path, "OFF header declares " + std::to_string(n.vertices) + " vertices and " +
                   std::to_string(n.faces) + " faces, more than a " + std::to_string(text.size()) +
                   "-byte file can hold (truncated file or corrupt header)");
  if (n.vertices > kMaxCount || n.faces > kMaxCount)
    fail(path, "OFF header declares more than " + std::to_string(kMaxCount) + " elements");

  // A short last line without its newline is a cut file, not a malformed record.
  auto short_line = [&](std::size_t line, const std::string& what, const std::string& problem) {
    if (lines.offset() >= text.size() && !text.ends_with('\n'))
      fail(path, "truncated OFF body: the file ends inside " + what + " (line " +
                     std::to_string(line) + ")");
    fail_line(path, line, what + problem);
  };

  const std::size_t coords = layout.homogeneous ? 4 : 3;
  const std::size_t normals = layout.normals ? coords : 0;
  for (unsigned long long v = 0; v < n.vertices; ++v) {
    if (!lines.next_tokens(tok, true))
      fail(path, "truncated OFF body: the file ends after " + std::to_string(v) + " of " +
                     std::to_string(n.vertices) + " vertices");
    const std::size_t line = lines.number();
    const std::string what = "vertex " + std::to_string(v);
    for (std::size_t i = 0; i < tok.size(); ++i) {
      double x;
      const Number r = parse_double(tok[i], &x);
      if (r == Number::kBad) fail_line(path, line, what + ": non-numeric token " + quote(tok[i]));
      if (r == Number::kOverflow || !std::isfinite(x)) {
        if (i < 3 && nonfinite.skip(text, tok[i], v)) continue;
        fail_line(path, line,
                  what + (i < 3 ? " has a non-finite coordinate " : " has a non-finite value ") +
                      quote(tok[i]) + (i < 3 ? kSkipHint : ""));
      }
      if (layout.homogeneous && i == 3 && x == 0.0)
        fail_line(path, line, what + " has homogeneous weight w = 0");
    }
    if (tok.size() < coords + normals)
      short_line(line, what,
                 " has " + std::to_string(tok.size()) + " numbers, expected at least " +
                     std::to_string(coords + normals));
    const std::size_t color = tok.size() - coords - normals;
    if (layout.colors && color != 0 && color != 1 && color != 3 && color != 4)
      fail_line(
          path, line,
          what + " has a color with " + std::to_string(color) + " components (expected 1, 3 or 4)");
    if (color > 0) colors.push_back(token_span(text, tok[coords + normals], tok.back()));
  }

  for (unsigned long long f = 0; f < n.faces; ++f) {
    if (!lines.next_tokens(tok, true))
      fail(path, "truncated OFF body: the file ends after " + std::to_string(f) + " of " +
                     std::to_string(n.faces) + " faces");
    const std::size_t line = lines.number();
    const std::string what = "face " + std::to_string(f);
    long long size;
    if (!parse_integer(tok[0], &size) || size < 0)
      fail_line(path, line,
                what + ": vertex count " + quote(tok[0]) + " is not a non-negative integer" +
                    (f == 0 ? " (the header declares " + std::to_string(n.vertices) +
                                  " vertices: wrong counts?)"
                            : ""));
    if (tok.size() - 1 < static_cast<unsigned long long>(size))
      short_line(line, what,
                 " declares " + std::to_string(size) + " vertices but lists " +
                     std::to_string(tok.size() - 1) + " indices");
    for (std::size_t j = 1; j <= static_cast<std::size_t>(size); ++j) {
      long long index;
      if (!parse_integer(tok[j], &index))
        fail_line(path, line, what + ": vertex index " + quote(tok[j]) + " is not an integer");
      check_face_index(path, line, f, index, n.vertices);
    }
    // A face may carry a color in any OFF variant (Geomview); anything else is misplaced data.
    const std::size_t color = tok.size() - 1 - static_cast<std::size_t>(size);
    if (color != 0 && color != 1 && color != 3 && color != 4)
      fail_line(path, line,
                what + " has " + std::to_string(color) +
                    " values after its indices (a color has 1, 3 or 4; wrong counts in the "
                    "header?)");
    if (color > 0) colors.push_back(token_span(text, tok[tok.size() - color], tok.back()));
  }
  if (lines.next_tokens(tok, true))
    fail_line(path, lines.number(),
              "data after the last of the " + std::to_string(n.vertices) + " vertices and " +
                  std::to_string(n.faces) + " faces the header declares (wrong counts?)");
  return n;
}

// ---- OBJ pre-read ------------------------------------------------------------------------------
//
// CGAL 5.5's read_OBJ ends a face silently at the first non-integer token ("f 1 2 x" gives a
// 2-gon, a lone "f" an empty polygon), skips up to the next ' ' after each index, so tab-separated
// indices are lost ("f 1\t2\t3" gives the 1-gon [0]; tabs are turned into spaces before CGAL reads
// the file), treats index 0 as a relative reference (= the current vertex count) and checks the
// largest index with an off-by-one (an index one past the last vertex is accepted).

// Statements CGAL's read_OBJ skips (everything else is an error there too).
bool obj_ignored_statement(std::string_view s) {
  static constexpr std::string_view kIgnored[] = {
      "vt",     "vn",    "vp",       "bevel",    "lod",        "ctech",     "c_interp", "usemap",
      "usemtl", "stech", "d_interp", "mtllib",   "shadow_obj", "trace_obj", "o",        "g",
      "s",      "p",     "cstype",   "deg",      "step",       "bmat",      "con",      "curv",
      "curv2",  "surf",  "parm",     "trim",     "hole",       "scrv",      "sp",       "end",
      "surf_1", "q0_1",  "q1_1",     "curv2d_1", "surf_2",     "q0_2",      "q1_2",     "curv2d_2",
      "bsp",    "bzp",   "cdc",      "cdp",      "res"};
  return std::find(std::begin(kIgnored), std::end(kIgnored), s) != std::end(kIgnored);
}

SoupCounts check_obj(const std::string& path, std::string_view text, NonFinite& nonfinite) {
  Lines lines(text);
  std::vector<std::string_view> tok;
  SoupCounts n;
  long long max_index = -1;  // largest positive (absolute) index, 0-based, and where it was
  std::size_t max_line = 0;
  unsigned long long max_face = 0;
  while (lines.next_tokens(tok, true)) {
    const std::size_t line = lines.number();
    if (tok[0] == "v") {
      const std::string what = "vertex " + std::to_string(n.vertices);
      if (tok.size() < 4)
        fail_line(path, line,
                  what + " has " + std::to_string(tok.size() - 1) + " coordinates, expected 3");
      for (std::size_t i = 1; i <= 3; ++i) {
        double x;
        const Number r = parse_double(tok[i], &x);
        if (r == Number::kBad) fail_line(path, line, what + ": non-numeric token " + quote(tok[i]));
        if ((r == Number::kOverflow || !std::isfinite(x)) &&
            !nonfinite.skip(text, tok[i], n.vertices))
          fail_line(path, line, what + " has a non-finite coordinate " + quote(tok[i]) + kSkipHint);
      }
      ++n.vertices;
    } else if (tok[0] == "f") {
      const std::string what = "face " + std::to_string(n.faces);
      for (std::size_t j = 1; j < tok.size(); ++j) {
        // v, v/vt, v//vn or v/vt/vn: the vertex index is before the first '/'.
        const std::string_view v = tok[j].substr(0, tok[j].find('/'));
        long long index;
        if (!parse_integer(v, &index) || index < std::numeric_limits<int>::min() ||
            index > std::numeric_limits<int>::max())
          fail_line(path, line, what + ": vertex index " + quote(tok[j]) + " is not an integer");
        if (index == 0)
          fail_line(path, line, what + ": vertex index 0 is invalid (OBJ indices start at 1)");
        if (index < 0 && static_cast<unsigned long long>(-index) > n.vertices)
          fail_line(path, line,
                    what + ": relative vertex index " + std::to_string(index) +
                        " refers before the first vertex");
        if (index > 0 && index - 1 > max_index) {
          max_index = index - 1;
          max_line = line;
          max_face = n.faces;
        }
      }
      ++n.faces;
    } else if (!obj_ignored_statement(tok[0])) {
      fail_line(path, line, "unsupported OBJ statement " + quote(tok[0]));
    }
  }
  if (max_index >= 0 && static_cast<unsigned long long>(max_index) >= n.vertices)
    fail_line(path, max_line,
              "face " + std::to_string(max_face) + " references vertex " +
                  std::to_string(max_index + 1) + " (1-based), but the file has " +
                  std::to_string(n.vertices) + " vertices");
  return n;
}

// ---- PLY pre-read ------------------------------------------------------------------------------
//
// CGAL 5.5's read_PLY skips header lines it does not understand, including properties of an
// unknown type (the data is then read misaligned, silently); fills a missing x, y or z property
// with 0; dereferences a null pointer when x, y or z is an integer property; reads ASCII uchar
// values through unsigned short and truncates (a list length 259 becomes 3); reads "-1" into a
// uint index as 4294967295; and resizes each list to its length before reading the entries (a
// binary int list length of 2^31 asks for 8 GB).

enum class PlyType { kChar, kUchar, kShort, kUshort, kInt, kUint, kFloat, kDouble };

struct PlyTypeInfo {
  std::string_view name, alias;
  PlyType type;
  int size;
  bool integer;
  long long min, max;  // for integer types
};

constexpr PlyTypeInfo kPlyTypes[] = {
    {"char", "int8", PlyType::kChar, 1, true, -128, 127},
    {"uchar", "uint8", PlyType::kUchar, 1, true, 0, 255},
    {"short", "int16", PlyType::kShort, 2, true, -32768, 32767},
    {"ushort", "uint16", PlyType::kUshort, 2, true, 0, 65535},
    {"int", "int32", PlyType::kInt, 4, true, -2147483648LL, 2147483647LL},
    {"uint", "uint32", PlyType::kUint, 4, true, 0, 4294967295LL},
    {"float", "float32", PlyType::kFloat, 4, false, 0, 0},
    {"double", "float64", PlyType::kDouble, 8, false, 0, 0},
};

const PlyTypeInfo* ply_type(std::string_view name) {
  for (const PlyTypeInfo& t : kPlyTypes)
    if (name == t.name || name == t.alias) return &t;
  return nullptr;
}

struct PlyProperty {
  std::string name;
  const PlyTypeInfo* type = nullptr;  // value type (entry type of a list)
  const PlyTypeInfo* size = nullptr;  // length type; non-null for a list
};

struct PlyElement {
  std::string name;
  unsigned long long count;
  std::vector<PlyProperty> properties;

  const PlyProperty* find(std::string_view property) const {
    for (const PlyProperty& p : properties)
      if (p.name == property) return &p;
    return nullptr;
  }
};

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  std::size_t body = 0;       // byte offset of the data section
  std::size_t body_line = 0;  // its line number (ASCII)
};

PlyHeader parse_ply_header(const std::string& path, std::string_view text) {
  PlyHeader h;
  Lines lines(text);
  std::vector<std::string_view> tok;
  std::string_view line;
  if (lines.next(&line)) split(line, tok);
  if (lines.number() != 1 || tok.size() != 1 || tok[0] != "ply")
    fail(path, "bad PLY header: the first line is not 'ply'");
  tok.clear();
  if (lines.next(&line)) split(line, tok);
  if (tok.size() != 3 || tok[0] != "format")
    fail_line(path, 2, "bad PLY header: expected 'format <ascii|binary_...> 1.0'");
  if (tok[1] == "ascii")
    h.format = PlyFormat::kAscii;
  else if (tok[1] == "binary_little_endian")
    h.format = PlyFormat::kBinaryLittleEndian;
  else if (tok[1] == "binary_big_endian")
    h.format = PlyFormat::kBinaryBigEndian;
  else
    fail_line(path, 2, "bad PLY header: unknown format " + quote(tok[1]));

  for (;;) {
    if (!lines.next(&line)) fail(path, "bad PLY header: no end_header line");
    const std::size_t n = lines.number();
    split(line, tok);
    if (tok.empty()) fail_line(path, n, "bad PLY header: empty line");
    if (tok[0] == "end_header") break;
    if (tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "element") {
      unsigned long long count;
      if (tok.size() != 3 || !parse_count(tok[2], &count))
        fail_line(path, n, "bad PLY header: expected 'element <name> <count>'");
      for (const PlyElement& e : h.elements)
        if (e.name == tok[1])
          fail_line(path, n, "bad PLY header: element " + quote(tok[1]) + " declared twice");
      h.elements.push_back({std::string(tok[1]), count, {}});
    } else if (tok[0] == "property") {
      if (h.elements.empty())
        fail_line(path, n, "bad PLY header: property before the first element");
      PlyProperty p;
      if (tok.size() == 5 && tok[1] == "list") {
        p.size = ply_type(tok[2]);
        p.type = ply_type(tok[3]);
        p.name = tok[4];
        if (p.size == nullptr || !p.size->integer)
          fail_line(path, n, "bad PLY header: invalid list length type " + quote(tok[2]));
        if (p.type == nullptr)
          fail_line(path, n, "bad PLY header: unknown property type " + quote(tok[3]));
      } else if (tok.size() == 3) {
        p.type = ply_type(tok[1]);
        p.name = tok[2];
        if (p.type == nullptr)
          fail_line(path, n, "bad PLY header: unknown property type " + quote(tok[1]));
      } else {
        fail_line(path, n, "bad PLY header: malformed property line");
      }
      if (h.elements.back().find(p.name) != nullptr)
        fail_line(path, n, "bad PLY header: property " + quote(p.name) + " declared twice");
      h.elements.back().properties.push_back(std::move(p));
    } else {
      fail_line(path, n, "bad PLY header: unexpected line starting with " + quote(tok[0]));
    }
  }
  h.body = lines.offset();
  h.body_line = lines.number() + 1;
  return h;
}

/// The element named `a` or `b` (CGAL accepts either); null if there is none or there are two.
const PlyElement* find_element(const PlyHeader& h, std::string_view a, std::string_view b) {
  const PlyElement* found = nullptr;
  for (const PlyElement& e : h.elements)
    if (e.name == a || e.name == b) found = found ? nullptr : &e;
  return found;
}

/// Reads an integer of PLY type `t` at `p` (binary).
long long read_binary_integer(const char* p, const PlyTypeInfo& t, bool big_endian) {
  unsigned char b[8];
  std::memcpy(b, p, t.size);
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(b, b + t.size);
  switch (t.type) {
    case PlyType::kChar: {
      std::int8_t v;
      std::memcpy(&v, b, 1);
      return v;
    }
    case PlyType::kUchar:
      return b[0];
    case PlyType::kShort: {
      std::int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case PlyType::kUshort: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case PlyType::kInt: {
      std::int32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case PlyType::kUint: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    default:
      return 0;  // not an integer type; never called so
  }
}

SoupCounts check_ply(const std::string& path, std::string_view text, NonFinite& nonfinite) {
  const PlyHeader h = parse_ply_header(path, text);

  // What CGAL's read_PLY needs: a vertex element with float/double x, y, z ...
  const PlyElement* vertex = find_element(h, "vertex", "vertices");
  if (vertex == nullptr) fail(path, "PLY file has no (single) 'vertex' element");
  const PlyProperty* xyz[3];
  for (int c = 0; c < 3; ++c) {
    const char* name = c == 0 ? "x" : (c == 1 ? "y" : "z");
    xyz[c] = vertex->find(name);
    if (xyz[c] == nullptr) fail(path, std::string("PLY vertex element has no '") + name + "'");
    if (xyz[c]->size != nullptr || xyz[c]->type->integer)
      fail(path, std::string("PLY vertex property '") + name +
                     "' must be float or double (CGAL's reader cannot read other types)");
  }
  // ... a face element with an int or uint list named vertex_indices or vertex_index ...
  const PlyElement* face = find_element(h, "face", "faces");
  if (face == nullptr) fail(path, "empty mesh: PLY file has no 'face' element");
  const PlyProperty* indices = nullptr;
  for (const char* name : {"vertex_indices", "vertex_index"}) {
    const PlyProperty* p = face->find(name);
    if (indices == nullptr && p != nullptr && p->size != nullptr &&
        (p->type->type == PlyType::kInt || p->type->type == PlyType::kUint))
      indices = p;
  }
  if (indices == nullptr)
    fail(path, "PLY face element has no 'vertex_indices' list of int or uint");
  // ... and, for a halfedge element, uint source/target (CGAL crashes on other types).
  for (const PlyElement& e : h.elements)
    if (e.name == "halfedge")
      for (const char* name : {"source", "target"})
        if (const PlyProperty* p = e.find(name);
            p != nullptr && (p->size != nullptr || p->type->type != PlyType::kUint))
          fail(path, std::string("PLY halfedge property '") + name + "' must be uint");

  // Refuse counts the data section cannot hold: a binary item takes at least its fixed-size
  // fields and list lengths, an ASCII item at least 2 bytes per property ("0 ").
  const bool ascii = h.format == PlyFormat::kAscii;
  const unsigned long long body = text.size() - h.body + (ascii ? 1 : 0);
  unsigned long long need = 0;
  bool absurd = false;
  std::string declared;
  for (const PlyElement& e : h.elements) {
    unsigned long long item = 0;
    for (const PlyProperty& p : e.properties)
      item += ascii ? 2 : (p.size != nullptr ? p.size->size : p.type->size);
    if (e.count > body) absurd = true;
    if (!absurd) need += e.count * item;  // < 2^40 * 2^20: no overflow
    declared += (declared.empty() ? "" : ", ") + std::to_string(e.count) + " '" + e.name + "'";
  }
  if (absurd || need > body)
    fail(path, "PLY header declares " + declared + " elements, more than the " +
                   std::to_string(text.size() - h.body) +
                   "-byte data section can hold (truncated file or corrupt header)");
  const SoupCounts n{vertex->count, face->count};
  if (n.vertices > kMaxCount || n.faces > kMaxCount)
    fail(path, "PLY header declares more than " + std::to_string(kMaxCount) + " elements");

  // Walk the data.
  if (ascii) {
    Tokens tokens(text, h.body, h.body_line);
    std::string_view t;
    for (const PlyElement& e : h.elements) {
      for (unsigned long long j = 0; j < e.count; ++j) {
        const std::string what = e.name + " " + std::to_string(j);
        // One value of type `type`; returns it as long long for integer types.
        auto value = [&](const PlyProperty& p, const PlyTypeInfo& type,
                         const char* role) -> long long {
          if (!tokens.next(&t))
            fail(path, "truncated PLY data: the file ends in " + e.name + " " + std::to_string(j) +
                           " of " + std::to_string(e.count));
          if (type.integer) {
            long long v;
            if (!parse_integer(t, &v) || v < type.min || v > type.max)
              fail_line(path, tokens.line(),
                        what + ": " + role + " " + quote(t) + " of property '" + p.name +
                            "' is not a valid " + std::string(type.name));
            return v;
          }
          double x;
          const Number r = parse_double(t, &x);
          if (r == Number::kBad)
            fail_line(path, tokens.line(), what + ": non-numeric token " + quote(t));
          const bool is_coordinate = &e == vertex && (&p == xyz[0] || &p == xyz[1] || &p == xyz[2]);
          const double limit = type.type == PlyType::kFloat ? std::numeric_limits<float>::max()
                                                            : std::numeric_limits<double>::max();
          if (r == Number::kOverflow || !(std::fabs(x) <= limit)) {
            if (is_coordinate && nonfinite.skip(text, t, j)) return 0;
            fail_line(
                path, tokens.line(),
                what +
                    (is_coordinate ? " has a non-finite coordinate "
                                   : ": non-finite or out-of-range value ") +
                    quote(t) +
                    (is_coordinate ? std::string(kSkipHint) : " of property '" + p.name + "'"));
          }
          return 0;
        };
        for (const PlyProperty& p : e.properties) {
          if (p.size == nullptr) {
            value(p, *p.type, "value");
            continue;
          }
          const long long len = value(p, *p.size, "list length");
          const bool is_face_list = &e == face && &p == indices;
          for (long long k = 0; k < len; ++k) {
            const long long v = value(p, *p.type, "entry");
            if (is_face_list) check_face_index(path, tokens.line(), j, v, n.vertices);
          }
        }
      }
    }
    if (tokens.next(&t))
      fail_line(path, tokens.line(),
                "data " + quote(t) + " after the last element the header declares (" + declared +
                    "; wrong counts?)");
  } else {
    const bool big = h.format == PlyFormat::kBinaryBigEndian;
    const char* at = text.data() + h.body;
    const char* const end = text.data() + text.size();
    for (const PlyElement& e : h.elements) {
      for (unsigned long long j = 0; j < e.count; ++j) {
        auto need_bytes = [&](unsigned long long bytes) {
          if (static_cast<unsigned long long>(end - at) < bytes)
            fail(path, "truncated PLY data: the file ends in " + e.name + " " + std::to_string(j) +
                           " of " + std::to_string(e.count));
        };
        for (const PlyProperty& p : e.properties) {
          if (p.size == nullptr) {
            need_bytes(p.type->size);
            at += p.type->size;
            continue;
          }
          need_bytes(p.size->size);
          const long long len = read_binary_integer(at, *p.size, big);
          at += p.size->size;
          if (len < 0)
            fail(path, e.name + " " + std::to_string(j) + ": list '" + p.name +
                           "' has negative length " + std::to_string(len));
          const bool is_face_list = &e == face && &p == indices;
          // Compare by division: len * size could overflow.
          if (static_cast<unsigned long long>(len) >
              static_cast<unsigned long long>(end - at) / p.type->size)
            need_bytes(std::numeric_limits<unsigned long long>::max());
          if (is_face_list) {
            for (long long k = 0; k < len; ++k) {
              const long long v = read_binary_integer(at + k * p.type->size, *p.type, big);
              if (v < 0)
                fail(path, "face " + std::to_string(j) + " has a negative vertex index " +
                               std::to_string(v));
              if (static_cast<unsigned long long>(v) >= n.vertices)
                fail(path, "face " + std::to_string(j) + " references vertex " + std::to_string(v) +
                               ", out of range [0, " + std::to_string(n.vertices) + ")");
            }
          }
          at += len * p.type->size;
        }
      }
    }
    // Trailing blanks (a final newline) are harmless; anything else means wrong counts.
    const auto extra = std::find_if(at, end, [](char c) { return !is_blank(c) && c != '\n'; });
    if (extra != end)
      fail(path, std::to_string(end - at) + " bytes after the last element the header declares (" +
                     declared + "; wrong counts?)");
  }
  return n;
}

// ---- soup -> mesh ------------------------------------------------------------------------------

/// True if polygon p names a vertex twice. O(k log k) for a k-gon.
bool has_repeated_index(const Polygon& p, std::vector<std::size_t>& scratch) {
  if (p.size() == 3) return p[0] == p[1] || p[1] == p[2] || p[0] == p[2];
  scratch.assign(p.begin(), p.end());
  std::sort(scratch.begin(), scratch.end());
  return std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end();
}

/// Builds the Mesh from CGAL's soup: drops polygons with fewer than 3 vertices or a repeated
/// index; refuses non-finite coordinates or, with skip_invalid, drops those vertices and the
/// polygons using them and renumbers; fan-triangulates (v0, vi, vi+1) the rest.
/// Takes the soup by value and frees it before the Mesh builds its adjacency (peak memory).
Mesh soup_to_mesh(const std::string& path, const std::string& format, std::vector<Point> points,
                  std::vector<Polygon> polygons, const NonFinite& nonfinite,
                  MeshReadReport* report) {
  const std::size_t n = points.size();
  if (n == 0) fail(path, "empty mesh: no vertices");
  if (polygons.empty()) fail(path, "empty mesh: no faces");
  if (n > kMaxCount) fail(path, "too many vertices");

  // Vertices to skip: non-finite tokens seen by the text pre-reads (already replaced by 0 for
  // CGAL) and non-finite values CGAL decoded from binary PLY.
  std::vector<unsigned char> skip(n, 0);
  for (const unsigned long long v : nonfinite.vertices) skip[v] = 1;
  std::vector<int> skipped;
  for (std::size_t v = 0; v < n; ++v) {
    const Point& q = points[v];
    if (!skip[v] && std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z())) continue;
    if (!nonfinite.skip_invalid) {
      std::ostringstream msg;
      msg << "vertex " << v << " has a non-finite coordinate (" << q.x() << ", " << q.y() << ", "
          << q.z() << ")" << kSkipHint;
      fail(path, msg.str());
    }
    skip[v] = 1;
    skipped.push_back(static_cast<int>(v));
  }
  // New index of each kept vertex (file order).
  std::vector<int> index(n, -1);
  std::vector<int> source;
  int kept_vertices = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (!skip[v]) index[v] = kept_vertices++;
  if (kept_vertices == 0)
    fail(path, "empty mesh: all " + std::to_string(n) + " vertices have a non-finite coordinate");
  if (!skipped.empty()) {
    source.reserve(static_cast<std::size_t>(kept_vertices));
    for (std::size_t v = 0; v < n; ++v)
      if (!skip[v]) source.push_back(static_cast<int>(v));
  }

  // Classify the polygons.
  enum Fate : unsigned char { kKeep, kFew, kSkipped, kRepeated };
  std::vector<unsigned char> fate(polygons.size(), kKeep);
  std::vector<std::size_t> scratch;
  unsigned long long triangles = 0;
  int kept = 0, triangulated = 0, few = 0, repeated = 0, faces_skipped = 0;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const Polygon& p = polygons[f];
    for (const std::size_t i : p)
      if (i >= n)
        fail(path, "face " + std::to_string(f) + " references vertex " + std::to_string(i) +
                       ", out of range [0, " + std::to_string(n) + ")");
    if (p.size() < 3) {
      fate[f] = kFew, ++few;
    } else if (std::any_of(p.begin(), p.end(), [&](std::size_t i) { return skip[i] != 0; })) {
      fate[f] = kSkipped, ++faces_skipped;
    } else if (has_repeated_index(p, scratch)) {
      fate[f] = kRepeated, ++repeated;
    } else {
      ++kept;
      triangles += p.size() - 2;
      if (p.size() > 3) ++triangulated;
    }
  }
  if (triangles > kMaxCount) fail(path, "too many triangles after fan triangulation");
  if (kept == 0) {
    std::string why;
    for (const auto& [k, what] : {std::pair{few, "with fewer than 3 vertices"},
                                  std::pair{repeated, "with a repeated vertex index"},
                                  std::pair{faces_skipped, "using a NaN/Inf vertex"}})
      if (k > 0) why += (why.empty() ? "" : ", ") + std::to_string(k) + " " + what;
    fail(path, "empty mesh: no faces left after dropping all " + std::to_string(polygons.size()) +
                   " (" + why + ")");
  }

  VertexMatrix V(kept_vertices, 3);
  for (std::size_t v = 0; v < n; ++v) {
    if (skip[v]) continue;
    const Eigen::Index r = index[v];
    V(r, 0) = points[v].x();
    V(r, 1) = points[v].y();
    V(r, 2) = points[v].z();
  }
  // Fan triangulation (v0, vi, vi+1) of each kept polygon.
  FaceMatrix F(static_cast<Eigen::Index>(triangles), 3);
  Eigen::Index t = 0;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (fate[f] != kKeep) continue;
    const Polygon& p = polygons[f];
    for (std::size_t i = 1; i + 1 < p.size(); ++i, ++t) {
      F(t, 0) = index[p[0]];
      F(t, 1) = index[p[i]];
      F(t, 2) = index[p[i + 1]];
    }
  }

  std::vector<Point>().swap(points);
  std::vector<Polygon>().swap(polygons);
#ifdef __GLIBC__
  // The soup was millions of small polygon vectors: hand their heap back to the system now
  // rather than carry it through the estimation (peak memory, issue 6).
  malloc_trim(0);
#endif
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

/// A file written under a temporary name in the target's directory and renamed into place by
/// commit(); destroyed uncommitted, it removes the temporary file.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path) : path_(path) {
    static std::atomic<unsigned> counter{0};
    const fs::path target(path);
    if (target.filename().empty()) fail(path, "cannot write: not a file name");
    std::error_code ec;
    if (fs::is_directory(target, ec)) fail(path, "cannot write: is a directory");
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    tmp_ = (dir / ("." + target.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                   std::to_string(counter++)))
               .string();
    fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0) {
      const int err = errno;
      if (err == ENOENT || err == ENOTDIR)
        fail(path, "cannot write: directory '" + dir.string() + "' does not exist");
      if (err == EACCES || err == EPERM || err == EROFS)
        fail(path, "cannot write: directory '" + dir.string() + "' is not writable (" +
                       std::strerror(err) + ")");
      fail(path, std::string("cannot write (") + std::strerror(err) + ")");
    }
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  ~AtomicFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(tmp_.c_str());
  }

  /// Appends to the buffer; flushes it to the file beyond 1 MiB.
  std::string& buffer() {
    if (buffer_.size() > (1u << 20)) flush();
    return buffer_;
  }

  void commit() {
    flush();
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail_errno("cannot write");
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail_errno("cannot rename into place");
    committed_ = true;
  }

 private:
  [[noreturn]] void fail_errno(const char* what) {
    fail(path_, std::string(what) + " (" + std::strerror(errno) + ")");
  }

  void flush() {
    const char* p = buffer_.data();
    std::size_t left = buffer_.size();
    while (left > 0) {
      const ssize_t w = ::write(fd_, p, left);
      if (w < 0) {
        if (errno == EINTR) continue;
        fail_errno("cannot write");
      }
      p += w;
      left -= static_cast<std::size_t>(w);
    }
    buffer_.clear();
  }

  std::string path_;
  std::string tmp_;
  std::string buffer_;
  int fd_ = -1;
  bool committed_ = false;
};

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

void check_properties(const Mesh& mesh, const std::vector<VertexProperty>& properties) {
  std::vector<std::string> names = {"x", "y", "z"};
  for (const VertexProperty& p : properties) {
    if (p.name.empty() ||
        std::any_of(p.name.begin(), p.name.end(), [](char c) { return c <= ' ' || c >= 0x7f; }))
      throw UsageError("vertex property name '" + p.name + "' is empty or not a printable word");
    if (std::find(names.begin(), names.end(), p.name) != names.end())
      throw UsageError("vertex property '" + p.name + "' given twice (or clashes with x/y/z)");
    names.push_back(p.name);
    if (p.values.size() != static_cast<std::size_t>(mesh.num_vertices()))
      throw UsageError("vertex property '" + p.name + "' has " + std::to_string(p.values.size()) +
                       " values for " + std::to_string(mesh.num_vertices()) + " vertices");
    if (p.integer)
      for (std::size_t v = 0; v < p.values.size(); ++v) {
        const double x = p.values[v];
        if (!(x >= std::numeric_limits<std::int32_t>::min() &&
              x <= std::numeric_limits<std::int32_t>::max() && std::trunc(x) == x))
          throw UsageError("integer vertex property '" + p.name + "' has value " +
                           std::to_string(x) + " at vertex " + std::to_string(v) +
                           ", not a 32-bit integer");
      }
  }
}

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
  std::string data;
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

  std::string text = read_file(path);
  SoupCounts counts;
  NonFinite nonfinite;
  nonfinite.skip_invalid = options.skip_invalid;
  if (format == "off") {
    std::vector<TextSpan> colors;
    counts = check_off(path, text, nonfinite, colors);
    for (const auto& [offset, length] : colors)
      std::fill_n(text.begin() + static_cast<std::ptrdiff_t>(offset), length, ' ');
  } else if (format == "obj") {
    counts = check_obj(path, text, nonfinite);
    // CGAL's OBJ face reader separates indices by ' ' only.
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c == '\t' || c == '\v' || c == '\f'; }, ' ');
  } else {
    counts = check_ply(path, text, nonfinite);
  }
  check_not_empty(path, counts);
  // Skipped non-finite coordinates become a "0" CGAL can read; the vertices are dropped later.
  for (const auto& [offset, length] : nonfinite.spans) {
    text[offset] = '0';
    std::fill_n(text.begin() + static_cast<std::ptrdiff_t>(offset) + 1, length - 1, ' ');
  }

  std::vector<Point> points;
  std::vector<Polygon> polygons;
  points.reserve(counts.vertices);  // exact sizes from the pre-read: no growth by doubling
  polygons.reserve(counts.faces);
  bool ok;
  {
    std::istringstream in(std::move(text), std::ios::in | std::ios::binary);
    const auto np = CGAL::parameters::verbose(false);
    if (format == "off")
      ok = CGAL::IO::read_OFF(in, points, polygons, np);
    else if (format == "obj")
      ok = CGAL::IO::read_OBJ(in, points, polygons, np);
    else
      ok = CGAL::IO::read_PLY(in, points, polygons, np);
  }  // the file's text is freed here, before the mesh is built
  if (!ok) fail(path, "malformed " + format + " file (rejected by CGAL's reader)");
  if (points.size() != counts.vertices || polygons.size() != counts.faces)
    fail(path, "malformed " + format + " file: CGAL's reader found " +
                   std::to_string(points.size()) + " vertices and " +
                   std::to_string(polygons.size()) + " faces, the pre-read " +
                   std::to_string(counts.vertices) + " and " + std::to_string(counts.faces));
  return soup_to_mesh(path, format, std::move(points), std::move(polygons), nonfinite, report);
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

void write_ply(const std::string& path, const Mesh& mesh,
               const std::vector<VertexProperty>& properties,
               const std::vector<std::string>& comments) {
  check_properties(mesh, properties);
  check_comments(comments);
  AtomicFile file(path);
  std::string& header = file.buffer();
  header += "ply\nformat binary_little_endian 1.0\ncomment written by curvbench\n";
  for (const std::string& c : comments) header += "comment " + c + "\n";
  header += "element vertex " + std::to_string(mesh.num_vertices()) + "\n";
  header += "property double x\nproperty double y\nproperty double z\n";
  for (const VertexProperty& p : properties)
    header += std::string("property ") + (p.integer ? "int " : "double ") + p.name + "\n";
  header += "element face " + std::to_string(mesh.num_faces()) + "\n";
  header += "property list uchar int vertex_indices\nend_header\n";
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    std::string& out = file.buffer();
    for (int c = 0; c < 3; ++c) append_le(out, mesh.vertices()(v, c));
    for (const VertexProperty& p : properties) {
      if (p.integer)
        append_le(out, static_cast<std::int32_t>(p.values[v]));
      else
        append_le(out, p.values[v]);
    }
  }
  for (int f = 0; f < mesh.num_faces(); ++f) {
    std::string& out = file.buffer();
    append_le(out, static_cast<std::uint8_t>(3));
    for (int k = 0; k < 3; ++k) append_le(out, static_cast<std::int32_t>(mesh.face_vertex(f, k)));
  }
  file.commit();
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
