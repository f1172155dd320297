// Claims E1-E9: noisy data (paper §5.3, Figs. 15-22), one registry entry each
// (harness/claims/kit.h; docs/claims.md). The noisy torus is the marching-cubes isosurface
// (fig15-16 degree 2, fig17-18 degrees 3 and 4); the bump gets O(h^3) (fig19-21) or O(h^2)
// (fig20-22) perturbations.
#include <cmath>

#include "harness/claims/kit.h"

namespace curvbench::claims {
namespace {

const Series* noisy_torus(const Data& d, Check& c, const std::string& m, const std::string& q,
                          const std::string& norm, const std::string& experiment = "fig15-16") {
  const double ring = experiment == "fig15-16" ? noisy_torus_ring(m) : 0.0;
  return d.find(c, query(experiment, kNoisyTorus, m, q, norm, "isosurface", ring));
}

// E3's Why line (localised), from the diagnostic experiment diag-e3-rings
// (experiments/diagnostics/diag-e3-rings.exp): LHF-2's H and K errors on the noisy torus at
// rings 1.5 to 4, per level. "" if the diagnostic was not run.
std::vector<WhyFinding> e3_ring_scan(const Data& d) {
  std::vector<std::string> parts;
  bool rises = true;  // the rate rises with the ring, for H and K
  double rate_at_2 = 0.0;
  for (const char* q : {"H", "K"}) {
    std::vector<std::string> rings;
    double previous = -1e300;
    for (const char* r : {"1.5", "2", "3", "4"}) {
      Check scratch;
      const Series* s = d.find(scratch, query("diag-e3-rings", kNoisyTorus,
                                              std::string("LHF-2 r") + r, q, "L2", "isosurface"));
      if (!s || s->points.empty()) return {};
      rises = rises && d.rate(*s) > previous;
      previous = d.rate(*s);
      if (std::string(r) == "2") rate_at_2 = std::max(rate_at_2, d.rate(*s));
      rings.push_back(std::string("ring ") + r + " rate " + f2(d.rate(*s)) + ", finest " +
                      g3(s->last().e));
    }
    parts.push_back(std::string(q) + ": " + join(rings, "; "));
  }
  std::string out =
      "diagnostic diag-e3-rings (LHF-2 on the noisy torus at fixed rings, "
      "report/diag-e3-rings.md): " +
      join(parts, " | ");
  // The same fit with a radius shrinking like h^(1/2) (diag-e3-radius), if it was run.
  std::vector<std::string> growing;
  for (const char* q : {"H", "K"}) {
    Check scratch;
    if (const Series* s = d.find(
            scratch, query("diag-e3-radius", kNoisyTorus, "LHF-2 r~h^0.5", q, "L2", "isosurface")))
      growing.push_back(std::string(q) + " rate " + f2(d.rate(*s)) + ", finest " + g3(s->last().e));
  }
  if (!growing.empty())
    out += " | diag-e3-radius (radius 0.44 h^(1/2): 1.5 to 4 rings over the levels): " +
           join(growing, "; ");
  if (rises)
    out +=
        ". The rate depends on the ring: at the 2 rings of the experiment (1.5 + the noisy-data "
        "half ring) it is at most " +
        f2(rate_at_2) +
        ", and it rises with the ring; with O(h^2) input the paper's error analysis (§3) bounds "
        "the curvature error by a term that a neighbourhood of a fixed number of rings does not "
        "shrink. LSCM-2 is not in the diagnostic, so whether the claim holds at a wider ring is "
        "not measured";
  return finding(CauseKind::localised, out);
}

const Series* bump_noise(const Data& d, Check& c, const std::string& fam, const std::string& m,
                         const std::string& q, const std::string& norm, int order) {
  return d.find(c, query(order == 3 ? "fig19-21" : "fig20-22", fam, m, q, norm,
                         "h^" + std::to_string(order)));
}

const std::vector<std::string> kDeg2All = {"Xu-2", "LHF-2", "LOP-2", "LSCM-2"};

}  // namespace

std::vector<ClaimEntry> section5_3_claims() {
  std::vector<ClaimEntry> out;

  const Band e1 = Band::at_least(20.0);
  out.push_back(
      {"E1",
       "Noisy torus: Xu-2 errors nearly two orders larger",
       "Xu-2 has the largest errors, \"nearly two orders of magnitude larger\" than the others.",
       "err(Xu-2)/min(err of LHF-2, LOP-2, LSCM-2) " + e1.text() +
           " at the finest level, for H and K (L2)",
       {{"ratio", e1}},
       [=](const Data& d, Check& c) {
         for (const char* q : {"H", "K"}) {
           const Series* xu = noisy_torus(d, c, "Xu-2", q, "L2");
           std::vector<const Series*> others;
           for (const auto& m : kDeg2Others)
             if (const Series* s = noisy_torus(d, c, m, q, "L2")) others.push_back(s);
           if (!xu || others.size() != kDeg2Others.size()) continue;
           const auto r = ratios_to_min(*xu, others);
           if (r.empty()) {
             c.missing(std::string(q) + ": no level in common");
             continue;
           }
           require_finest(c, r, e1,
                          kNoisyTorus + " " + q + " L2 " + xu->method + " / min(" +
                              join(methods_of(others), ", ") + ")");
         }
       },
       {},
       // Where the ratio reaches the band (every quantity and norm the experiment scores), and
       // the others' curvature errors against the ring (the E3 diagnostic).
       [=](const Data& d) -> std::vector<WhyFinding> {
         std::vector<std::string> reach, below;
         for (const auto& [q, norm] : std::vector<std::pair<std::string, std::string>>{
                  {"normal", "L2"}, {"normal", "Linf"}, {"H", "L2"}, {"K", "L2"}}) {
           Check scratch;
           const Series* xu = noisy_torus(d, scratch, "Xu-2", q, norm);
           std::vector<const Series*> others;
           for (const auto& m : kDeg2Others)
             if (const Series* s = noisy_torus(d, scratch, m, q, norm)) others.push_back(s);
           if (!xu || others.size() != kDeg2Others.size()) continue;
           const auto r = ratios_to_min(*xu, others);
           if (r.empty()) continue;
           (e1.holds(r.back().value) ? reach : below)
               .push_back(q + " " + norm + " " + f2(r.back().value));
         }
         if (reach.empty() || below.empty()) return {};
         std::vector<WhyFinding> found = finding(CauseKind::localised,
                                                 "the sentence holds for some quantities only "
                                                 "(experiment fig15-16, report/fig15-16.md): Xu-2 "
                                                 "/ best other at the finest level reaches " +
                                                     e1.text() + " for " + join(reach, ", ") +
                                                     ", not for " + join(below, ", "));
         // The denominator: LHF-2's H error at the experiment's 2 rings and at wider ones
         // (diag-e3-rings), against Xu-2's at the finest level.
         Check scratch;
         const Series* xu = noisy_torus(d, scratch, "Xu-2", "H", "L2");
         std::vector<std::string> rings;
         for (const char* r : {"2", "3", "4"}) {
           const Series* s =
               d.find(scratch, query("diag-e3-rings", kNoisyTorus, std::string("LHF-2 r") + r, "H",
                                     "L2", "isosurface"));
           if (!xu || !s) return found;
           const auto ratio = error_ratios(*xu, *s);
           if (ratio.empty()) return found;
           rings.push_back(std::string("ring ") + r + ": LHF-2 H rate " + f2(d.rate(*s)) +
                           ", Xu-2 / LHF-2 at level " + std::to_string(ratio.back().level) + " " +
                           f2(ratio.back().value));
         }
         found.push_back(
             {CauseKind::localised,
              "the denominator: at the experiment's 2 rings LHF-2's H error on the "
              "noisy torus converges slower than first order (claim E3), which keeps "
              "the ratio down; the ring scan (diagnostic diag-e3-rings, report/diag-e3-rings.md) "
              "gives " +
                  join(rings, "; ") +
                  " (a mechanism measured for H, not a prediction of the miss: the "
                  "band's K ratio is not covered)"});
         return found;
       }});

  const Band e2_l2 = Band::in(1.6, 2.6), e2_linf = Band::below(1.9);
  out.push_back(
      {"E2",
       "Noisy torus: normals second order in L2, slower in Linf",
       "LHF-2, LOP-2 and LSCM-2 normals: L2 about second order; Linf slower than second "
       "order.",
       "normal L2 rate " + e2_l2.text() + "; Linf rate < L2 rate and " + e2_linf.text(),
       {{"L2_rate", e2_l2}, {"Linf_rate", e2_linf}},
       [=](const Data& d, Check& c) {
         for (const auto& m : kDeg2Others) {
           const Series* l2 = noisy_torus(d, c, m, "normal", "L2");
           const Series* linf = noisy_torus(d, c, m, "normal", "Linf");
           if (l2) require_rate(d, c, *l2, e2_l2);
           if (l2 && linf)
             c.require(
                 d.rate(*linf) < d.rate(*l2) && e2_linf.holds(d.rate(*linf)),
                 rate_line(d, *linf, "< L2 rate " + f2(d.rate(*l2)) + " and " + e2_linf.text()));
         }
       },
       {},
       // The normals' rate against the neighbourhood (the E3 diagnostics).
       [](const Data& d) -> std::vector<WhyFinding> {
         std::vector<std::string> parts;
         for (const char* r : {"1.5", "2", "3", "4"}) {
           Check scratch;
           if (const Series* s =
                   d.find(scratch, query("diag-e3-rings", kNoisyTorus, std::string("LHF-2 r") + r,
                                         "normal", "L2", "isosurface")))
             parts.push_back(std::string("ring ") + r + " " + f2(d.rate(*s)) + " (" +
                             s->detail().substr(s->detail().find("level-to-level")) + ")");
         }
         Check scratch;
         if (const Series* s = d.find(scratch, query("diag-e3-radius", kNoisyTorus, "LHF-2 r~h^0.5",
                                                     "normal", "L2", "isosurface")))
           parts.push_back("radius 0.44 h^(1/2) " + f2(d.rate(*s)));
         if (parts.empty()) return {};
         return finding(CauseKind::tried,
                        "diagnostics diag-e3-rings and diag-e3-radius (report/diag-e3-rings.md, "
                        "report/diag-e3-radius.md), LHF-2 normal "
                        "L2 rates on the noisy torus: " +
                            join(parts, "; ") +
                            "; for O(h^2) input the paper's error analysis (§3) gives normals of "
                            "first order at a fixed number of rings; the level-to-level rates "
                            "above show how far each ring is from that limit at these levels");
       }});

  const Band e3 = Band::in(0.6, 1.5);
  out.push_back({"E3",
                 "Noisy torus: H and K about first order",
                 "LHF-2, LOP-2 and LSCM-2: L2 errors of H and K converge at about first order.",
                 "H and K L2 rates " + e3.text(),
                 {{"rate", e3}},
                 [=](const Data& d, Check& c) {
                   for (const auto& m : kDeg2Others)
                     for (const char* q : {"H", "K"})
                       if (const Series* s = noisy_torus(d, c, m, q, "L2"))
                         require_rate(d, c, *s, e3);
                 },
                 {},
                 e3_ring_scan});

  const Band e4 = Band::above(1.0);
  out.push_back(
      {"E4",
       "Noisy torus: cubic and quartic fits worse than quadratic",
       "Cubic and quartic fits are worse than quadratic on the noisy torus, because a degree-d "
       "fit needs O(h^(d+1)) input.",
       "at the finest level, err(LHF-3) > err(LHF-2) and err(LHF-4) > err(LHF-2) for H and K "
       "(L2); the normals (L2, weak claim) are reported but do not decide",
       {{"ratio", e4}},
       [=](const Data& d, Check& c) {
         for (const char* q : {"H", "K", "normal"}) {
           const bool weak = std::string(q) == "normal";
           Check scratch;  // the weak normal claim does not decide the verdict
           Check& cc = weak ? scratch : c;
           const Series* lhf2 = noisy_torus(d, cc, "LHF-2", q, "L2", "fig17-18");
           for (const char* m : {"LHF-3", "LHF-4"}) {
             const Series* s = noisy_torus(d, cc, m, q, "L2", "fig17-18");
             if (!s || !lhf2) continue;
             const auto r = error_ratios(*s, *lhf2);
             if (r.empty()) {
               cc.missing(std::string(q) + ": no level in common");
               continue;
             }
             const std::string what =
                 kNoisyTorus + " " + q + " L2 " + s->method + " / " + lhf2->method;
             if (weak) {
               const std::string text =
                   what + " at the finest level " + std::to_string(r.back().level) + " = " +
                   f2(r.back().value) + " (" + e4.text() + "); all " + levels_text(r);
               c.info("weak claim, not in the verdict: " + text +
                      (e4.holds(r.back().value) ? " holds" : " does not hold"));
             } else {
               require_finest(c, r, e4, what);
             }
           }
         }
       },
       {}});

  const Band e5_ratio = Band::within_factor(1.5), e5_rates = Band::at_most(0.3);
  out.push_back(
      {"E5",
       "Bump with noise: normals identical for O(h^3) and O(h^2)",
       "Normals: each method behaves nearly identically for O(h^3) and O(h^2) perturbations.",
       "per method (Xu-2, LHF-2, LOP-2, LSCM-2) and bump mesh, the normal errors (L2 and Linf) of "
       "the two noise orders are " +
           e5_ratio.text() + " at every level, and the rates differ by " + e5_rates.text(),
       {{"ratio", e5_ratio}, {"rate_difference", e5_rates}},
       [=](const Data& d, Check& c) {
         for (const auto& fam : d.bumps())
           for (const auto& m : kDeg2All)
             for (const char* norm : {"L2", "Linf"}) {
               const Series* s3 = bump_noise(d, c, fam, m, "normal", norm, 3);
               const Series* s2 = bump_noise(d, c, fam, m, "normal", norm, 2);
               if (!s3 || !s2) continue;
               const std::string what = fam + " " + s3->method + " normal " + norm;
               require_every_level(c, error_ratios(*s2, *s3), e5_ratio, what + " h^2 / h^3");
               const double diff = std::abs(d.rate(*s2) - d.rate(*s3));
               c.require(e5_rates.holds(diff), what + ": rates h^3 " + f2(d.rate(*s3)) + ", h^2 " +
                                                   f2(d.rate(*s2)) + " differ by " + f2(diff) +
                                                   " (" + e5_rates.text() + ")");
             }
       },
       {}});

  const Band e6 = Band::at_most(1.0), e6_factor = Band::at_least(0.5);
  out.push_back({"E6",
                 "Bump with noise: Xu-2 normals slightly better on the 4-8 mesh",
                 "Xu-2 normals are slightly better than the others on the 4-8 mesh (weak claim).",
                 kBump48 +
                     ", h^3 and h^2: err(Xu-2) <= min(err of LHF-2, LOP-2, LSCM-2) at >= 3 of 4 "
                     "levels (normal L2), by a factor <= " +
                     num(1.0 / e6_factor.lo),
                 {{"ratio", e6}, {"ratio_where_better", e6_factor}},
                 [=](const Data& d, Check& c) {
                   for (int order : {3, 2}) {
                     const Series* xu = bump_noise(d, c, kBump48, "Xu-2", "normal", "L2", order);
                     std::vector<const Series*> others;
                     for (const auto& m : kDeg2Others)
                       if (const Series* s = bump_noise(d, c, kBump48, m, "normal", "L2", order))
                         others.push_back(s);
                     if (!xu || others.size() != kDeg2Others.size()) continue;
                     require_most_levels(
                         c, ratios_to_min(*xu, others), e6,
                         kBump48 + " h^" + std::to_string(order) + " normal L2 " + xu->method +
                             " / min(" + join(methods_of(others), ", ") + ")",
                         e6_factor, " (better by a factor <= " + num(1.0 / e6_factor.lo) + ")");
                   }
                 },
                 {}});

  out.push_back({"E7",
                 "Bump with noise: Xu-2 curvatures fail to converge",
                 "Xu-2 curvatures fail to converge (both perturbation orders).",
                 "the failure criterion, H and K L2, h^3 and h^2, both bump meshes",
                 {},
                 [](const Data& d, Check& c) {
                   for (int order : {3, 2})
                     for (const auto& fam : d.bumps())
                       for (const char* q : {"H", "K"})
                         if (const Series* s = bump_noise(d, c, fam, "Xu-2", q, "L2", order))
                           require_failure(d, c, *s, "h^" + std::to_string(order) + " ");
                 },
                 {}});

  const Band e8 = Band::above(1.0, 1);
  out.push_back({"E8",
                 "Bump with O(h^3) noise: curvatures faster than linear",
                 "Others (LHF-2, LOP-2, LSCM-2), O(h^3) noise: curvatures converge faster than "
                 "linearly.",
                 "H and K L2 rate " + e8.text() + ", both bump meshes",
                 {{"rate", e8}},
                 [=](const Data& d, Check& c) {
                   for (const auto& fam : d.bumps())
                     for (const auto& m : kDeg2Others)
                       for (const char* q : {"H", "K"})
                         if (const Series* s = bump_noise(d, c, fam, m, q, "L2", 3))
                           require_rate(d, c, *s, e8, "h^3 ");
                 },
                 {}});

  const Band e9 = Band::below(1.0, 1);
  out.push_back(
      {"E9",
       "Bump with O(h^2) noise: curvatures generally lower than linear",
       "Others (LHF-2, LOP-2, LSCM-2), O(h^2) noise: curvatures converge \"generally lower than "
       "linear\".",
       "H and K L2 rates both " + e9.text() + " for a majority of the (method, mesh) pairs",
       {{"rate", e9}},
       [=](const Data& d, Check& c) {
         int pairs = 0, below = 0;
         for (const auto& fam : d.bumps())
           for (const auto& m : kDeg2Others) {
             const Series* h = bump_noise(d, c, fam, m, "H", "L2", 2);
             const Series* k = bump_noise(d, c, fam, m, "K", "L2", 2);
             if (!h || !k) continue;
             ++pairs;
             const bool ok = e9.holds(d.rate(*h)) && e9.holds(d.rate(*k));
             below += ok;
             c.info("h^2 " + fam + " " + h->method + ": H L2 rate " + f2(d.rate(*h)) +
                    ", K L2 rate " + f2(d.rate(*k)) +
                    (ok ? " (both " + e9.text() + ")" : " (not both " + e9.text() + ")"));
           }
         if (pairs > 0)
           c.require(2 * below > pairs, "H and K L2 rates " + e9.text() + " for " +
                                            std::to_string(below) + " of " + std::to_string(pairs) +
                                            " (method, mesh) pairs (need a majority)");
       },
       {}});
  return out;
}

}  // namespace curvbench::claims
