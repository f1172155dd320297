// OBJ reader (Wavefront, geometry only): one validating pass over the text that builds the
// polygon soup as it goes.
//
// Read: "v x y z" (further values, such as a w or vertex colors, ignored) and "f" with indices
// v, v/vt, v//vn or v/vt/vn (1-based; negative indices count back from the last vertex read so
// far). Skipped: every other statement CGAL's read_OBJ skips (vt, vn, g, o, usemtl, ...).
// Refused, with the line number: any other statement, a vertex with fewer than 3 coordinates or a
// non-numeric one, a non-integer index, index 0, a relative index before the first vertex, an
// index beyond the last vertex, a non-finite coordinate (recorded instead with skip_invalid).
//
// The soup equals what CGAL 5.5's read_OBJ gives on the same accepted file (tests/mesh/
// test_io_oracle.cpp, with tabs turned into spaces for CGAL), but CGAL also accepts malformed
// faces silently: it ends a face at the first non-integer token ("f 1 2 x" gives a 2-gon, a lone
// "f" an empty polygon), loses tab-separated indices ("f 1\t2\t3" gives the 1-gon [0]), treats
// index 0 as a relative reference and accepts an index one past the last vertex.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/read_soup.h"

namespace curvbench::io_detail {

namespace {

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

}  // namespace

Soup read_obj(const std::string& path, std::string_view text, bool skip_invalid) {
  Soup soup;
  soup.skip_invalid = skip_invalid;
  // The file has no counts: the vectors grow (OBJ text takes at least 6 bytes per vertex line and
  // 2 per index, so they stay proportional to the file's size).
  Lines lines(text);
  std::vector<std::string_view> tok;
  unsigned long long num_vertices = 0, num_faces = 0;
  long long max_index = -1;  // largest positive (absolute) index, 0-based, and where it was
  std::size_t max_line = 0;
  unsigned long long max_face = 0;
  while (lines.next_tokens(tok, true)) {
    const std::size_t line = lines.number();
    if (tok[0] == "v") {
      const auto what = [&] { return "vertex " + std::to_string(num_vertices); };
      if (tok.size() < 4)
        fail_line(path, line,
                  what() + " has " + std::to_string(tok.size() - 1) + " coordinates, expected 3");
      for (std::size_t i = 1; i <= 3; ++i) {
        double x;
        const Number r = parse_double(tok[i], &x);
        if (r == Number::kBad)
          fail_line(path, line, what() + ": non-numeric token " + quote(tok[i]));
        if (r == Number::kOverflow || !std::isfinite(x)) {
          if (!soup.skip(num_vertices))
            fail_line(path, line,
                      what() + " has a non-finite coordinate " + quote(tok[i]) + kSkipHint);
          x = 0;  // the vertex is dropped
        }
        soup.xyz.push_back(x);
      }
      ++num_vertices;
    } else if (tok[0] == "f") {
      const auto what = [&] { return "face " + std::to_string(num_faces); };
      for (std::size_t j = 1; j < tok.size(); ++j) {
        // v, v/vt, v//vn or v/vt/vn: the vertex index is before the first '/'.
        const std::string_view v = tok[j].substr(0, tok[j].find('/'));
        long long index;
        if (!parse_integer(v, &index) || index < std::numeric_limits<int>::min() ||
            index > std::numeric_limits<int>::max())
          fail_line(path, line, what() + ": vertex index " + quote(tok[j]) + " is not an integer");
        if (index == 0)
          fail_line(path, line, what() + ": vertex index 0 is invalid (OBJ indices start at 1)");
        if (index < 0 && static_cast<unsigned long long>(-index) > num_vertices)
          fail_line(path, line,
                    what() + ": relative vertex index " + std::to_string(index) +
                        " refers before the first vertex");
        if (index > 0 && index - 1 > max_index) {
          max_index = index - 1;
          max_line = line;
          max_face = num_faces;
        }
        // Relative indices count back from the vertices read so far.
        const long long absolute =
            index > 0 ? index - 1 : static_cast<long long>(num_vertices) + index;
        soup.indices.push_back(static_cast<std::int32_t>(absolute));
      }
      soup.end_polygon();
      ++num_faces;
    } else if (!obj_ignored_statement(tok[0])) {
      fail_line(path, line, "unsupported OBJ statement " + quote(tok[0]));
    }
  }
  if (num_vertices > kMaxCount || num_faces > kMaxCount)
    fail(path, "OBJ file has more than " + std::to_string(kMaxCount) + " vertices or faces");
  // Forward references are allowed: the largest index is checked once all vertices are known.
  if (max_index >= 0 && static_cast<unsigned long long>(max_index) >= num_vertices)
    fail_line(path, max_line,
              "face " + std::to_string(max_face) + " references vertex " +
                  std::to_string(max_index + 1) + " (1-based), but the file has " +
                  std::to_string(num_vertices) + " vertices");
  check_not_empty(path, num_vertices, num_faces);
  // Point sets come as .xyz/.pts/.pwn, OFF or PLY: an OBJ without faces stays refused, as CGAL's
  // reader (the tests' oracle) refuses it.
  if (num_faces == 0) fail(path, "empty mesh: no faces");
  return soup;
}

}  // namespace curvbench::io_detail
