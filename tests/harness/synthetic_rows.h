// Synthetic error rows for the report tests: one method's H L2 series over levels 1-3 of a
// family, h = 0.4, 0.2, 0.1 and errors e0 (h / 0.4)^rate, so that every rate is known exactly;
// and single rows of a sweep (one level, one error per method, noise and quantity).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "harness/model/results_table.h"

namespace curvbench::testing {

inline std::vector<ErrorRow> synthetic_series(const std::string& experiment,
                                              const std::string& family, const std::string& method,
                                              double e0, double rate) {
  ErrorRow like;  // the columns the levels share
  like.experiment = experiment;
  like.surface = "bump";
  like.family = family;
  like.method = method;
  like.noise = "none";
  like.vertex_set = "all";
  like.quantity = "H";
  like.norm = "L2";
  std::vector<ErrorRow> rows;
  for (int level = 1; level <= 3; ++level) {
    ErrorRow r = like;
    r.level = level;
    r.vertices = 100 << (2 * level);
    r.h = 0.4 / (1 << (level - 1));
    r.error = e0 * std::pow(r.h / 0.4, rate);
    r.counted = r.vertices;
    r.seconds = 1e-6 * 5.0 * r.vertices;  // 5 us per vertex
    rows.push_back(r);
  }
  return rows;
}

/// One L2 error row of the experiment "sweep-test" on the torus at level 2 (5000 vertices,
/// h = 0.05), its typed columns filled as reading the CSV does.
inline ErrorRow sweep_row(const std::string& family, const std::string& method,
                          const std::string& noise, double error,
                          const std::string& quantity = "H") {
  ErrorRow r;
  r.experiment = "sweep-test";
  r.surface = "torus";
  r.family = family;
  r.level = 2;
  r.vertices = 5000;
  r.h = 0.05;
  r.method = method;
  r.noise = noise;
  r.vertex_set = "all";
  r.quantity = quantity;
  r.norm = "L2";
  r.error = error;
  type_columns(r);
  return r;
}

}  // namespace curvbench::testing
