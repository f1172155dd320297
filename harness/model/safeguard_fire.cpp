#include "harness/model/safeguard_fire.h"

#include <cstdio>

#include "core/build_info.h"
#include "core/errors.h"
#include "harness/model/results_table.h"

namespace curvbench {

namespace {
constexpr const char* kHeader =
    "family,level,vertices,method,vertex,x,y,z,boundary,rows,column_rank,rank,condition,degree,"
    "ring,points,degree_rjj_only,ring_rjj_only,points_rjj_only";
}

std::string safeguard_fires_csv(const std::vector<SafeguardFire>& rows) {
  std::string text = provenance_comment() + "\n" + kHeader + "\n";
  char buf[512];
  for (const SafeguardFire& f : rows) {
    std::snprintf(buf, sizeof buf,
                  "%s,%d,%d,%s,%d,%.17g,%.17g,%.17g,%d,%d,%d,%d,%.6g,%d,%g,%d,%d,%g,%d\n",
                  f.family.c_str(), f.level, f.vertices, f.method.c_str(), f.vertex, f.x, f.y, f.z,
                  f.boundary ? 1 : 0, f.rows, f.column_rank, f.rank, f.condition, f.degree, f.ring,
                  f.points, f.degree_rjj_only, f.ring_rjj_only, f.points_rjj_only);
    text += buf;
  }
  return text;
}

std::vector<SafeguardFire> read_safeguard_fires_csv(const std::string& path) {
  const CsvTable t = read_csv_table(path);
  std::vector<SafeguardFire> out;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const auto num = [&](const char* c) { return t.number(i, t.col(c)); };
    const auto integer = [&](const char* c) { return static_cast<int>(num(c)); };
    SafeguardFire f;
    f.family = t.text(i, t.col("family"));
    f.method = t.text(i, t.col("method"));
    f.level = integer("level");
    f.vertices = integer("vertices");
    f.vertex = integer("vertex");
    f.x = num("x"), f.y = num("y"), f.z = num("z");
    f.boundary = integer("boundary") != 0;
    f.rows = integer("rows");
    f.column_rank = integer("column_rank");
    f.rank = integer("rank");
    f.condition = num("condition");
    f.degree = integer("degree"), f.degree_rjj_only = integer("degree_rjj_only");
    f.ring = num("ring"), f.ring_rjj_only = num("ring_rjj_only");
    f.points = integer("points"), f.points_rjj_only = integer("points_rjj_only");
    out.push_back(f);
  }
  return out;
}

std::vector<SafeguardFireCase> default_safeguard_fire_cases() {
  return {{"bump-48", {1, 2, 3, 4}, {"lhf-4", "lscm-4", "lhf-4 rings=3.5"}},
          {"bump-irregular", {1, 2, 3, 4}, {"lhf-4", "lscm-4"}}};
}

}  // namespace curvbench
