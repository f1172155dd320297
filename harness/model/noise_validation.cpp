#include "harness/model/noise_validation.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "core/errors.h"
#include "harness/model/noise_estimate.h"
#include "harness/model/shortest_double.h"
#include "meshgen/generate.h"
#include "meshgen/noise.h"

namespace curvbench {

namespace {

std::string shortest(double x) {
  if (!std::isfinite(x)) return "";
  char buf[kShortestRoom];
  return std::string(buf, write_shortest(buf, x));
}

}  // namespace

std::vector<NoiseCheckRow> noise_check(const NoiseCheckSpec& spec) {
  std::vector<std::string> families = spec.families;
  if (families.empty())
    for (const MeshFamilyInfo& f : mesh_family_table())
      if (!f.point_set) families.push_back(f.name);  // the estimate reads a mesh's faces
  std::vector<NoiseCheckRow> rows;
  for (const std::string& family : families) {
    if (mesh_family(family).point_set)
      throw UsageError("noise-check: " + family +
                       " is a point-cloud family; the noise estimate reads a mesh's faces");
    for (int level : spec.levels) {
      if (level > max_mesh_level(family)) continue;
      MeshSpec ms;
      ms.family = family;
      ms.level = level;
      ms.seed = spec.seed;
      const GeneratedMesh clean = generate_mesh(ms);
      double floor = std::numeric_limits<double>::quiet_NaN();
      for (double sigma : spec.sigmas) {
        NoiseCheckRow r;
        r.family = family;
        r.level = level;
        r.vertices = clean.mesh.num_vertices();
        r.h = clean.mesh.mean_edge_length();
        r.true_sigma = sigma;
        NoiseModel model;
        model.scale = sigma;
        try {
          const NoiseEstimate e =
              estimate_noise(sigma == 0 ? clean.mesh : add_noise(clean, 1, spec.seed, model).mesh);
          r.estimated = e.sigma_over_h;
          r.vertices_used = e.vertices_used;
          r.crease_vertices = e.crease_vertices;
        } catch (const InputError&) {
          r.estimated = std::numeric_limits<double>::quiet_NaN();
        }
        if (sigma == 0) floor = r.estimated;
        r.floor = floor;
        r.expected = std::hypot(sigma, floor);
        const double rel = level >= 2 ? kNoiseEstimateRelTol : kNoiseEstimateCoarseRelTol;
        r.within = std::fabs(r.estimated - r.expected) <= rel * r.expected + kNoiseEstimateAbsTol;
        rows.push_back(r);
      }
    }
  }
  return rows;
}

std::string noise_check_csv(const std::vector<NoiseCheckRow>& rows) {
  std::string s =
      "family,level,vertices,h,true_sigma_over_h,estimated_sigma_over_h,ratio,floor,expected,"
      "vertices_used,crease_vertices,within\n";
  for (const NoiseCheckRow& r : rows)
    s += r.family + "," + std::to_string(r.level) + "," + std::to_string(r.vertices) + "," +
         shortest(r.h) + "," + shortest(r.true_sigma) + "," + shortest(r.estimated) + "," +
         (r.true_sigma > 0 ? shortest(r.estimated / r.true_sigma) : "") + "," + shortest(r.floor) +
         "," + shortest(r.expected) + "," + std::to_string(r.vertices_used) + "," +
         std::to_string(r.crease_vertices) + "," + (r.within ? "yes" : "out") + "\n";
  return s;
}

std::string noise_check_markdown(const std::vector<NoiseCheckRow>& rows) {
  std::vector<double> sigmas;
  for (const NoiseCheckRow& r : rows) {
    bool seen = false;
    for (double s : sigmas) seen = seen || s == r.true_sigma;
    if (!seen) sigmas.push_back(r.true_sigma);
  }
  std::string s = "| family | level | vertices |";
  std::string rule = "|---|---:|---:|";
  for (double sigma : sigmas) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " est. at %g h |", sigma);
    s += buf;
    rule += "---:|";
  }
  s += " worst deviation from hypot(sigma, floor) | within |\n" + rule + "---:|---|\n";
  for (size_t i = 0; i < rows.size();) {
    const NoiseCheckRow& first = rows[i];
    char buf[64];
    std::snprintf(buf, sizeof buf, "| %d | %d |", first.level, first.vertices);
    std::string line = "| `" + first.family + "` " + buf;
    double worst = 0.0;  // signed, the largest in magnitude
    bool within = true;
    for (; i < rows.size() && rows[i].family == first.family && rows[i].level == first.level; ++i) {
      const NoiseCheckRow& r = rows[i];
      std::snprintf(buf, sizeof buf, " %.2g |", r.estimated);
      line += std::isnan(r.estimated) ? std::string(" none |") : std::string(buf);
      const double deviation = r.expected > 0 ? r.estimated / r.expected - 1 : 0.0;
      if (std::fabs(deviation) > std::fabs(worst)) worst = deviation;
      within = within && r.within;
    }
    std::snprintf(buf, sizeof buf, " %+.0f%% | %s |\n", 100 * worst, within ? "yes" : "**no**");
    s += line + buf;
  }
  return s;
}

}  // namespace curvbench
