// Claims D1-D6: the noise-free open surface (the bump; paper §5.2, Figs. 9-14), one registry
// entry each (harness/claims/kit.h; docs/claims.md). Experiments fig09-10 (degree 2), fig11-12
// (degrees 3, 4) and fig13-14 (boundary vertices).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "harness/claims/kit.h"
#include "harness/model/safeguard_fire.h"
#include "meshgen/bump_grid.h"

namespace curvbench::claims {
namespace {

const Series* bump(const Data& d, Check& c, const std::string& family, const std::string& m,
                   const std::string& q, const std::string& norm) {
  return d.find(c, query(degree_of(m) == 2 ? "fig09-10" : "fig11-12", family, m, q, norm));
}

const Series* torus2(const Data& d, Check& c, const std::string& family, const std::string& m,
                     const std::string& q, const std::string& norm) {
  return d.find(c, query("fig03-05", family, m, q, norm, "none", torus_ring(m)));
}

// Offsets of a band relative to the degree d: "[d - 0.5, d + 0.7]".
std::string degree_band_text(const Band& offset) {
  auto term = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "d %c %g", x < 0 ? '-' : '+', std::abs(x));
    return std::string(buf);
  };
  std::string out = "[";
  out += term(offset.lo);
  out += ", ";
  out += term(offset.hi);
  out += "]";
  return out;
}

constexpr const char* kInteriorDiag = "diag-d-bump-interior";
constexpr const char* kLevel5Diag = "diag-d6-level5";
constexpr const char* kD5Level5Diag = "diag-d5-level5";

const Series* interior(const Data& d, Check& c, const std::string& family, const std::string& m,
                       const std::string& q) {
  return d.find(c, query(kInteriorDiag, family, m, q, "L2", "none", 0.0, "interior"));
}

const Series* boundary_ring(const Data& d, Check& c, const std::string& family,
                            const std::string& m, const std::string& q) {
  return d.find(c, query("fig13-14", family, m, q, "L2", "none", 0.0, "boundary-ring"));
}

// "a, b, c, d" of the level-by-level ratios a/b, and their maximum.
std::string ratio_list(const Series& a, const Series& b, double& max_ratio) {
  std::vector<std::string> values;
  for (const auto& x : error_ratios(a, b)) {
    values.push_back(f2(x.value));
    max_ratio = std::max(max_ratio, x.value);
  }
  return join(values, ", ");
}

// D1's Why line (localised): the K spread of the degree-2 fits split into the interior vertices
// (diag-d-bump-interior) and the boundary ring (fig13-14), and the LSCM map's solver.
std::vector<WhyFinding> why_d1(const Data& d, const Band& band) {
  std::vector<std::string> parts;
  bool interior_outside = false, ring_inside = true;
  for (const auto& fam : d.bumps()) {
    Check scratch;
    const Series* lhf = interior(d, scratch, fam, "LHF-2", "K");
    const Series* lop = interior(d, scratch, fam, "LOP-2", "K");
    const Series* lscm = interior(d, scratch, fam, "LSCM-2", "K");
    const Series* fast = interior(d, scratch, fam, "LSCM-fast-2", "K");
    const Series* lhf_ring = boundary_ring(d, scratch, fam, "LHF-2", "K");
    const Series* lscm_ring = boundary_ring(d, scratch, fam, "LSCM-2", "K");
    if (!lhf || !lop || !lscm || !fast || !lhf_ring || !lscm_ring) return {};
    double m_in = 0.0, m_ring = 0.0, m_lop = 0.0, m_fast = 0.0;
    const std::string in = ratio_list(*lscm, *lhf, m_in);
    const std::string ring = ratio_list(*lscm_ring, *lhf_ring, m_ring);
    ratio_list(*lop, *lhf, m_lop);
    ratio_list(*fast, *lscm, m_fast);
    interior_outside = interior_outside || !band.holds(m_in);
    ring_inside = ring_inside && band.holds(m_ring);
    parts.push_back(fam + ": interior " + in + ", boundary ring " + ring +
                    " (LOP-2 / LHF-2 interior at most " + f2(m_lop) +
                    ", LSCM-fast-2 / LSCM-2 at most " + f2(m_fast) + ")");
  }
  const std::string numbers =
      "diagnostic diag-d-bump-interior (report/diag-d-bump-interior.md), K L2 of LSCM-2 / LHF-2 at "
      "levels 1-4: " +
      join(parts, "; ");
  if (!(interior_outside && ring_inside)) return finding(CauseKind::tried, numbers);
  return finding(CauseKind::localised,
                 "the LSCM map on the interior: " + numbers +
                     "; the three fits agree on the boundary ring, and the spread is LSCM-2's "
                     "Gaussian curvature at the interior vertices, the same with the fast solve "
                     "of the same map: in the conformal parameterization, not in the solver or "
                     "at the boundary");
}

// D2's Why line (localised): the degree-2 H rates over the interior (diag-d-bump-interior), over
// the boundary ring (fig13-14) and over all vertices (fig09-10), against the tori's: how much the
// boundary lowers each bump's rate, and where the interior itself sets it.
std::vector<WhyFinding> why_d2(const Data& d, const std::vector<std::string>& tori, double gap) {
  std::vector<std::string> parts;
  for (const auto& fam : d.bumps()) {
    Check scratch;
    const Series* in = interior(d, scratch, fam, "LHF-2", "H");
    const Series* ring = boundary_ring(d, scratch, fam, "LHF-2", "H");
    const Series* all = bump(d, scratch, fam, "LHF-2", "H", "L2");
    if (!in || !ring || !all) return {};
    const double loss = d.rate(*in) - d.rate(*all);
    parts.push_back(
        fam + ": interior " + f2(d.rate(*in)) + ", boundary ring " + f2(d.rate(*ring)) +
        ", all vertices " + f2(d.rate(*all)) +
        (loss >= gap ? " (the boundary lowers the rate by " + f2(loss) + ", as the paper says)"
                     : " (the interior converges no faster than the boundary ring: its irregular "
                       "stencils, not the boundary, set the rate)"));
  }
  std::vector<std::string> torus_rates;
  for (const auto& tor : tori) {
    Check scratch;
    if (const Series* t = torus2(d, scratch, tor, "LHF-2", "H", "L2"))
      torus_rates.push_back(tor + " " + f2(d.rate(*t)));
  }
  return finding(CauseKind::localised,
                 "the rates split by vertex set (diagnostic diag-d-bump-interior, "
                 "report/diag-d-bump-interior.md), "
                 "LHF-2 H L2: " +
                     join(parts, "; ") + "; the tori the bump is compared with converge at " +
                     join(torus_rates, ", ") +
                     ", below the symmetric-stencil rate 2 themselves, so a bump whose interior "
                     "is as symmetric as the 4-8 mesh's ends level with them");
}

// ---- the safeguard (the reading `safeguard`, docs/claims.md) and the deep levels ----------------

constexpr const char* kFiresCsv = "diag-safeguard-fires.csv";
constexpr const char* kDeepFolder = "deep";
constexpr const char* kDeepD5 = "diag-deep-d5-level6";
constexpr const char* kDeepD6 = "diag-deep-d6-level6";

// The error rows of a results subfolder (a reading's run, results/deep/), or none.
std::optional<Data> folder_data(const Data& d, const std::string& sub) {
  std::error_code ec;
  const std::string path = d.dir() + "/" + sub;
  if (d.dir().empty() || !std::filesystem::is_directory(path, ec)) return std::nullopt;
  return d.in_folder(path);
}

// The series restricted to levels [a, b].
Series levels_of(const Series& s, int a, int b) {
  Series out = s;
  std::erase_if(out.points, [&](const Point& p) { return p.level < a || p.level > b; });
  return out;
}

// "LSCM-4 H 3.02, normal 4.10" on bump-48 over the levels of `s`'s source under each safeguard
// choice: the adopted from d, the alternatives from results/readings/safeguard=<choice>/ (or "not
// run"). `series` picks the series of a Data.
template <class SeriesOf>
std::string safeguard_rates(const Data& d, const std::vector<std::string>& methods,
                            SeriesOf series) {
  std::vector<std::string> parts;
  for (const char* choice : {"condition-1e-3", "rjj-only", "1e-8"}) {
    const bool adopted = std::string(choice) == "condition-1e-3";
    const std::string folder = std::string("readings/safeguard=") + choice;
    std::optional<Data> alt;
    if (!adopted) alt = folder_data(d, folder);
    const Data* src = adopted ? &d : alt ? &*alt : nullptr;
    std::vector<std::string> rates;
    for (const std::string& m : methods)
      for (const char* q : {"H", "normal"}) {
        const Series* s = src ? series(*src, m, q) : nullptr;
        rates.push_back(m + " " + q + " " + (s ? f2(d.rate(*s)) : std::string("n/a")));
      }
    parts.push_back(
        std::string(choice) + (adopted ? " (adopted)" : "") + ": " +
        (src ? join(rates, ", ") : "not run here (results/" + folder + "/, make experiments)"));
  }
  return join(parts, "; ");
}

// Where the condition test cuts a stencil (results/diag-safeguard-fires.csv) for `method` on
// bump-48: per level the vertices cut and their condition numbers, whether the cut points agree
// with the coarser level's on the points both levels have (the 4-8 grids nest), and the runs of
// consecutive levels over which they do (the stencil is one and the same). Empty without the CSV.
struct Fires {
  std::string text;
  std::vector<std::pair<int, int>> same_runs;  ///< [first, last] level, >= 2 levels each
};
Fires safeguard_fires_on_bump48(const Data& d, const std::string& method) {
  Fires out;
  std::error_code ec;
  const std::string path = d.dir() + "/" + kFiresCsv;
  if (d.dir().empty() || !std::filesystem::exists(path, ec)) return out;
  std::map<int, std::set<std::pair<long, long>>> cut;  // level -> grid points (i, j) at level 6
  std::map<int, std::vector<double>> condition;
  std::map<int, int> boundary;
  for (const SafeguardFire& f : read_safeguard_fires_csv(path)) {
    if (f.family != kBump48 || upper(f.method) != upper(method)) continue;
    cut[f.level];
    if (f.vertex < 0) continue;
    const double n = bump_grid_size(max_bump_level());  // finest grid: exact integer indices
    cut[f.level].insert({std::lround(f.x * n), std::lround(f.y * n)});
    condition[f.level].push_back(f.condition);
    boundary[f.level] += f.boundary;
  }
  if (cut.empty()) return out;
  std::vector<std::string> levels;
  std::vector<bool> same_as_previous;
  int previous = -1;
  for (const auto& [level, points] : cut) {
    const auto& c = condition[level];
    std::string line = "level " + std::to_string(level) + ": " + std::to_string(points.size());
    if (!c.empty())
      line += " (" + std::to_string(boundary[level]) + " on the boundary; condition " +
              f2(*std::min_element(c.begin(), c.end())) + "-" +
              f2(*std::max_element(c.begin(), c.end())) + ")";
    bool same = false;
    if (previous == level - 1) {
      // The points of the coarser level: a multiple of its grid step on the finest grid.
      const long step = bump_grid_size(max_bump_level()) / bump_grid_size(level - 1);
      std::set<std::pair<long, long>> here;
      for (const auto& p : points)
        if (p.first % step == 0 && p.second % step == 0) here.insert(p);
      same = here == cut.at(level - 1);
      if (!same) line += ", not cut alike at the points of level " + std::to_string(level - 1);
    }
    same_as_previous.push_back(same);
    levels.push_back(line);
    previous = level;
  }
  // Runs of levels whose consecutive pairs agree.
  const std::vector<int> ls = [&] {
    std::vector<int> v;
    for (const auto& [level, points] : cut) v.push_back(level);
    return v;
  }();
  size_t start = 0;
  for (size_t i = 1; i <= ls.size(); ++i)
    if (i == ls.size() || !same_as_previous[i]) {
      if (i - 1 > start) out.same_runs.push_back({ls[start], ls[i - 1]});
      start = i;
    }
  out.text = "the condition test cuts the first stencil of " + method + " on bump-48 at " +
             join(levels, "; ") + " (" + kFiresCsv + ")";
  return out;
}

// The rates of `series` over each run of levels where the stencils are the same, or "".
template <class SeriesOf>
std::string same_stencil_rates(const Data& d, const Fires& fires, const std::string& method,
                               SeriesOf series) {
  std::vector<std::string> parts;
  for (const auto& [a, b] : fires.same_runs)
    for (const char* q : {"H", "normal"})
      if (const Series* s = series(method, q)) {
        const Series part = levels_of(*s, a, b);
        if (part.points.size() >= 2)
          parts.push_back(q + (" over levels " + std::to_string(a) + "-" + std::to_string(b)) +
                          " " + f2(d.rate(part)));
      }
  return join(parts, ", ");
}

// The level-to-level rate from level 5 to 6 of the deep run's series (results/deep/), or none.
std::optional<double> deep_rate(const std::optional<Data>& deep, const std::string& experiment,
                                const std::string& family, const std::string& method, const char* q,
                                const std::string& vertex_set) {
  if (!deep) return std::nullopt;
  Check scratch;
  const Series* s =
      deep->find(scratch, query(experiment, family, method, q, "L2", "none", 0.0, vertex_set));
  if (!s || s->experiment != experiment || !s->at(5) || !s->at(6)) return std::nullopt;
  return deep->rate(levels_of(*s, 5, 6));
}

// "where the deep levels would come from" when results/deep/ lacks them.
std::string deep_absent(const std::string& experiment) {
  return "levels 5-6 of " + experiment +
         " are not in results/deep/ (make experiments-deep "
         "writes them, experiments/deep/; opt-in, level 6 has 263169 vertices)";
}

// One diagnostic of D5: a cause when the rate gap holds on every bump under it (D5's check is
// reproduced with the diagnostic's change), else localised or tried; `text` says what was
// measured.
struct D5Finding {
  bool cause = false;  ///< the gap holds on every bump
  std::string text;
  std::vector<std::string> short_of;  ///< the bumps where the gap misses the band
  bool localised = false;             ///< not a cause, but where the miss starts
};

// rate(LHF-4) - rate(<lscm>) for normals and H (L2) on each bump, from `series(family, method, q)`;
// holds when normals or H reach the band on every bump. Empty text when a series is missing.
template <class SeriesOf>
D5Finding d5_gaps(const Data& d, const Band& band, const std::string& lscm, SeriesOf series,
                  bool with_rates = false) {
  std::vector<std::string> parts, short_of;
  bool holds_everywhere = true;
  for (const auto& fam : d.bumps()) {
    bool any = false;
    std::vector<std::string> gaps;
    for (const char* q : {"normal", "H"}) {
      const std::optional<double> lhf = series(fam, std::string("LHF-4"), q),
                                  other = series(fam, lscm, q);
      if (!lhf || !other) return {};
      const double g = *lhf - *other;
      any = any || band.holds(g);
      gaps.push_back(std::string(q) + " " +
                     (with_rates ? f2(*lhf) + " - " + f2(*other) + " = " : std::string()) + f2(g));
    }
    holds_everywhere = holds_everywhere && any;
    if (!any) short_of.push_back(fam);
    parts.push_back(fam + ": " + join(gaps, ", "));
  }
  return {holds_everywhere,
          join(parts, "; ") + " (" + band.text() + " for normals or H" +
              (holds_everywhere ? ")" : ": short on " + join(short_of, ", ") + ")"),
          short_of};
}

// `f` with `prefix` before its text (unchanged when a series was missing).
D5Finding prefixed(D5Finding f, const std::string& prefix) {
  if (!f.text.empty()) f.text = prefix + f.text;
  return f;
}

std::optional<double> rate_of(const Data& d, const Series* s) {
  return s ? std::optional<double>(d.rate(*s)) : std::nullopt;
}

// The LSCM map solved by conjugate gradients (lscm-cg-4, the solver of C4's Why line).
D5Finding d5_solver(const Data& d, const Band& band) {
  D5Finding f = d5_gaps(d, band, "LSCM-CG-4",
                        [&](const std::string& fam, const std::string& m, const char* q) {
                          Check scratch;
                          return rate_of(d, bump(d, scratch, fam, m, q, "L2"));
                        });
  return prefixed(std::move(f),
                  "the LSCM solver: with the map solved by conjugate gradients to 1e-6 "
                  "(lscm-cg-4), rate(LHF-4) - rate(LSCM-CG-4) is ");
}

// The gap over the interior vertices alone (diag-d-bump-interior).
D5Finding d5_interior(const Data& d, const Band& band) {
  D5Finding f = d5_gaps(
      d, band, "LSCM-4",
      [&](const std::string& fam, const std::string& m, const char* q) {
        Check scratch;
        return rate_of(d, interior(d, scratch, fam, m, q));
      },
      true);
  return prefixed(
      std::move(f),
      "the boundary ring: over the interior vertices alone (diagnostic "
      "diag-d-bump-interior, report/diag-d-bump-interior.md), rate(LHF-4) - rate(LSCM-4) is ");
}

// The gap between the rates of the finest pair of levels, one level finer than the paper's four
// (diag-d5-level5), with each method's level-to-level H rates.
D5Finding d5_levels(const Data& d, const Band& band) {
  // The level-to-level rates over levels 1-5 (none when the diagnostic is missing).
  auto pair_rates = [&](const std::string& fam, const std::string& m, const char* q) {
    Check scratch;
    const Series* s = d.find(scratch, query(kD5Level5Diag, fam, m, q, "L2"));
    return s && s->points.size() >= 5 ? d.pair_rates(*s) : std::vector<double>{};
  };
  D5Finding f = d5_gaps(
      d, band, "LSCM-4",
      [&](const std::string& fam, const std::string& m, const char* q) -> std::optional<double> {
        const std::vector<double> r = pair_rates(fam, m, q);
        return r.empty() ? std::nullopt : std::optional<double>(r.back());
      },
      true);
  if (f.text.empty()) return f;
  // The mechanism the paper names, LSCM-4 losing an order, seen as a fall of its H rate at the
  // finest pair on every bump (>= 0.3 below its earlier level-to-level rates).
  std::vector<std::string> rates, drops, at_theory;
  bool falls_everywhere = true, lhf_at_theory = true;
  for (const auto& fam : d.bumps()) {
    for (const char* m : {"LHF-4", "LSCM-4"}) {
      std::vector<std::string> values;
      for (double r : pair_rates(fam, m, "H")) values.push_back(f2(r));
      rates.push_back(fam + " " + m + " H " + join(values, ", "));
    }
    const std::vector<double> lscm = pair_rates(fam, "LSCM-4", "H");
    const double fall = *std::max_element(lscm.begin(), lscm.end() - 1) - lscm.back();
    falls_everywhere = falls_everywhere && fall >= 0.3;
    drops.push_back(fam + " " + f2(fall));
    if (std::find(f.short_of.begin(), f.short_of.end(), fam) != f.short_of.end()) {
      const double lhf = pair_rates(fam, "LHF-4", "H").back();
      lhf_at_theory = lhf_at_theory && std::abs(lhf - 3.0) <= 0.3;
      at_theory.push_back(fam + " " + f2(lhf));
    }
  }
  const std::string numbers = "level-to-level rates " + join(rates, "; ") +
                              "; rate(LHF-4) - rate(LSCM-4) from level 4 to 5 is " + f.text;
  if (f.cause || !falls_everywhere) {
    f.text =
        "one level finer than the paper's four (diagnostic diag-d5-level5, "
        "report/diag-d5-level5.md), " +
        numbers;
    return f;
  }
  // The fall is where the miss is, not a cause: the gap is still short one level finer.
  f.localised = true;
  f.text =
      "one level finer than the paper's four (diagnostic diag-d5-level5, "
      "report/diag-d5-level5.md), LSCM-4's "
      "H rate from level 4 to 5 falls below its earlier level-to-level rates by " +
      join(drops, ", ") +
      ", as the tori's does from level 1 (claim C5), but the gap is still short there: " + numbers +
      "; where it is short, LHF-4's H rate from level 4 to 5 is " + join(at_theory, ", ") +
      (lhf_at_theory ? ", its theoretical d - 1 = 3, so the gap reaches 1.0 only once LSCM-4 "
                       "has lost a whole order, which levels 1-5 do not show"
                     : "");
  return f;
}

// The gap from level 5 to 6 (make experiments-deep, results/deep/): a cause if it holds on every
// bump there; the LSCM-4 and LHF-4 H rates of the three bump meshes with it.
D5Finding d5_deep(const Data& d, const Band& band) {
  const std::optional<Data> deep = folder_data(d, kDeepFolder);
  auto rate = [&](const std::string& fam, const std::string& m, const char* q) {
    return deep_rate(deep, kDeepD5, fam, m, q, "all");
  };
  D5Finding f = d5_gaps(d, band, "LSCM-4", rate, true);
  if (f.text.empty()) return {false, "two levels finer: " + deep_absent(kDeepD5), {}, false};
  std::vector<std::string> rates;
  for (const char* fam : {"bump-irregular", "bump-48", "bump-unstructured"})
    for (const char* m : {"LSCM-4", "LHF-4"})
      if (const auto r = rate(fam, m, "H"))
        rates.push_back(std::string(fam) + " " + m + " " + f2(*r));
  f.text = "two levels finer than the paper's four (make experiments-deep, results/deep/" +
           std::string(kDeepD5) + ".csv), the H rates from level 5 to 6: " + join(rates, ", ") +
           "; rate(LHF-4) - rate(LSCM-4) from level 5 to 6 is " + f.text;
  return f;
}

// The safeguard on bump-48 (docs/claims.md, "The safeguard of the QR"): LHF-4's and LSCM-4's rates
// over levels 1-4 (fig11-12) under the three safeguards, where the condition test cuts a stencil,
// and the rates over the levels whose stencils are the same.
std::optional<WhyFinding> d5_safeguard(const Data& d) {
  const std::string rates = safeguard_rates(
      d, {"LHF-4", "LSCM-4"}, [](const Data& src, const std::string& m, const char* q) {
        Check scratch;
        return bump(src, scratch, kBump48, m, q, "L2");
      });
  bool located = true;  // localised where the firing CSV says which levels mix stencils
  std::string text =
      "the safeguard of the QR (the reading safeguard, docs/claims.md): bump-48 "
      "L2 rates over levels 1-4 (fig11-12) under " +
      rates;
  for (const char* m : {"LSCM-4", "LHF-4"}) {
    const Fires fires = safeguard_fires_on_bump48(d, m);
    if (fires.text.empty()) {
      text += std::string("; where the condition test cuts a stencil is not here (") + kFiresCsv +
              ", make experiments)";
      located = false;
      break;
    }
    text += "; " + fires.text;
    const std::string same =
        same_stencil_rates(d, fires, m, [&](const std::string& method, const char* q) {
          Check scratch;
          return bump(d, scratch, kBump48, method, q, "L2");
        });
    text += same.empty() ? ": no two consecutive levels with the same stencils, so every rate over "
                           "levels 1-4 mixes stencils"
                         : ": the rates over the levels with the same stencils: " + same;
  }
  return WhyFinding{located ? CauseKind::localised : CauseKind::tried, text};
}

// D5's Why line from its diagnostics.
std::vector<WhyFinding> why_d5(const Data& d, const Band& band) {
  std::vector<WhyFinding> out;
  for (const D5Finding& f :
       {d5_levels(d, band), d5_deep(d, band), d5_interior(d, band), d5_solver(d, band)}) {
    if (f.text.empty()) continue;
    out.push_back({f.cause       ? CauseKind::cause_removed_passes
                   : f.localised ? CauseKind::localised
                                 : CauseKind::tried,
                   f.text});
  }
  if (auto f = d5_safeguard(d)) out.push_back(std::move(*f));
  return out;
}

// D6's check: LHF-d and LSCM-d (d = 2, 3, 4) over the boundary ring of both bumps (fig13-14),
// each rate in its band and <= the all-vertex rate + margin. With `finer`, degree 4 is read one
// level finer: the boundary ring from diag-d6-level5 and all vertices from diag-d5-level5.
void claim_d6(const Data& d, Check& c, const Band& normal_offset, const Band& curvature_offset,
              double margin, bool finer) {
  for (const auto& fam : d.bumps())
    for (const char* method : {"LHF", "LSCM"})
      for (int deg : {2, 3, 4}) {
        const std::string m = std::string(method) + "-" + std::to_string(deg);
        const bool level5 = finer && deg == 4;
        for (const char* q : {"normal", "H", "K"}) {
          const Series* s =
              level5 ? d.find(c, query(kLevel5Diag, fam, m, q, "L2", "none", 0.0, "boundary-ring"))
                     : boundary_ring(d, c, fam, m, q);
          const Series* all = level5 ? d.find(c, query(kD5Level5Diag, fam, m, q, "L2"))
                                     : bump(d, c, fam, m, q, "L2");
          // One level finer means the diagnostics' own rows (find falls back to other
          // experiments' rows of the same configuration).
          for (auto [series, experiment] : {std::pair{&s, kLevel5Diag}, {&all, kD5Level5Diag}})
            if (level5 && *series && (*series)->experiment != experiment) {
              c.missing(fam + " " + m + " " + q + " L2: no rows of " + experiment +
                        " (make experiments)");
              *series = nullptr;
            }
          if (!s) continue;
          const Band& off = std::string(q) == "normal" ? normal_offset : curvature_offset;
          require_rate(d, c, *s, Band::in(deg + off.lo, deg + off.hi, 2), "boundary-ring ");
          if (all)
            c.require(d.rate(*s) <= d.rate(*all) + margin,
                      fam + " " + m + " " + q + " L2: boundary-ring rate " + f2(d.rate(*s)) +
                          " <= all-vertex rate " + f2(d.rate(*all)) + " + " + num(margin));
        }
      }
}

// D6's findings one level finer: D6's check with degree 4 over levels 1-5 (a cause only if it
// is reproduced there), with LHF-4's boundary-ring rates over levels 1-5 (diag-d6-level5).
std::vector<WhyFinding> why_d6_levels(const Data& d, const Band& normal_offset,
                                      const Band& curvature_offset, double margin) {
  const Band band = Band::in(4 + curvature_offset.lo, 4 + curvature_offset.hi, 2);
  std::vector<std::string> parts;
  for (const auto& fam : d.bumps())
    for (const char* q : {"H", "K"}) {
      Check scratch;
      const Series* s =
          d.find(scratch, query(kLevel5Diag, fam, "LHF-4", q, "L2", "none", 0.0, "boundary-ring"));
      if (!s || s->points.size() < 5) return {};
      parts.push_back(fam + " " + q + " rate over levels 1-" + std::to_string(s->last().level) +
                      " " + f2(d.rate(*s)) + " (" +
                      s->detail().substr(s->detail().find("level-to-level")) + ")");
    }
  Check finer;
  claim_d6(d, finer, normal_offset, curvature_offset, margin, true);
  std::vector<std::string> open;  // what keeps the finer check from being reproduced
  for (const std::string& line : finer.lines())
    if (line.rfind("[FAIL]", 0) == 0 || line.rfind("[missing]", 0) == 0)
      open.push_back(line.substr(0, line.find("; errors at")));
  const std::string numbers =
      "one level finer than the paper's four (diagnostics diag-d6-level5 and diag-d5-level5, "
      "report/diag-d6-level5.md and report/diag-d5-level5.md), LHF-4 boundary ring: " +
      join(parts, "; ") + " (band " + band.text() + "); D6's check with degree 4 over levels " +
      "1-5 is " + to_string(finer.verdict());
  if (finer.verdict() == Verdict::reproduced)
    return finding(CauseKind::cause_removed_passes, "the levels: " + numbers);
  return finding(CauseKind::tried, numbers + (open.empty() ? "" : ": " + join(open, "; ")));
}

// D6 two levels finer: the degree-4 boundary-ring rates from level 5 to 6 (results/deep/)
// against D6's bands; tried (D6's check reads degrees 2 and 3 too), or where they would come
// from.
WhyFinding why_d6_deep(const Data& d, const Band& normal_offset, const Band& curvature_offset) {
  const std::optional<Data> deep = folder_data(d, kDeepFolder);
  std::vector<std::string> parts;
  int in_band = 0, total = 0;
  for (const char* fam : {"bump-irregular", "bump-48", "bump-unstructured"})
    for (const char* m : {"LHF-4", "LSCM-4"})
      for (const char* q : {"normal", "H", "K"}) {
        const auto r = deep_rate(deep, kDeepD6, fam, m, q, "boundary-ring");
        if (!r) continue;
        const Band& off = std::string(q) == "normal" ? normal_offset : curvature_offset;
        const bool ok = Band::in(4 + off.lo, 4 + off.hi, 2).holds(*r);
        in_band += ok;
        ++total;
        parts.push_back(std::string(fam) + " " + m + " " + q + " " + f2(*r) + (ok ? "" : " (out)"));
      }
  if (total == 0) return {CauseKind::tried, "two levels finer: " + deep_absent(kDeepD6)};
  return {CauseKind::tried,
          "two levels finer than the paper's four (make experiments-deep, results/deep/" +
              std::string(kDeepD6) + ".csv), the degree-4 boundary-ring rates from level 5 to 6: " +
              join(parts, ", ") + "; " + std::to_string(in_band) + " of " + std::to_string(total) +
              " in D6's bands (normals d - " + num(-normal_offset.lo) + " to d + " +
              num(normal_offset.hi) + ", H and K d - " + num(-curvature_offset.lo) + " to d - " +
              num(-curvature_offset.hi) + ")"};
}

// D6 and the safeguard on the 4-8 mesh's boundary (localised): the degree-4 boundary-ring rates
// over levels 1-4 (fig13-14) under the three safeguards, where the condition test cuts a stencil,
// and the boundary-ring rates over the levels whose stencils are the same.
std::optional<WhyFinding> why_d6_safeguard(const Data& d) {
  const auto ring_of = [](const Data& src, const std::string& m, const char* q) {
    Check scratch;
    return boundary_ring(src, scratch, kBump48, m, q);
  };
  Check probe;
  if (!boundary_ring(d, probe, kBump48, "LHF-4", "H")) return std::nullopt;
  bool located = true;  // localised where the firing CSV says which levels mix stencils
  std::string text =
      "on bump-48, the safeguard on the degree-4 stencils of the 4-8 mesh's boundary, which lie "
      "on four grid lines (docs/claims.md): boundary-ring L2 rates over levels 1-4 (fig13-14) "
      "under " +
      safeguard_rates(d, {"LHF-4", "LSCM-4"}, ring_of);
  for (const char* m : {"LHF-4", "LSCM-4"}) {
    const Fires fires = safeguard_fires_on_bump48(d, m);
    if (fires.text.empty()) {
      text += std::string("; where the condition test cuts a stencil is not here (") + kFiresCsv +
              ", make experiments)";
      located = false;
      break;
    }
    text += "; " + fires.text;
    const std::string same = same_stencil_rates(
        d, fires, m,
        [&](const std::string& method, const char* q) { return ring_of(d, method, q); });
    text += same.empty()
                ? ": no two consecutive levels with the same stencils, so every "
                  "boundary-ring rate over levels 1-4 mixes stencils"
                : ": the boundary-ring rates over the levels with the same stencils: " + same;
  }
  // One stencil per point over the levels: LHF-4 at 3.5 rings (diag-d6-level5's "LHF-4 3.5-ring"),
  // whose stencils reach a fifth grid line.
  const Fires fixed = safeguard_fires_on_bump48(d, "LHF-4 rings=3.5");
  if (!fixed.text.empty()) {
    const std::string same = same_stencil_rates(
        d, fixed, "LHF-4 3.5-ring", [&](const std::string& method, const char* q) {
          Check scratch;
          return d.find(scratch,
                        query(kLevel5Diag, kBump48, method, q, "L2", "none", 0.0, "boundary-ring"));
        });
    text += "; " + fixed.text +
            (same.empty() ? std::string(": no two consecutive levels with the same stencils")
                          : ": the boundary-ring rates of LHF-4 at 3.5 rings (diag-d6-level5) "
                            "over the levels with the same stencils: " +
                                same);
  }
  return WhyFinding{located ? CauseKind::localised : CauseKind::tried, text};
}

}  // namespace

std::vector<ClaimEntry> section5_2_claims() {
  std::vector<ClaimEntry> out;

  const Band d1 = Band::at_most(1.5);
  out.push_back({"D1",
                 "Degree 2 on the bump: LHF-2, LOP-2, LSCM-2 very similar",
                 "Degree 2: LHF-2, LOP-2 and LSCM-2 deliver very similar results.",
                 "within a factor " + num(d1.hi) +
                     " of each other at every level (normal L2 and Linf, H L2, K L2; "
                     "bump-irregular and bump-48)",
                 {{"max_over_min", d1}},
                 [=](const Data& d, Check& c) {
                   const std::pair<const char*, const char*> measures[] = {
                       {"normal", "L2"}, {"normal", "Linf"}, {"H", "L2"}, {"K", "L2"}};
                   for (const auto& fam : d.bumps())
                     for (const auto& [q, norm] : measures) {
                       std::vector<const Series*> ss;
                       for (const auto& m : kDeg2Others)
                         if (const Series* s = bump(d, c, fam, m, q, norm)) ss.push_back(s);
                       if (ss.size() != kDeg2Others.size()) continue;
                       require_every_level(c, spreads(ss), d1,
                                           fam + " " + q + " " + norm + " max/min of " +
                                               join(methods_of(ss), ", "));
                     }
                 },
                 {},
                 [=](const Data& d) { return why_d1(d, d1); }});

  const Band d2_gap = Band::at_least(0.2);
  out.push_back({"D2",
                 "Bump H L2 rates lower than on the torus",
                 "Degree 2: the L2 convergence rates of mean curvature are lower than on the torus "
                 "(loss of cancellation at the boundary).",
                 "bump H L2 rate <= torus H L2 rate - " + num(d2_gap.lo) +
                     " for the same method (LHF-2, LOP-2, "
                     "LSCM-2; each bump mesh against each torus mesh type); expect about 1.0-1.6",
                 {{"torus_minus_bump_rate", d2_gap}},
                 [=](const Data& d, Check& c) {
                   for (const auto& m : kDeg2Others)
                     for (const auto& fam : d.bumps()) {
                       const Series* b = bump(d, c, fam, m, "H", "L2");
                       for (const auto& tor : d.tori()) {
                         const Series* t = torus2(d, c, tor, m, "H", "L2");
                         if (!b || !t) continue;
                         c.require(d.rate(*b) <= d.rate(*t) - d2_gap.lo,
                                   m + " H L2: rate on " + fam + " " + f2(d.rate(*b)) +
                                       " <= rate on " + tor + " " + f2(d.rate(*t)) + " - " +
                                       num(d2_gap.lo) + "; bump " + b->detail());
                       }
                     }
                 },
                 {},
                 [=](const Data& d) { return why_d2(d, d.tori(), d2_gap.lo); }});

  out.push_back({"D3",
                 "Xu-2 curvatures fail to converge on the bump",
                 "Xu-2 curvatures (H and K) fail to converge on both mesh types, because the "
                 "stencils have too few points.",
                 "the failure criterion for H and K in L2 (interior vertices), bump-irregular and "
                 "bump-48",
                 {},
                 [](const Data& d, Check& c) {
                   for (const auto& fam : d.bumps())
                     for (const char* q : {"H", "K"})
                       if (const Series* s = bump(d, c, fam, "Xu-2", q, "L2"))
                         require_failure(d, c, *s);
                 },
                 {}});

  const Band d4 = Band::below(1.0);
  out.push_back({"D4",
                 "LHF more accurate than LSCM at degrees 3 and 4 on the bump",
                 "Degrees 3 and 4: LHF is consistently more accurate than LSCM for both d = 3 and "
                 "d = 4.",
                 "err(LHF-d) < err(LSCM-d) at >= 3 of 4 levels, for normals (L2 and Linf), H and K "
                 "(L2), d = 3, 4, on both bump meshes",
                 {{"ratio", d4}},
                 [=](const Data& d, Check& c) {
                   const std::pair<const char*, const char*> measures[] = {
                       {"normal", "L2"}, {"normal", "Linf"}, {"H", "L2"}, {"K", "L2"}};
                   for (const auto& fam : d.bumps())
                     for (int deg : {3, 4})
                       for (const auto& [q, norm] : measures) {
                         const std::string dd = std::to_string(deg);
                         const Series* lhf = bump(d, c, fam, "LHF-" + dd, q, norm);
                         const Series* lscm = bump(d, c, fam, "LSCM-" + dd, q, norm);
                         if (!lhf || !lscm) continue;
                         require_most_levels(
                             c, error_ratios(*lhf, *lscm), d4,
                             fam + " " + q + " " + norm + " " + lhf->method + " / " + lscm->method);
                       }
                 },
                 {}});

  const Band d5 = Band::at_least(1.0, 1);
  out.push_back({"D5",
                 "LSCM-4 converges substantially slower than LHF-4 on the bump",
                 "LSCM-4 converges substantially slower than LHF-4.",
                 "rate(LHF-4) - rate(LSCM-4) " + d5.text() +
                     " for normals or H (L2), on each bump "
                     "mesh",
                 {{"rate_gap", d5}},
                 [=](const Data& d, Check& c) {
                   for (const auto& fam : d.bumps()) {
                     std::vector<std::string> parts;
                     bool any = false, complete = true;
                     for (const char* q : {"normal", "H"}) {
                       const Series* lhf = bump(d, c, fam, "LHF-4", q, "L2");
                       const Series* lscm = bump(d, c, fam, "LSCM-4", q, "L2");
                       if (!lhf || !lscm) {
                         complete = false;
                         continue;
                       }
                       const double gap = d.rate(*lhf) - d.rate(*lscm);
                       any = any || d5.holds(gap);
                       parts.push_back(std::string(q) + " L2 " + f2(d.rate(*lhf)) + " - " +
                                       f2(d.rate(*lscm)) + " = " + f2(gap));
                     }
                     if (complete)
                       c.require(any, fam + ": rate(LHF-4) - rate(LSCM-4): " + join(parts, "; ") +
                                          " (" + d5.text() + " for normals or H)");
                   }
                 },
                 {},
                 // Diagnostics: one level finer (diag-d5-level5), the interior vertices
                 // (diag-d-bump-interior), the LSCM map's solver (lscm-cg-4).
                 [=](const Data& d) { return why_d5(d, d5); }});

  // Relative to the degree d.
  const Band d6_normal = Band::in(-0.5, 0.7, 2), d6_curvature = Band::in(-1.5, -0.3, 2);
  const double d6_margin = 0.2;
  out.push_back(
      {"D6",
       "Boundary vertices: rates close to theory",
       "Boundary vertices plus their 1-ring neighbours (LHF, LSCM): rates are somewhat lower than "
       "for interior vertices but \"very close to the theoretical analysis\".",
       "LHF-d and LSCM-d (d = 2, 3, 4), boundary-ring L2 rates: normals in " +
           degree_band_text(d6_normal) + "; H and K in " + degree_band_text(d6_curvature) +
           "; each <= the corresponding all-vertex rate + " + num(d6_margin) + "; both bump meshes",
       {{"normal_rate_minus_degree", d6_normal}, {"curvature_rate_minus_degree", d6_curvature}},
       [=](const Data& d, Check& c) { claim_d6(d, c, d6_normal, d6_curvature, d6_margin, false); },
       {},
       // One level finer (diag-d6-level5, diag-d5-level5), two levels finer (results/deep/), and
       // the safeguard on the 4-8 mesh's boundary stencils (docs/claims.md, "The safeguard on
       // near-degenerate stencils", and the reading safeguard).
       [=](const Data& d) -> std::vector<WhyFinding> {
         std::vector<WhyFinding> found = why_d6_levels(d, d6_normal, d6_curvature, d6_margin);
         found.push_back(why_d6_deep(d, d6_normal, d6_curvature));
         if (auto f = why_d6_safeguard(d)) found.push_back(std::move(*f));
         return found;
       }});
  return out;
}

}  // namespace curvbench::claims
