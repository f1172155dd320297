// The readings table; see readings.h. Why each choice is adopted: docs/claims.md.
#include "harness/readings/readings.h"

#include <algorithm>

#include "methods/estimator.h"

namespace curvbench {

namespace {

// Keeps the mesh lines `change` changes (it returns true for them); the others' rows stay those
// of the adopted run (the overlay replaces rows by experiment and family, harness/claims/kit.h Data).
template <class Change>
bool keep_changed_meshes(Experiment& e, Change&& change) {
  std::vector<ExperimentMesh> kept;
  for (ExperimentMesh m : e.meshes)
    if (change(m)) kept.push_back(std::move(m));
  e.meshes = std::move(kept);
  return !e.meshes.empty();
}

// The isosurface tori of the experiment files run at levels 2-5 (n = 32..256); the alternative
// shifts each such mesh line down by one level (n = 16..128).
bool shift_iso_levels_down(Experiment& e) {
  return keep_changed_meshes(e, [](ExperimentMesh& m) {
    if (m.family != "torus-iso" && m.family != "torus-iso-projected") return false;
    if (std::find(m.levels.begin(), m.levels.end(), 1) != m.levels.end()) return false;
    for (int& level : m.levels) --level;
    return true;
  });
}

// A choice that reads another mesh family: the experiments run `swap.by` in place of
// `swap.family` (of the paper's sections only, with `paper_only`; the studies beyond the paper
// keep theirs), and the claims read its rows for `swap.family`.
ReadingChoice family_swap(std::string name, std::string description, FamilySubstitute swap,
                          bool paper_only) {
  auto apply = [swap, paper_only](Experiment& e) {
    if (paper_only && e.section == "beyond") return false;
    return keep_changed_meshes(e, [&swap](ExperimentMesh& m) {
      if (m.family != swap.family) return false;
      m.family = swap.by;
      return true;
    });
  };
  return {std::move(name), std::move(description), apply, std::move(swap)};
}

// The safeguarded QR of every fit of the paper's weighted least-squares framework (LHF, LOP,
// LSCM) that keeps the default safeguard (neither its own tolerance nor its own condition test),
// in the experiments of the paper's sections, changed by `set`.
template <class Set>
bool set_safeguard(Experiment& e, Set set) {
  if (e.section == "beyond") return false;
  const EstimatorOptions defaults;
  bool changed = false;
  for (ExperimentMethod& m : e.methods) {
    if (m.is_external() || m.spec == kAllOperators) continue;
    if (m.options.qr_tolerance != defaults.qr_tolerance ||
        m.options.qr_condition != defaults.qr_condition)
      continue;
    if (!make_estimator(m.spec, m.options)->ring_fit()) continue;
    set(m.options);
    changed = true;
  }
  return changed;
}

// The safeguard of the paper's time: the |R_jj| test at 1e-3 alone, no condition test.
bool safeguard_rjj_only(Experiment& e) {
  return set_safeguard(e, [](EstimatorOptions& o) { o.qr_condition = false; });
}

// The tolerance of the group's later codes, 1e-8, for both tests.
constexpr double kLooseQrTolerance = 1e-8;
bool safeguard_1e_8(Experiment& e) {
  return set_safeguard(e, [](EstimatorOptions& o) { o.qr_tolerance = kLooseQrTolerance; });
}

// The noisy-data half ring for degree 2 only, where the experiment fits a higher degree.
bool noisy_rings_quadratic_only(Experiment& e) {
  if (!e.noisy || e.noisy_quadratic_only) return false;
  const bool higher = std::any_of(e.methods.begin(), e.methods.end(), [](const auto& m) {
    return !m.is_external() && m.spec != kAllOperators &&
           make_estimator(m.spec, m.options)->options().degree > 2;
  });
  if (higher) e.noisy_quadratic_only = true;
  return higher;
}

// The experiment's controlled noise (alpha h^k) drawn from `model`; false where it has none, or
// already this model.
std::function<bool(Experiment&)> set_noise_model(NoiseModel model) {
  return [model](Experiment& e) {
    if (std::none_of(e.meshes.begin(), e.meshes.end(),
                     [&](const ExperimentMesh& m) { return e.noise_order_of(m) > 0; }))
      return false;
    const auto same = [&](const NoiseModel& x) { return !(x < model) && !(model < x); };
    if (same(e.noise_model)) return false;
    e.noise_model = model;
    return true;
  };
}

// The h of the controlled noise alpha h^k as the paper's Table 4 prints its "average edge
// length", half the mean edge length (claim A4): alpha (h/2)^k = (alpha / 2^k) h^k, so each
// controlled-noise mesh of order k >= 2 along the normal (the paper's) keeps its distribution and
// gets alpha's scale divided by 2^k, in the experiments of the paper's sections.
bool noise_h_half_mean_edge(Experiment& e) {
  if (e.section == "beyond") return false;
  return keep_changed_meshes(e, [&e](ExperimentMesh& m) {
    const int k = e.noise_order_of(m);
    const NoiseModel model = e.noise_model_of(m);
    if (k < 2 || model.direction != NoiseDirection::normal || model.is_outliers()) return false;
    m.has_noise_model = true;
    m.noise_model = model;
    m.noise_model.scale = model.scale / static_cast<double>(1 << k);
    return true;
  });
}

bool unchanged(Experiment&) {
  return false;
}

}  // namespace

const std::vector<Reading>& readings() {
  static const std::vector<Reading> table = {
      {"iso-levels",
       "Which isosurface meshes",
       "§5.1 uses \"four\" isosurface meshes and §5.3 the same ones; Table 4 lists five, from "
       "16^3 to 256^3 volume cells",
       {{"32-256", "levels 2-5 (n = 32..256: 1760 to 122464 vertices)", unchanged, {}},
        {"16-128", "levels 1-4 (n = 16..128: 320 to 31136 vertices)", shift_iso_levels_down, {}}}},
      {"noisy-rings",
       "Rings of the noisy-data fits",
       "§5.3: the neighbourhood grows by half a ring for LHF, LOP and LSCM, stated before the "
       "degree-2 figures; the cubic and quartic fits follow \"for completeness\"",
       {{"all", "half a ring more for the fits of every degree", unchanged, {}},
        {"quadratic",
         "half a ring more for degree 2 only; degrees 3, 4 keep their own rings",
         noisy_rings_quadratic_only,
         {}}}},
      {"noise-alpha",
       "The distribution of the controlled noise",
       "§5.3: alpha is \"a random number between 0 and 0.1 with Gaussian distribution\"",
       {{"gaussian-0.033",
         "alpha = (0.1/3) N(0,1): |alpha| < 0.1 at three standard deviations",
         unchanged,
         {}},
        {"gaussian-0.1",
         "alpha = 0.1 N(0,1): 0.1 as the standard deviation (32% of |alpha| above 0.1)",
         set_noise_model({NoiseDistribution::gaussian, 0.1}),
         {}},
        {"uniform-0.1",
         "alpha = 0.1 U[0,1): one-signed, in [0, 0.1)",
         set_noise_model({NoiseDistribution::uniform, 0.1}),
         {}}}},
      {"noise-h",
       "The h of the controlled noise",
       "§5.3: the noise is alpha h^k with \"h the average edge length\"; Table 4's column of "
       "that name prints half the mean edge length (claim A4)",
       {{"mean-edge", "h = the mean edge length of the mesh", unchanged, {}},
        {"half-mean-edge",
         "h = half the mean edge length, as Table 4's \"average edge length\": alpha's scale "
         "divided by 2^k (by 8 at O(h^3), 4 at O(h^2))",
         noise_h_half_mean_edge,
         {}}}},
      {"well-shaped-torus",
       "The vertex valences of the well-shaped torus",
       "§5.1: four \"well shaped\" meshes from the commercial generator GAMBIT, \"such as those "
       "obtained from CAD software for finite element analysis\"; their valences are not given",
       {{"delaunay",
         "torus-unstructured: CGAL's Delaunay refinement as it comes (1.6% valence 4)",
         unchanged,
         {}},
        family_swap("min-valence-5",
                    "torus-unstructured-minval5: the same meshes with every valence-4 vertex "
                    "removed by edge flips",
                    {"torus-unstructured", "torus-unstructured-minval5"}, false)}},
      {"safeguard",
       "The safeguard of the QR",
       "§4.3.2: columns are removed from the right while the Vandermonde matrix has \"a large "
       "condition number\", and the kept fit is \"well-conditioned\"; neither the test nor its "
       "threshold is given",
       {{"condition-1e-3",
         "the |R_jj| test and the condition test ||R^-1||_F <= 1/tol, tol = 1e-3 (the kept "
         "columns' smallest singular value >= 1e-3 of the column scale)",
         unchanged,
         {}},
        {"rjj-only",
         "the |R_jj| test alone, tol = 1e-3 (qr-condition=no): the safeguard of the paper's "
         "time, for every LHF, LOP and LSCM fit",
         safeguard_rjj_only,
         {}},
        {"1e-8",
         "both tests with tol = 1e-8 (qr-tol=1e-8), the group's later codes' tolerance, for "
         "every LHF, LOP and LSCM fit",
         safeguard_1e_8,
         {}}}},
      {"irregular-bump",
       "The generator of the irregular bump mesh",
       "§5.2: two bump meshes, \"irregular\" and 4-8, \"both well-shaped\" with \"variations of "
       "vertex valences\"; the irregular one is shown in a figure, its generator is not named",
       {{"jittered-grid",
         "bump-irregular: the 4-8 mesh's grid points jittered by up to h/4, Delaunay-triangulated",
         unchanged,
         {}},
        family_swap("delaunay-refined",
                    "bump-unstructured: CGAL's Delaunay refinement of the square (angle 30 deg), "
                    "as the well-shaped torus",
                    {"bump-irregular", "bump-unstructured"}, true)}},
  };
  return table;
}

std::vector<Experiment> apply_reading(const std::vector<Experiment>& experiments,
                                      const ReadingChoice& choice) {
  std::vector<Experiment> out;
  for (Experiment e : experiments)
    if (e.sweep.empty() && choice.apply(e)) out.push_back(std::move(e));  // not the sweeps
  return out;
}

std::string reading_folder(const std::string& output, const Reading& reading,
                           const ReadingChoice& choice) {
  return output + "/readings/" + reading.id + "=" + choice.name;
}

}  // namespace curvbench
