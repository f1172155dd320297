// CGAL 5.5's polygon-soup readers as a differential oracle for curvbench's own readers
// (mesh/read_off.cpp, read_obj.cpp, read_ply.cpp). Used by tests/mesh/test_io_oracle.cpp (the
// whole corpus) and fuzz/fuzz_read_mesh.cpp (every input our reader accepts).
//
// The contract checked: on every file our reader accepts, CGAL's reader accepts it too and gives
// the same soup (bit-identical coordinates, the same polygons). Files our reader refuses are not
// given to CGAL: CGAL accepts much malformed input silently, sizes its arrays by header counts
// (gigabytes for a corrupt count) and has undefined behaviour on some of it (the notes at the top
// of each reader list what). Allowed differences, applied to CGAL's input by cgal_input():
//   - OBJ: '#' starts a comment anywhere on a line ("f#c 1 2 3" is a face for us, an unknown
//     statement for CGAL); tabs, '\v', '\f' and a '\r' inside a line separate tokens (CGAL's face
//     reader skips from an index to the next ' ' only). Both are turned into what CGAL reads the
//     same way: comments cut, those blanks made spaces.
//   - OFF: colors are checked and ignored by us; CGAL converts them without range checks
//     (undefined behaviour on a color-map index 1e300), so they are removed before CGAL reads.
//     Every other token is passed on verbatim.
#pragma once

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Simple_cartesian.h>
#include <bit>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.h"
#include "mesh/read_soup.h"

namespace curvbench::oracle {

using Point = CGAL::Simple_cartesian<double>::Point_3;
using Polygon = std::vector<std::size_t>;

struct CgalSoup {
  bool ok = false;
  std::vector<Point> points;
  std::vector<Polygon> polygons;
};

/// The bytes of a file our reader accepted, as CGAL must see them (see the list above).
inline std::string cgal_input(const std::string& format, const std::string& text) {
  if (format == "obj") {
    std::string out;
    out.reserve(text.size());
    bool comment = false;
    for (const char c : text) {
      if (c == '\n') comment = false;
      if (c == '#') comment = true;
      if (comment) continue;
      out += (c == '\t' || c == '\v' || c == '\f' || c == '\r') ? ' ' : c;
    }
    return out;
  }
  if (format != "off") return text;
  // OFF: the keyword, the counts, then each vertex line's coordinates (and normals) and each face
  // line's size and indices, tokens verbatim; comments, blank lines and colors dropped.
  io_detail::Lines lines(text);
  std::vector<std::string_view> tok;
  std::string out;
  lines.next_tokens(tok, true);
  const std::string_view keyword = tok[0];
  std::vector<std::string_view> counts(tok.begin() + 1, tok.end());
  if (counts.empty()) {
    lines.next_tokens(tok, true);
    counts = tok;
  }
  out += std::string(keyword) + "\n" + std::string(counts[0]) + " " + std::string(counts[1]) + " " +
         std::string(counts[2]) + "\n";
  const std::size_t coords = keyword.find('4') != std::string_view::npos ? 4 : 3;
  const std::size_t per_vertex = coords * (keyword.find('N') != std::string_view::npos ? 2 : 1);
  const unsigned long long nv = std::stoull(std::string(counts[0]));
  const unsigned long long nf = std::stoull(std::string(counts[1]));
  auto emit = [&](std::size_t k) {
    for (std::size_t i = 0; i < k; ++i) out += std::string(tok[i]) + (i + 1 < k ? " " : "\n");
    if (k == 0) out += "\n";
  };
  for (unsigned long long v = 0; v < nv && lines.next_tokens(tok, true); ++v) emit(per_vertex);
  for (unsigned long long f = 0; f < nf && lines.next_tokens(tok, true); ++f)
    emit(1 + std::stoull(std::string(tok[0])));
  return out;
}

/// CGAL's reader for `format` on `text` (already through cgal_input).
inline CgalSoup read_with_cgal(const std::string& format, const std::string& text) {
  CgalSoup soup;
  std::istringstream in(text, std::ios::in | std::ios::binary);
  const auto np = CGAL::parameters::verbose(false);
  if (format == "off")
    soup.ok = CGAL::IO::read_OFF(in, soup.points, soup.polygons, np);
  else if (format == "obj")
    soup.ok = CGAL::IO::read_OBJ(in, soup.points, soup.polygons, np);
  else
    soup.ok = CGAL::IO::read_PLY(in, soup.points, soup.polygons, np);
  return soup;
}

/// Empty if the soups are the same (coordinates compared bit for bit, any NaN equal to any NaN),
/// else the first difference.
inline std::string compare(const io_detail::Soup& ours, const CgalSoup& cgal) {
  if (!cgal.ok) return "CGAL's reader refuses the file";
  if (cgal.points.size() != ours.num_vertices())
    return "vertices: ours " + std::to_string(ours.num_vertices()) + ", CGAL " +
           std::to_string(cgal.points.size());
  if (cgal.polygons.size() != ours.num_polygons())
    return "polygons: ours " + std::to_string(ours.num_polygons()) + ", CGAL " +
           std::to_string(cgal.polygons.size());
  const auto same = [](double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) || (a != a && b != b);
  };
  for (std::size_t v = 0; v < cgal.points.size(); ++v)
    for (int c = 0; c < 3; ++c)
      if (!same(ours.xyz[3 * v + c], cgal.points[v][c]))
        return "vertex " + std::to_string(v) + " coordinate " + std::to_string(c);
  for (std::size_t f = 0; f < cgal.polygons.size(); ++f) {
    const Polygon& p = cgal.polygons[f];
    const std::size_t begin = ours.polygon_begin(f), size = ours.polygon_size(f);
    bool equal = p.size() == size;
    for (std::size_t i = 0; equal && i < size; ++i)
      equal = p[i] == static_cast<std::size_t>(ours.indices[begin + i]);
    if (!equal) return "polygon " + std::to_string(f);
  }
  return "";
}

/// Reads `text` with our reader for `format` (the same call read_mesh makes) and, if it accepts,
/// with CGAL's: the empty string if our reader refuses the file or the soups agree, else the
/// difference. Throws nothing our reader does not (InputError is caught here).
inline std::string differential(const std::string& format, const std::string& text,
                                bool* accepted = nullptr) {
  io_detail::Soup ours;
  try {
    if (format == "off")
      ours = io_detail::read_off("oracle", text, false);
    else if (format == "obj")
      ours = io_detail::read_obj("oracle", text, false);
    else
      ours = io_detail::read_ply("oracle", text, false);
  } catch (const InputError&) {
    if (accepted != nullptr) *accepted = false;
    return "";
  }
  if (accepted != nullptr) *accepted = true;
  return compare(ours, read_with_cgal(format, cgal_input(format, text)));
}

}  // namespace curvbench::oracle
