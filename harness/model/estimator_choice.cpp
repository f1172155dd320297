#include "harness/model/estimator_choice.h"

#include <algorithm>

#include "core/errors.h"
#include "core/text.h"
#include "harness/model/results_table.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"

namespace curvbench {

std::vector<std::string> EstimatorChoice::flags() const {
  std::vector<std::string> f{"--method", method};
  if (!parameter.empty()) {
    f.push_back("--" + parameter);
    f.push_back(format_g(radius));
  }
  return f;
}

std::string EstimatorChoice::text() const {
  const std::string name = split_radius_label(label).method;
  if (parameter.empty()) return name + " at its own neighbourhood (no radius option)";
  if (parameter == "rings") return name + ", rings " + format_g(radius);
  return name + ", ball factor C = " + format_g(radius) + " (a ball of radius C h)";
}

EstimatorChoice estimator_choice(const std::string& label) {
  const RadiusLabel l = split_radius_label(label);
  EstimatorChoice c;
  c.label = label;
  c.method = ascii_lower(l.method);
  c.parameter = l.parameter;
  c.radius = l.radius;
  if (c.method.empty() || c.method.find(' ') != std::string::npos)
    throw UsageError("'" + label + "' is not a method label with an optional radius");
  if (!c.parameter.empty()) set_option(c.options, c.parameter, format_double(c.radius));
  (void)make_estimator(c.method, c.options);  // throws UsageError for what it cannot make
  return c;
}

std::vector<EstimatorChoice> distinct_estimator_choices(const std::vector<std::string>& labels) {
  std::vector<EstimatorChoice> out;
  for (const std::string& l : labels)
    if (std::none_of(out.begin(), out.end(),
                     [&](const EstimatorChoice& c) { return c.label == l; }))
      out.push_back(estimator_choice(l));
  return out;
}

}  // namespace curvbench
