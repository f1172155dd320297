// Point-set text files: .xyz, .pts and .pwn (CGAL's points_3 data), one point per line:
// "x y z" or "x y z nx ny nz" (the normals kept as the soup's normals). Blank lines and '#'
// comments are skipped; a .pts file may start with a line holding the point count alone. Every
// point line must have the column count of the first: a line with another count (a 2-D line in a
// 3-D file) is refused with its line number. The soup has no polygons: the Mesh is a point set.
#include <cmath>
#include <string>

#include "mesh/read_soup.h"

namespace curvbench::io_detail {

Soup read_xyz(const std::string& path, std::string_view text, bool skip_invalid) {
  Soup soup;
  soup.skip_invalid = skip_invalid;
  Lines lines(text);
  std::vector<std::string_view> tok;
  std::size_t columns = 0;
  std::size_t first_line = 0;
  unsigned long long v = 0;
  while (lines.next_tokens(tok, true)) {
    const std::size_t line = lines.number();
    unsigned long long count = 0;
    if (columns == 0 && v == 0 && tok.size() == 1 && parse_count(tok[0], &count))
      continue;  // a leading point count (.pts)
    if (columns == 0) {
      if (tok.size() != 3 && tok.size() != 6)
        fail_line(path, line,
                  "a point has " + std::to_string(tok.size()) +
                      " numbers (expected x y z or x y z nx ny nz)");
      columns = tok.size();
      first_line = line;
    } else if (tok.size() != columns) {
      fail_line(path, line,
                "point " + std::to_string(v) + " has " + std::to_string(tok.size()) +
                    " numbers where line " + std::to_string(first_line) + " has " +
                    std::to_string(columns) + " (mixed 2-D/3-D or normal columns?)");
    }
    if (v >= kMaxCount) fail(path, "too many points");
    double x[6] = {0, 0, 0, 0, 0, 0};
    for (std::size_t i = 0; i < tok.size(); ++i) {
      double value;
      const Number r = parse_double(tok[i], &value);
      if (r == Number::kBad)
        fail_line(path, line,
                  "point " + std::to_string(v) + ": non-numeric token " + quote(tok[i]));
      if (r == Number::kOverflow || !std::isfinite(value)) {
        if (i < 3 && soup.skip(v)) continue;  // dropped later (soup_to_mesh)
        fail_line(path, line,
                  "point " + std::to_string(v) +
                      (i < 3 ? " has a non-finite coordinate " : " has a non-finite normal ") +
                      quote(tok[i]) + (i < 3 ? kSkipHint : ""));
      }
      x[i] = value;
    }
    soup.xyz.append(x, 3);
    if (columns == 6) soup.normals.append(x + 3, 3);
    ++v;
  }
  if (v == 0) fail(path, "empty point set: no points");
  return soup;
}

}  // namespace curvbench::io_detail
