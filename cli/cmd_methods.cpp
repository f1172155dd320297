// `curvbench methods [--labels LO-HI | --point-sets] [--options [--markdown flags|spellings]]`:
// the registered
// estimators (name, degrees, the option that sizes the neighbourhood, one line each) and the
// estimator options, both from their tables (methods/registry.cpp,
// include/curvbench/estimator_options.h). --labels prints one label a line, each fit at each of its
// degrees in LO..HI and each degree-free operator once, and --point-sets the names of the methods
// that work on a point set, one a line, for scripts (tools/realmeshes.sh).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "core/errors.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"

namespace curvbench::cli {

namespace {

struct MethodsOptions {
  std::string labels;  // "LO-HI"
  bool point_sets = false;
  bool options = false;
  std::string markdown;  // "", "flags" or "spellings": the options as docs/cli.md's or
                         // docs/methods.md's table
};

int run_methods(const MethodsOptions& o) {
  if (!o.labels.empty()) {
    const auto dash = o.labels.find('-');
    int lo = 0, hi = 0;
    if (dash == std::string::npos || std::sscanf(o.labels.c_str(), "%d-%d", &lo, &hi) != 2 ||
        lo < 1 || hi < lo)
      throw UsageError("--labels " + o.labels + ": expected LO-HI, e.g. 2-4");
    for (const std::string& label : method_labels(lo, hi)) std::printf("%s\n", label.c_str());
    return 0;
  }
  if (o.point_sets) {
    const std::string names = point_set_methods();  // "lhf, lop, ..."
    std::size_t start = 0;
    while (start < names.size()) {
      const std::size_t end = std::min(names.find(", ", start), names.size());
      std::printf("%s\n", names.substr(start, end - start).c_str());
      start = end + 2;
    }
    return 0;
  }
  if (!o.markdown.empty()) {
    std::fputs(option_table_markdown(o.markdown == "flags" ? OptionTableStyle::flags
                                                           : OptionTableStyle::spellings)
                   .c_str(),
               stdout);
    return 0;
  }
  if (o.options) {
    for (const OptionInfo& option : estimator_option_schema())
      std::printf("%-16s %-9s default %-8s %s\n", option.name.c_str(), option.scope_name.c_str(),
                  option.default_text.c_str(), option.help.c_str());
    return 0;
  }
  // name, degrees, the option that sizes its neighbourhood (its registry line's
  // NeighbourhoodSize: rings, ball-factor; "-" for a fixed 1-ring), summary
  std::printf("%-17s %-7s %-11s %s\n", "method", "degrees", "size", "what it is");
  for (const MethodInfo& m : method_table()) {
    const std::string degrees =
        m.is_fit() ? std::to_string(m.min_degree) + ".." + std::to_string(m.max_degree) : "-";
    const std::string size = *radius_option(m.radius) ? radius_option(m.radius) : "-";
    std::printf("%-17s %-7s %-11s %s\n", m.name.c_str(), degrees.c_str(), size.c_str(),
                m.summary.c_str());
  }
  return 0;
}

}  // namespace

Command add_methods_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "methods", "List the estimators (name, degrees, what each does) or their options");
  auto o = std::make_shared<MethodsOptions>();
  sub->add_option("--labels", o->labels,
                  "Print one label a line: every fit at each of its degrees in LO-HI (e.g. 2-4), "
                  "every degree-free operator once");
  sub->add_flag("--point-sets", o->point_sets,
                "Print the names of the methods that work on a point set (no faces), one a line");
  sub->add_flag("--options", o->options,
                "Print the estimator options (name, which methods take them, default, help)");
  sub->add_option("--markdown", o->markdown,
                  "With --options: print them as the markdown table of docs/cli.md (flags) or "
                  "docs/methods.md (spellings)")
      ->check(CLI::IsMember({"flags", "spellings"}));
  return [o]() { return run_methods(*o); };
}

}  // namespace curvbench::cli
