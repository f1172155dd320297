// The plot styles (plot_styles.h): every registered method at every degree it supports has a look
// dealt out by its registry position; no two of them look alike; lookup is deterministic; other
// labels (outside estimators, variants) get a fallback look of their own, distinct within a plot.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "harness/report/plot_styles.h"
#include "methods/estimator.h"

namespace curvbench {
namespace {

// The registry's own methods, taken at start-up: before any test registers one of its own
// (test_extending.cpp's toy estimator, which has no style).
const std::vector<MethodInfo> kBuiltIn = method_table();

// The label of every registered method at every degree it supports (operators once).
std::vector<std::string> registered_labels() {
  std::vector<std::string> labels;
  for (const MethodInfo& m : kBuiltIn) {
    if (!m.is_fit()) {
      labels.push_back(make_estimator(m.name, {})->label());
      continue;
    }
    for (int d = m.min_degree; d <= m.max_degree; ++d) {
      EstimatorOptions o;
      o.degree = d;
      labels.push_back(make_estimator(m.name, o)->label());
    }
  }
  return labels;
}

TEST(PlotStyles, EveryRegisteredMethodAtEveryDegreeHasItsOwnLook) {
  const auto labels = registered_labels();
  ASSERT_GE(labels.size(), 30u);
  std::map<std::string, std::string> seen;  // look -> label
  for (const std::string& label : labels) {
    const PlotStyle s = plot_style(label);
    EXPECT_FALSE(s.fallback) << label << " has no look of its own";
    const auto [it, fresh] = seen.emplace(
        s.colour + " " + std::to_string(s.marker) + " " + std::to_string(s.dash), label);
    EXPECT_TRUE(fresh) << label << " looks like " << it->second;
    EXPECT_EQ(s.colour.size(), 7u) << label;
    EXPECT_EQ(s.colour.front(), '#') << label;
  }
  for (const MethodInfo& m : kBuiltIn)
    for (int d : m.bench_degrees) {
      EstimatorOptions o;
      o.degree = d;
      EXPECT_FALSE(plot_style(make_estimator(m.name, o)->label()).fallback) << m.name << " " << d;
    }
  // A fit's degrees share its colour; the degree is in the marker.
  EXPECT_EQ(plot_style("LHF-2").colour, plot_style("LHF-4").colour);
  EXPECT_NE(plot_style("LHF-2").marker, plot_style("LHF-4").marker);
  // The pairs that used to look alike.
  for (const auto& [a, b] : std::vector<std::pair<std::string, std::string>>{
           {"LHF-2", "Taubin"}, {"LOP-2", "Goldfeather"}, {"LHF-4", "Quadric"}})
    EXPECT_FALSE(plot_style(a).same_look(plot_style(b))) << a << " " << b;
}

TEST(PlotStyles, LookupIsDeterministicAndUnknownLabelsFallBack) {
  for (const std::string& label : registered_labels()) {
    const PlotStyle a = plot_style(label), b = plot_style(label);
    EXPECT_TRUE(a.same_look(b)) << label;
  }
  // The same label looks the same in every plot, whatever else is plotted.
  EXPECT_TRUE(plot_styles({"Meyer", "LHF-2"})[1].same_look(plot_styles({"LHF-2"})[0]));

  const std::vector<std::string> unknown = {
      "LHF-2 (rings 2.5)",  "my-estimator", "",         "LHF-9",    "LHF-",           "Meyer-2",
      "LHF-2 r1.5",         "LHF-2 r2",     "LHF-2 r3", "LHF-2 r4", "vtk-curvatures", "lhf-2",
      "ICC (LHF-3 normals)"};
  for (const std::string& label : unknown) {
    const PlotStyle s = plot_style(label);
    EXPECT_TRUE(s.fallback) << label;
    EXPECT_TRUE(s.same_look(plot_style(label))) << label;
    // Never the look of a table entry.
    for (const std::string& known : registered_labels())
      EXPECT_FALSE(s.same_look(plot_style(known))) << label << " " << known;
  }
  // Within one plot every series has its own look, also when labels hash alike.
  std::vector<std::string> plot = registered_labels();
  plot.insert(plot.end(), unknown.begin(), unknown.end());
  for (int i = 0; i < 300; ++i) plot.push_back("external-" + std::to_string(i));
  const auto styles = plot_styles(plot);
  ASSERT_EQ(styles.size(), plot.size());
  size_t distinct = 0;
  for (size_t i = 0; i < styles.size(); ++i) {
    bool unique = true;
    for (size_t j = 0; j < i; ++j) unique = unique && !styles[i].same_look(styles[j]);
    distinct += unique;
  }
  // 300 more labels than the spare palette's 192 looks: the palette is used up, no crash.
  EXPECT_GE(distinct, registered_labels().size() + 192);
  // With room to spare, every look in the plot differs.
  const auto few = plot_styles(unknown);
  for (size_t i = 0; i < few.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      EXPECT_FALSE(few[i].same_look(few[j])) << unknown[i] << " " << unknown[j];
  EXPECT_EQ(gnuplot_style(plot_style("LHF-2")), "lc rgb '#0072b2' pt 7 dt 1");
}

}  // namespace
}  // namespace curvbench
