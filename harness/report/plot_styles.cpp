#include "harness/report/plot_styles.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string_view>

#include "core/hash.h"

namespace curvbench {

namespace {

// gnuplot point types: 4/5 square, 6/7 circle, 8/9 triangle up, 10/11 triangle down,
// 12/13 diamond, 14/15 pentagon (open/filled); 1 +, 2 x, 3 *.
// A fit's marker by degree 1..6 (filled shapes).
constexpr int kDegreeMarker[] = {0, 11, 7, 5, 9, 13, 15};

struct Entry {
  const char* label;  ///< a fit's display name (label without "-d"), or a whole label
  bool fit;           ///< the marker follows the degree
  const char* colour;
  int marker;  ///< for a non-fit
  int dash;
};

// clang-format off
constexpr Entry kTable[] = {
    // fits: one colour each, the degree by marker
    {"LHF",          true,  "#0072b2", 0,  1},
    {"LOP",          true,  "#e69f00", 0,  1},
    {"Xu",           true,  "#009e73", 0,  1},
    {"LSCM",         true,  "#cc79a7", 0,  1},
    {"LSCM-fast",    true,  "#d55e00", 0,  2},
    {"LSCM-CG",      true,  "#56b4e9", 0,  3},
    {"Jet",          true,  "#000000", 0,  1},
    // discrete operators and known outside estimators: open markers, broken lines
    {"Meyer",        false, "#8b0000", 6,  2},
    {"Taubin",       false, "#6a3d9a", 4,  4},
    {"Rusinkiewicz", false, "#b8860b", 8,  2},
    {"Quadric",      false, "#8c564b", 10, 4},
    {"Goldfeather",  false, "#e7298a", 12, 2},
    {"Normal-cycle", false, "#555555", 14, 4},
    {"ICC",          false, "#66a61e", 3,  5},
    {"ICC (LHF-3 normals)", false, "#66a61e", 12, 1}, {"Normal-cycle (LHF-3 normals)", false, "#555555", 6, 1},
    {"vtk-curvatures", false, "#17becf", 2, 5},
    {"APSS",         false, "#7570b3", 5,  3},
    {"SurfVar",      false, "#a6761d", 7,  3},
    {"pcl",          false, "#e6ab02", 9,  4},
};
// The spare palette of the fallback styles: colours no entry above uses.
constexpr const char* kSpareColours[] = {"#d62728", "#9467bd", "#bcbd22", "#1a5276",
                                         "#ff69b4", "#2ca02c", "#5d6d7e", "#a0522d"};
constexpr int kSpareMarkers[] = {1, 2, 3, 4, 6, 8, 10, 12};
constexpr int kSpareDashes[] = {1, 2, 4};
// clang-format on

constexpr size_t kSpareSlots =
    std::size(kSpareColours) * std::size(kSpareMarkers) * std::size(kSpareDashes);

PlotStyle spare_style(size_t slot) {
  slot %= kSpareSlots;
  PlotStyle s;
  s.colour = kSpareColours[slot % std::size(kSpareColours)];
  slot /= std::size(kSpareColours);
  s.marker = kSpareMarkers[slot % std::size(kSpareMarkers)];
  s.dash = kSpareDashes[slot / std::size(kSpareMarkers)];
  s.fallback = true;
  return s;
}

size_t spare_slot(const std::string& label) {
  return static_cast<size_t>(fnv1a64(label) % kSpareSlots);
}

}  // namespace

PlotStyle plot_style(const std::string& label) {
  for (const Entry& e : kTable)
    if (!e.fit && label == e.label) return {e.colour, e.marker, e.dash, false};
  // A fit's label: "<name>-<degree>".
  const size_t dash = label.rfind('-');
  if (dash != std::string::npos && dash + 2 == label.size() &&
      std::isdigit(static_cast<unsigned char>(label.back()))) {
    const int degree = label.back() - '0';
    const std::string_view name = std::string_view(label).substr(0, dash);
    if (degree >= 1 && degree < static_cast<int>(std::size(kDegreeMarker)))
      for (const Entry& e : kTable)
        if (e.fit && name == e.label) return {e.colour, kDegreeMarker[degree], e.dash, false};
  }
  return spare_style(spare_slot(label));
}

std::vector<PlotStyle> plot_styles(const std::vector<std::string>& labels) {
  std::vector<PlotStyle> out;
  for (const std::string& label : labels) out.push_back(plot_style(label));
  // A fallback look already taken in this plot moves on to the next free spare slot.
  for (size_t i = 0; i < out.size(); ++i) {
    if (!out[i].fallback) continue;
    const auto taken = [&](const PlotStyle& s) {
      for (size_t j = 0; j < i; ++j)
        if (out[j].same_look(s)) return true;
      return false;
    };
    size_t slot = spare_slot(labels[i]);
    for (size_t tries = 0; tries < kSpareSlots && taken(out[i]); ++tries)
      out[i] = spare_style(++slot);
  }
  return out;
}

std::string gnuplot_style(const PlotStyle& s) {
  return "lc rgb '" + s.colour + "' pt " + std::to_string(s.marker) + " dt " +
         std::to_string(s.dash);
}

}  // namespace curvbench
