// OFF reader (Geomview Object File Format, ASCII): one validating pass over the text that builds
// the polygon soup as it goes.
//
// Accepted: the keyword [C][N][4]OFF (colors, normals, homogeneous coordinates; counts on the
// keyword line or the next line), '#' comments anywhere, blank lines, CRLF. Vertex colors
// (1, 3 or 4 components after the coordinates and normals) and face colors (1, 3 or 4 values after
// the indices, in any variant, as Geomview writes them) are checked and ignored; NOFF's normals
// are checked and kept (the soup's normals: their first three numbers); homogeneous points are
// divided by w (w = 0 refused). Refused, with the line number: ST/nOFF/SKEL/binary OFF, counts the
// file cannot hold, a truncated body, data after the declared elements, a non-numeric token, a
// non-integer face size or index, a negative or out-of-range index, a non-finite coordinate
// (recorded instead with skip_invalid).
//
// The soup equals what CGAL 5.5's read_OFF gives on the same accepted file (tests/mesh/
// test_io_oracle.cpp), but CGAL also accepts much malformed input silently: it stops a vertex line
// at the first non-number ("0 0 0x"), truncates face sizes and indices given as decimals, ignores
// extra indices, misreads binary OFF, reads colors without range checks (undefined behaviour on
// a color-map index 1e300), and sizes its arrays by the header counts before reading.
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/read_soup.h"

namespace curvbench::io_detail {

namespace {

struct OffLayout {
  bool colors = false;
  bool normals = false;
  bool homogeneous = false;
};

OffLayout parse_off_keyword(const std::string& path, std::size_t line, std::string_view keyword) {
  // [ST][C][N][4][n]OFF, in this order, as CGAL's File_header_OFF scans it.
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

}  // namespace

Soup read_off(const std::string& path, std::string_view text, bool skip_invalid) {
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
  unsigned long long num_vertices, num_faces;
  long long edges;
  if (!parse_count(counts[0], &num_vertices))
    fail_line(
        path, lines.number(),
        "bad OFF header: vertex count " + quote(counts[0]) + " is not a non-negative integer");
  if (!parse_count(counts[1], &num_faces))
    fail_line(path, lines.number(),
              "bad OFF header: face count " + quote(counts[1]) + " is not a non-negative integer");
  if (!parse_integer(counts[2], &edges) || edges < std::numeric_limits<int>::min() ||
      edges > std::numeric_limits<int>::max())
    fail_line(path, lines.number(),
              "bad OFF header: edge count " + quote(counts[2]) + " is not an integer");

  // Refuse counts the file cannot hold before anything is sized by them: a vertex line takes at
  // least 6 bytes ("0 0 0\n"), a face line at least 2 (the empty face "0\n", dropped later); the
  // last newline may miss. The reservations below are then at most a few times the file's size.
  const unsigned long long body = text.size() - lines.offset() + 1;
  if (num_vertices > body || num_faces > body || 6 * num_vertices + 2 * num_faces > body)
    fail(path, "OFF header declares " + std::to_string(num_vertices) + " vertices and " +
                   std::to_string(num_faces) + " faces, more than a " +
                   std::to_string(text.size()) +
                   "-byte file can hold (truncated file or corrupt header)");
  if (num_vertices > kMaxCount || num_faces > kMaxCount)
    fail(path, "OFF header declares more than " + std::to_string(kMaxCount) + " elements");

  Soup soup;
  soup.skip_invalid = skip_invalid;
  soup.xyz.reserve(3 * num_vertices);
  soup.indices.reserve(3 * num_faces);

  // A short last line without its newline is a cut file, not a malformed record.
  auto short_line = [&](std::size_t line, const std::string& what, const std::string& problem) {
    if (lines.offset() >= text.size() && !text.ends_with('\n'))
      fail(path, "truncated OFF body: the file ends inside " + what + " (line " +
                     std::to_string(line) + ")");
    fail_line(path, line, what + problem);
  };

  const std::size_t coords = layout.homogeneous ? 4 : 3;
  const std::size_t normals = layout.normals ? coords : 0;
  for (unsigned long long v = 0; v < num_vertices; ++v) {
    if (!lines.next_tokens(tok, true))
      fail(path, "truncated OFF body: the file ends after " + std::to_string(v) + " of " +
                     std::to_string(num_vertices) + " vertices");
    const std::size_t line = lines.number();
    const auto what = [v] { return "vertex " + std::to_string(v); };
    double x[4] = {0, 0, 0, 1}, normal[3] = {0, 0, 0};
    for (std::size_t i = 0; i < tok.size(); ++i) {
      double value;
      const Number r = parse_double(tok[i], &value);
      if (r == Number::kBad) fail_line(path, line, what() + ": non-numeric token " + quote(tok[i]));
      if (r == Number::kOverflow || !std::isfinite(value)) {
        if (i < 3 && soup.skip(v)) continue;  // x[i] stays 0; the vertex is dropped
        fail_line(path, line,
                  what() + (i < 3 ? " has a non-finite coordinate " : " has a non-finite value ") +
                      quote(tok[i]) + (i < 3 ? kSkipHint : ""));
      }
      if (i < coords) x[i] = value;
      if (normals > 0 && i >= coords && i < coords + 3) normal[i - coords] = value;
      if (layout.homogeneous && i == 3 && value == 0.0)
        fail_line(path, line, what() + " has homogeneous weight w = 0");
    }
    if (tok.size() < coords + normals)
      short_line(line, what(),
                 " has " + std::to_string(tok.size()) + " numbers, expected at least " +
                     std::to_string(coords + normals));
    const std::size_t color = tok.size() - coords - normals;
    if (layout.colors && color != 0 && color != 1 && color != 3 && color != 4)
      fail_line(path, line,
                what() + " has a color with " + std::to_string(color) +
                    " components (expected 1, 3 or 4)");
    // Geomview's homogeneous point (x, y, z, w) is (x/w, y/w, z/w).
    for (int c = 0; c < 3; ++c) soup.xyz.push_back(x[c] / x[3]);
    if (normals > 0) soup.normals.append(normal, 3);
  }

  for (unsigned long long f = 0; f < num_faces; ++f) {
    if (!lines.next_tokens(tok, true))
      fail(path, "truncated OFF body: the file ends after " + std::to_string(f) + " of " +
                     std::to_string(num_faces) + " faces");
    const std::size_t line = lines.number();
    const auto what = [f] { return "face " + std::to_string(f); };
    long long size;
    if (!parse_integer(tok[0], &size) || size < 0)
      fail_line(path, line,
                what() + ": vertex count " + quote(tok[0]) + " is not a non-negative integer" +
                    (f == 0 ? " (the header declares " + std::to_string(num_vertices) +
                                  " vertices: wrong counts?)"
                            : ""));
    if (tok.size() - 1 < static_cast<unsigned long long>(size))
      short_line(line, what(),
                 " declares " + std::to_string(size) + " vertices but lists " +
                     std::to_string(tok.size() - 1) + " indices");
    for (std::size_t j = 1; j <= static_cast<std::size_t>(size); ++j) {
      long long index;
      if (!parse_integer(tok[j], &index))
        fail_line(path, line, what() + ": vertex index " + quote(tok[j]) + " is not an integer");
      check_face_index(path, line, f, index, num_vertices);
      soup.indices.push_back(static_cast<std::int32_t>(index));
    }
    // A face may carry a color in any OFF variant (Geomview); anything else is misplaced data.
    const std::size_t color = tok.size() - 1 - static_cast<std::size_t>(size);
    if (color != 0 && color != 1 && color != 3 && color != 4)
      fail_line(path, line,
                what() + " has " + std::to_string(color) +
                    " values after its indices (a color has 1, 3 or 4; wrong counts in the "
                    "header?)");
    soup.end_polygon();
  }
  if (lines.next_tokens(tok, true))
    fail_line(path, lines.number(),
              "data after the last of the " + std::to_string(num_vertices) + " vertices and " +
                  std::to_string(num_faces) + " faces the header declares (wrong counts?)");
  check_not_empty(path, num_vertices, num_faces);
  return soup;
}

}  // namespace curvbench::io_detail
