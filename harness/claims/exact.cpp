// Claims A1-A5: the paper's tables (Table 2, §3.2; Table 4, §5.3) and the identity LOP = LHF
// (§3.3), one registry entry each (harness/claims/kit.h; docs/claims.md).
#include <cmath>
#include <map>
#include <tuple>

#include "harness/claims/kit.h"
#include "harness/model/paper_tables.h"

namespace curvbench::claims {
namespace {

// Row of table4.csv for grid n, or -1 after recording it missing.
int table4_row(const Data& d, Check& c, int n) {
  const CsvTable& t = *d.table4();
  const size_t cg = t.col("grid_points");
  for (size_t i = 0; i < t.rows.size(); ++i)
    if (t.number(i, cg) == n) return static_cast<int>(i);
  c.missing("table4.csv has no row for n = " + std::to_string(n) + " (run with --table4-max 256)");
  return -1;
}

bool have_table4(const Data& d, Check& c) {
  if (!d.table4()) c.missing("table4.csv not present: run make experiments");
  return d.table4().has_value();
}

void claim_a1(const Data& d, Check& c) {
  if (!d.table2()) {
    c.missing("table2.csv not present: run make experiments");
    return;
  }
  const CsvTable& t = *d.table2();
  const size_t cd = t.col("degree"), cc = t.col("coefficients"), cp = t.col("points_with_centre"),
               cr = t.col("ring");
  for (const auto& paper : paper::kTable2) {
    const int deg = paper.degree;
    int row = -1;
    for (size_t i = 0; i < t.rows.size(); ++i)
      if (t.number(i, cd) == deg) row = static_cast<int>(i);
    if (row < 0) {
      c.missing("table2.csv has no row for d = " + std::to_string(deg));
      continue;
    }
    const double p = t.number(row, cp), k = t.number(row, cc);
    c.require(p == paper.points_with_centre && k == paper.coefficients,
              "d = " + std::to_string(deg) + ", " + t.text(row, cr) + "-ring: " + g3(p) +
                  " points with centre (paper " + std::to_string(paper.points_with_centre) + "), " +
                  g3(k) + " coefficients (paper " + std::to_string(paper.coefficients) + ")");
  }
}

void claim_a2(const Data& d, Check& c) {
  if (!have_table4(d, c)) return;
  const size_t cv = d.table4()->col("vertices");
  for (const auto& paper : paper::kTable4) {
    const int row = table4_row(d, c, paper.grid_points);
    if (row < 0) continue;
    const double v = d.table4()->number(row, cv);
    c.require(v == paper.vertices, "n = " + std::to_string(paper.grid_points) + ": " +
                                       std::to_string(static_cast<long long>(v)) +
                                       " vertices (paper " + std::to_string(paper.vertices) + ")");
  }
}

// Unit of the last printed digit of a paper value printed with `digits` significant digits.
double last_digit_unit(double paper, int digits) {
  return std::pow(10.0, std::floor(std::log10(paper)) - (digits - 1));
}

// Our value rounded to the paper's last printed digit (3 significant digits) is within one unit
// of that digit of the paper's value.
bool within_last_digit(double ours, double paper) {
  const double unit = last_digit_unit(paper, 3);
  const double rounded = std::round(ours / unit) * unit;
  return std::abs(rounded - paper) <= 1.0001 * unit;
}

void claim_a3(const Data& d, Check& c) {
  if (!have_table4(d, c)) return;
  const size_t crms = d.table4()->col("rms_error"), cmax = d.table4()->col("max_error");
  std::vector<std::string> rates2, ratesinf;
  double prev2 = std::nan(""), previnf = std::nan("");
  std::vector<std::string> paper2, paperinf;
  for (size_t i = 0; i < paper::kTable4.size(); ++i) {
    const auto& paper = paper::kTable4[i];
    if (i > 0) {
      paper2.push_back(f2(paper.rate_l2));
      paperinf.push_back(f2(paper.rate_linf));
    }
    const int row = table4_row(d, c, paper.grid_points);
    if (row < 0) {
      prev2 = previnf = std::nan("");
      continue;
    }
    const double r = d.table4()->number(row, crms), m = d.table4()->number(row, cmax);
    c.require(within_last_digit(r, paper.l2) && within_last_digit(m, paper.linf),
              "n = " + std::to_string(paper.grid_points) + ": L2 " + e3(r) + " (paper " +
                  e2(paper.l2) + "), Linf " + e3(m) + " (paper " + e2(paper.linf) + ")");
    if (i > 0 && std::isfinite(prev2)) {
      rates2.push_back(f2(std::log2(prev2 / r)));
      ratesinf.push_back(f2(std::log2(previnf / m)));
    }
    prev2 = r;
    previnf = m;
  }
  c.info("consecutive rates (log2 of the error ratio): L2 " + join(rates2, ", ") + " (paper " +
         join(paper2, ", ") + "); Linf " + join(ratesinf, ", ") + " (paper " +
         join(paperinf, ", ") + ")");
}

// Calls f(n, true mean edge length, paper column) for each of Table 4's rows present.
template <class F>
void for_each_table4_edge(const Data& d, Check& c, F&& f) {
  if (!have_table4(d, c)) return;
  const size_t ch = d.table4()->col("mean_edge_length");
  for (const auto& row4 : paper::kTable4)
    if (const int row = table4_row(d, c, row4.grid_points); row >= 0)
      f(row4.grid_points, d.table4()->number(row, ch), row4.edge_column);
}

void claim_a4(const Data& d, Check& c, double tolerance) {
  for_each_table4_edge(d, c, [&](int n, double h, double paper) {
    const double ratio = h / paper;
    c.require(std::abs(ratio - 2.0) <= tolerance,
              "n = " + std::to_string(n) + ": true mean edge length " + g3(h) + " / paper column " +
                  g3(paper) + " = " + f2(ratio) + " (band 2.00 +- " + f2(tolerance) + ")");
    // Context, not part of the band: the column has 2 significant digits, so its rounding
    // alone moves the ratio by up to 0.5 unit / value (4.5% at 0.011).
    const double unit = last_digit_unit(paper, 2);
    c.info("n = " + std::to_string(n) + ": half the mean edge length " + g3(0.5 * h) +
           " rounds to " + g3(std::round(0.5 * h / unit) * unit) +
           " at the paper's 2 digits (paper " + g3(paper) +
           "; rounding of the column alone allows the ratio 2 +- " + f2(2.0 * 0.5 * unit / paper) +
           ")");
  });
}

// A4 at the paper's printed precision: half the true mean edge length rounds to the column.
void claim_a4_rounded(const Data& d, Check& c) {
  for_each_table4_edge(d, c, [&](int n, double h, double paper) {
    const double unit = last_digit_unit(paper, 2);
    const double rounded = std::round(0.5 * h / unit) * unit;
    c.require(std::abs(rounded - paper) < 0.5 * unit,
              "n = " + std::to_string(n) + ": half the true mean edge length " + g3(0.5 * h) +
                  " rounds to " + g3(rounded) + " at 2 significant digits (paper " + g3(paper) +
                  ")");
  });
}

// Errors below this are roundoff (e.g. principal directions on a perfectly symmetric mesh, ~1e-16)
// and are treated as equal by the A5 comparison.
constexpr double kRoundoffError = 1e-12;

void claim_a5(const Data& d, Check& c, const Band& band) {
  using Key = std::tuple<std::string, std::string, int, std::string, std::string, std::string,
                         std::string, std::string, std::string>;
  std::map<Key, const ErrorRow*> lhf;
  for (const auto& r : d.rows()) {
    const std::string m = upper(r.method);
    if (m.rfind("LHF-", 0) == 0)
      lhf[{r.experiment, r.family, r.level, m.substr(4), r.rings, r.noise, r.vertex_set, r.quantity,
           r.norm}] = &r;
  }
  std::map<std::string, std::pair<double, int>> per_family;  // family -> (max diff, pairs)
  double worst = -1.0;
  std::string worst_where;
  int pairs = 0;
  for (const auto& r : d.rows()) {
    const std::string m = upper(r.method);
    if (m.rfind("LOP-", 0) != 0) continue;
    auto it = lhf.find({r.experiment, r.family, r.level, m.substr(4), r.rings, r.noise,
                        r.vertex_set, r.quantity, r.norm});
    if (it == lhf.end()) continue;
    const double a = r.error, b = it->second->error;
    double diff = 0.0;
    if (std::isnan(a) && std::isnan(b))
      diff = 0.0;
    else if (!std::isfinite(a) || !std::isfinite(b))
      diff = kInf;
    else if (std::max(std::abs(a), std::abs(b)) < kRoundoffError)
      diff = 0.0;  // both errors are roundoff: their ratio carries no information
    else if (a != b)
      diff = std::abs(a - b) / std::max(std::abs(a), std::abs(b));
    ++pairs;
    auto& pf = per_family[r.family];
    pf.first = std::max(pf.first, diff);
    ++pf.second;
    if (diff > worst) {
      worst = diff;
      worst_where = r.experiment + " " + r.family + " level " + std::to_string(r.level) + " " +
                    r.method + " " + r.quantity + " " + r.norm + " (" + e2(a) + " vs " + e2(b) +
                    ")";
    }
  }
  if (pairs == 0) {
    c.missing("no LOP-d / LHF-d row pairs with the same ring in the errors CSVs");
    return;
  }
  c.info(
      "aggregate check on the error norms of the CSVs (the per-vertex identity of normals and "
      "curvatures is checked by the unit tests)");
  for (const auto& [family, pf] : per_family)
    c.require(band.holds(pf.first), family + ": max relative difference " + e2(pf.first) +
                                        " over " + std::to_string(pf.second) + " row pairs (band " +
                                        band.text() + ")");
  c.info("largest difference at " + worst_where);
}

std::string table2_text() {
  std::string points, coeffs;
  for (const auto& r : paper::kTable2) {
    points += (points.empty() ? "" : ", ") + std::to_string(r.points_with_centre);
    coeffs += (coeffs.empty() ? "" : ", ") + std::to_string(r.coefficients);
  }
  return "On a regular valence-6 mesh, the (d+1)/2-rings of an interior vertex hold " + points +
         " points (centre included) for d = 1..6. The numbers of coefficients are " + coeffs + ".";
}

// "a, b, c" of one column of Table 4 printed with %g (vertex counts, edge column) or %.2e.
template <class Get>
std::string table4_column(Get get, bool scientific) {
  std::vector<std::string> v;
  for (const auto& r : paper::kTable4) {
    char buf[32];
    const double x = get(r);
    if (scientific) {
      // the paper prints 3 significant digits: 3.60e-3
      const int ex = static_cast<int>(std::floor(std::log10(x)));
      std::snprintf(buf, sizeof buf, "%.2fe%d", x / std::pow(10.0, ex), ex);
    } else {
      std::snprintf(buf, sizeof buf, "%g", x);
    }
    v.push_back(buf);
  }
  return join(v, ", ");
}

}  // namespace

std::vector<ClaimEntry> exact_claims() {
  const Band a5 = Band::at_most(1e-8);
  const double a4_tolerance = 0.05;
  std::vector<ClaimEntry> out;
  out.push_back({"A1", "Half-ring sizes [Table 2]", table2_text(), "exact", {}, claim_a1, {}});
  out.push_back({"A2",
                 "Isosurface vertex counts [Table 4]",
                 "SDF of the torus (R = 1, r = 0.3) on linspace(-1.5,1.5,n)^3 with n = 16, 32, 64, "
                 "128, 256 gives " +
                     table4_column([](const auto& r) { return double(r.vertices); }, false) +
                     " vertices.",
                 "exact",
                 {},
                 claim_a2,
                 {}});
  out.push_back(
      {"A3",
       "Isosurface position errors [Table 4]",
       "Distance of the marching-cubes vertices to the torus: L2 = " +
           table4_column([](const auto& r) { return r.l2; }, true) +
           " and Linf = " + table4_column([](const auto& r) { return r.linf; }, true) +
           " for n = 16..256. The isosurface is \"second-order accurate\".",
       "each value within +-1 in the last printed digit (our value rounded to the paper's 3 "
       "significant digits)",
       {},
       claim_a3,
       {}});
  out.push_back(
      {"A4",
       "Table 4 \"average edge length\" is half the mean edge length",
       "Table 4's \"average edge length\" (" +
           table4_column([](const auto& r) { return r.edge_column; }, false) +
           ") equals half the true mean edge length of such a mesh. This is a finding about the "
           "paper's bookkeeping, not a claim of the paper.",
       "half the true mean edge length, rounded to the paper's 2 significant digits, equals "
       "the paper column at every n",
       {{"ratio", Band::in(2.0 - a4_tolerance, 2.0 + a4_tolerance, 2)}},
       claim_a4_rounded,
       {},
       nullptr,
       "true mean edge length / paper column = 2.00 +- " + f2(a4_tolerance) + " at every n",
       [=](const Data& d, Check& c) { claim_a4(d, c, a4_tolerance); },
       "the column is printed to 2 significant digits: at 0.011 its rounding alone moves the "
       "ratio by up to +-0.09 (0.0005 / 0.011 relative, times 2), more than the +-0.05 fixed in "
       "advance, so that band asked for more than the printed numbers carry."});
  out.push_back({"A5",
                 "LOP = LHF",
                 "With identical neighbourhoods, weights and safeguard, LOP-d and LHF-d give the "
                 "same normals and curvatures (\"LHF and LOP deliver nearly identical results\").",
                 "max relative difference " + a5.text() +
                     " on every mesh; here an aggregate check over the error norms of every "
                     "LOP-d/LHF-d row pair of the CSVs (the per-vertex check is in the unit tests)",
                 {{"relative_difference", a5}},
                 [=](const Data& d, Check& c) { claim_a5(d, c, a5); },
                 {}});
  return out;
}

}  // namespace curvbench::claims
