// The command line's flags of the estimator options, one per line of the option table
// (include/curvbench/estimator_options.h): --name VALUE for a number or a choice; a flag --name
// for a boolean whose default is no, --no-name for one whose default is yes.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <memory>
#include <string>

#include "curvbench/estimator_options.h"

namespace curvbench::cli {

class EstimatorOptionFlags {
 public:
  /// Adds every option's flag to `app`, with the table's help text.
  void add_to(CLI::App& app);
  /// The options given on the command line (set_option: the table's one validation), the
  /// defaults elsewhere. Throws UsageError "<name> ...: <problem>".
  EstimatorOptions options() const;

 private:
  // Per option name: its text as given (a flag: "yes"/"no"), shared with the CLI11 callbacks.
  std::shared_ptr<std::map<std::string, std::string>> given_ =
      std::make_shared<std::map<std::string, std::string>>();
};

}  // namespace curvbench::cli
