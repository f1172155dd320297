// The look of each method in every plot (colour, marker, dash), from one table keyed by the
// method's label, so that a method looks the same in every plot of every study.
//
//   fits (LHF-d, LOP-d, Xu-d, LSCM-d, LSCM-fast-d, LSCM-CG-d, Jet-d): one colour per method,
//        one filled marker per degree d, solid lines (LSCM-fast dashed, LSCM-CG dotted)
//   discrete operators (Meyer, Taubin, ...) and known outside estimators (vtk-curvatures):
//        a colour, an open marker and a dashed line each
//   any other label (an outside estimator, a labelled variant such as "LHF-2 (1.5-ring)"):
//        a fallback style from a hash of the label into a spare palette used by no table entry
#pragma once

#include <string>
#include <vector>

namespace curvbench {

struct PlotStyle {
  std::string colour;     ///< "#rrggbb"
  int marker = 7;         ///< gnuplot point type
  int dash = 1;           ///< gnuplot dash type (1 = solid)
  bool fallback = false;  ///< the label is not in the table (hashed style)

  bool same_look(const PlotStyle& o) const {
    return colour == o.colour && marker == o.marker && dash == o.dash;
  }
};

/// The style of a method label; deterministic, never throws.
PlotStyle plot_style(const std::string& label);

/// The styles of the series of one plot, in order: the table's for known labels, and for the
/// others their hashed style moved on (deterministically) past any look already used in the plot.
std::vector<PlotStyle> plot_styles(const std::vector<std::string>& labels);

/// "lc rgb '#rrggbb' pt N dt N" for a gnuplot plot element.
std::string gnuplot_style(const PlotStyle& s);

}  // namespace curvbench
