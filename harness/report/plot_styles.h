// The look of each method in every plot (colour, marker, dash), so that a method looks the same
// in every plot of every study. The looks are dealt out by registry position (a new registry
// line gets the next one), so no method is named here:
//
//   fits (LHF-d, LOP-d, Xu-d, LSCM-d, ...): one colour per method, one filled marker per degree
//        d, solid lines (the 5th and 6th fits, LSCM-fast and LSCM-CG, dashed and dotted)
//   degree-free methods (Meyer, Taubin, ..., APSS): a colour, an open marker and a broken line
//   any other label (an outside estimator, a labelled variant such as "LHF-2 (1.5-ring)"):
//        a fallback style from a hash of the label into a spare palette no method's look uses
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
