#include "harness/report/plot_styles.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <mutex>
#include <string_view>

#include "core/hash.h"
#include "methods/estimator.h"

namespace curvbench {

namespace {

// gnuplot point types: 4/5 square, 6/7 circle, 8/9 triangle up, 10/11 triangle down,
// 12/13 diamond, 14/15 pentagon (open/filled); 1 +, 2 x, 3 *.
// A fit's marker by degree 1..6 (filled shapes).
constexpr int kDegreeMarker[] = {0, 11, 7, 5, 9, 13, 15};

struct Look {
  const char* colour;
  int marker;  ///< an operator's (a fit's marker is its degree's)
  int dash;
};

// clang-format off
// The looks of the registered methods, dealt out in registry order: the k-th fit (a method with
// degrees) takes the k-th fit look, the k-th degree-free method the k-th operator look. Fits:
// one colour each (Okabe-Ito first), the degree in the marker, mostly solid lines. Operators: a
// colour, an open marker and a broken line each. Each list has room for methods to come.
constexpr Look kFitLooks[] = {
    {"#0072b2", 0, 1}, {"#e69f00", 0, 1}, {"#009e73", 0, 1}, {"#cc79a7", 0, 1},
    {"#d55e00", 0, 2}, {"#56b4e9", 0, 3}, {"#000000", 0, 1}, {"#f0e442", 0, 4},
    {"#0072b2", 0, 5}, {"#e69f00", 0, 5}, {"#009e73", 0, 5}, {"#cc79a7", 0, 5},
};
constexpr Look kOperatorLooks[] = {
    {"#8b0000", 6, 2},  {"#6a3d9a", 4, 4}, {"#b8860b", 8, 2}, {"#8c564b", 10, 4},
    {"#e7298a", 12, 2}, {"#555555", 14, 4}, {"#66a61e", 3, 5}, {"#7570b3", 5, 3},
    {"#a6761d", 7, 3},  {"#17becf", 2, 5}, {"#e6ab02", 9, 4}, {"#1b9e77", 13, 3},
    {"#d95f02", 15, 2}, {"#666666", 1, 5},
};
// The spare palette of the fallback styles (labels that are no registered method: outside
// estimators, labelled variants): colours no look above uses.
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

// A registered method as its labels spell it: the display name ("LSCM-fast", "Meyer") and
// whether it is a fit ("<name>-<degree>"), with its look.
struct Styled {
  std::string display;
  bool fit = false;
  Look look{};
};

// The registry's methods with their looks, in registry order; rebuilt when the registry grows
// (register_estimator). A method past the end of its list gets none (fallback).
std::vector<Styled> styled_methods() {
  static std::mutex mutex;
  static std::vector<Styled> cache;
  static size_t registered = 0;
  const std::lock_guard<std::mutex> lock(mutex);
  const std::vector<MethodInfo> table = method_table();
  if (table.size() != registered) {
    cache.clear();
    size_t fits = 0, operators = 0;
    for (const MethodInfo& m : table) {
      Styled s;
      s.display = display_name(m);
      s.fit = m.is_fit();
      size_t& k = s.fit ? fits : operators;
      const size_t n = s.fit ? std::size(kFitLooks) : std::size(kOperatorLooks);
      if (k < n) {
        s.look = s.fit ? kFitLooks[k] : kOperatorLooks[k];
        cache.push_back(s);
      }
      ++k;
    }
    registered = table.size();
  }
  return cache;
}

}  // namespace

PlotStyle plot_style(const std::string& label) {
  const std::vector<Styled> methods = styled_methods();
  for (const Styled& m : methods)
    if (!m.fit && label == m.display) return {m.look.colour, m.look.marker, m.look.dash, false};
  // A fit's label: "<name>-<degree>".
  const size_t dash = label.rfind('-');
  if (dash != std::string::npos && dash + 2 == label.size() &&
      std::isdigit(static_cast<unsigned char>(label.back()))) {
    const int degree = label.back() - '0';
    const std::string_view name = std::string_view(label).substr(0, dash);
    if (degree >= 1 && degree < static_cast<int>(std::size(kDegreeMarker)))
      for (const Styled& m : methods)
        if (m.fit && name == m.display)
          return {m.look.colour, kDegreeMarker[degree], m.look.dash, false};
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
