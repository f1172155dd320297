// The paper's own numbers (Wang, Jiao et al., CAGD 2009), one home for every user: the claims
// registry (harness/claims_*.cpp), REPORT.md (harness/report/report.cpp), `curvbench mesh
// --table4`, the report's Table 5 (harness/report/table5.cpp) and the tests. docs/claims.md
// explains each table.
//
//   kTable2  §3.2 Table 2: per degree d = 1..6 the number of coefficients and the number of points
//            (centre included) of the (d+1)/2-ring of an interior vertex of a valence-6 mesh
//   kTable4  §5.3 Table 4: the marching-cubes torus meshes on n^3 samples, as printed: vertices,
//            the "average edge length" column (half the true mean edge length, claim A4), the
//            L2 and Linf vertex distances to the torus, and the printed level-to-level rates
//   kTable5  §5.4 Table 5: seconds per whole-mesh pass on the unstructured well-shaped torus
//            meshes (GAMBIT; 3 GHz Pentium 4, gcc 4.2.4) for the eight methods of kTable5Methods;
//            kTable5Ratios the ratios §5.4 discusses, kTable5Reference the method they divide by
#pragma once

#include <array>
#include <cmath>
#include <string_view>

namespace curvbench::paper {

struct Table2Row {
  int degree;
  int coefficients;
  int points_with_centre;
};
inline constexpr std::array<Table2Row, 6> kTable2 = {
    {{1, 3, 7}, {2, 6, 13}, {3, 10, 19}, {4, 15, 31}, {5, 21, 37}, {6, 28, 55}}};

struct Table4Row {
  int grid_points;  ///< n samples per axis on [-1.5, 1.5]
  int vertices;
  double edge_column;         ///< the paper's "average edge length" (= half the mean edge length)
  double l2, linf;            ///< vertex distance to the torus, RMS and max
  double rate_l2, rate_linf;  ///< log2 of the ratio to the previous row (NaN on the first)
};
inline constexpr std::array<Table4Row, 5> kTable4 = {{
    {16, 320, 0.11, 3.60e-3, 9.30e-3, NAN, NAN},
    {32, 1760, 0.048, 1.12e-3, 3.47e-3, 1.69, 1.42},
    {64, 7320, 0.023, 2.59e-4, 9.03e-4, 2.11, 1.94},
    {128, 31136, 0.011, 6.71e-5, 2.25e-4, 1.95, 2.00},
    {256, 122464, 0.0057, 1.65e-5, 5.70e-5, 2.03, 1.98},
}};

/// The methods of Table 5, in the paper's column order.
inline constexpr std::array<std::string_view, 8> kTable5Methods = {
    "Xu-2", "LOP-2", "LHF-2", "LHF-3", "LHF-4", "LSCM-2", "LSCM-3", "LSCM-4"};

struct Table5Row {
  int vertices;
  int triangles;
  std::array<double, 8> seconds;  ///< in the order of kTable5Methods
};
/// Rows are the mesh levels 1-4 of the well-shaped torus.
inline constexpr std::array<Table5Row, 4> kTable5 = {{
    {1338, 2676, {0.035, 0.011, 0.0061, 0.013, 0.028, 0.20, 0.36, 0.66}},
    {5246, 10492, {0.12, 0.039, 0.023, 0.050, 0.11, 0.81, 1.43, 2.65}},
    {21156, 42312, {0.51, 0.16, 0.096, 0.20, 0.44, 3.32, 5.74, 10.58}},
    {85208, 170416, {2.06, 0.65, 0.38, 0.83, 1.81, 13.66, 23.21, 43.16}},
}};

/// Seconds of Table 5 for a method label and level 1-4; 0 if the paper has no such entry.
/// The method §5.4 measures the others against (the fastest of Table 5): its label at a degree
/// is "LHF-<d>"; the report's ratios and scaling table use it.
inline constexpr std::string_view kTable5Reference = "LHF";

/// What §5.4 says of the jet's time, which Table 5 does not list.
inline constexpr std::string_view kTable5JetNote =
    "The paper gives Jet-2/LHF-2 only as \"more than 16x\" (about 28k triangles/s for "
    "Jet_fitting_3).";

/// The time ratios §5.4's text draws from Table 5 (numerator, denominator), in its order.
struct Table5Ratio {
  std::string_view a, b;
};
inline constexpr std::array<Table5Ratio, 9> kTable5Ratios = {{{"LOP-2", "LHF-2"},
                                                              {"LHF-3", "LHF-2"},
                                                              {"LHF-4", "LHF-3"},
                                                              {"Xu-2", "LHF-2"},
                                                              {"Xu-2", "LOP-2"},
                                                              {"LSCM-2", "LHF-2"},
                                                              {"LSCM-3", "LHF-3"},
                                                              {"LSCM-4", "LHF-4"},
                                                              {"LSCM-2", "Xu-2"}}};

constexpr double table5_seconds(std::string_view method, int level) {
  if (level < 1 || level > static_cast<int>(kTable5.size())) return 0.0;
  for (size_t j = 0; j < kTable5Methods.size(); ++j)
    if (kTable5Methods[j] == method) return kTable5[level - 1].seconds[j];
  return 0.0;
}

}  // namespace curvbench::paper
