// The estimator options as data: one OptionInfo per line of CURVBENCH_ESTIMATOR_OPTIONS
// (include/curvbench/estimator_options.h), and the one parser, printer and validation that the
// command line, the experiment files, the case store, the public C++ API and Python all use.
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "curvbench/estimator_options.h"
#include "mesh/rings.h"

namespace curvbench {

/// text: a value with its own syntax (the neighbourhood option: "knn=20", "radius=2.5s").
enum class OptionType : std::uint8_t { boolean, integer, real, choice, text };
/// Which methods take an option (a value other than its default elsewhere is an error):
/// listed = the methods OptionInfo::methods names.
/// ball_radius = the methods whose registry line declares their neighbourhood a ball of radius
/// C h (NeighbourhoodSize::ball_factor).
enum class OptionScope : std::uint8_t { all, fits, ring_fits, operators, ball_radius, listed };
/// result: changes the estimates (experiment method lines, case keys); run: how they are
/// computed, not what (threads, kernel).
enum class OptionRole : std::uint8_t { result, run };

struct OptionInfo {
  std::string name;         ///< "ball-factor": the experiment key and the CLI flag --ball-factor
  std::string python_name;  ///< "ball_factor": Python's keyword (name with '_' for '-')
  std::string field;        ///< "ball_factor": the member of EstimatorOptions (C++)
  OptionType type;
  OptionScope scope;
  std::string scope_name;  ///< "all", "fits", "ring-fits", "operators", or the methods' names
                           ///< joined by '|' ("normal-cycle|icc")
  std::vector<std::string> methods;  ///< OptionScope::listed: the names of the methods taking it
  OptionRole role;
  double lowest, highest;            ///< valid range of a number
  std::vector<std::string> choices;  ///< a choice's names (the first is the default's)
  std::string default_text;          ///< the default as text ("0", "yes", "default")
  std::string help;
};

/// Every option, in the table's order.
const std::vector<OptionInfo>& estimator_option_schema();

/// The option table as markdown, the one docs/cli.md and docs/methods.md carry between their
/// marker lines (tests/methods/test_option_docs.cpp; `curvbench methods --options --markdown`):
///   flags      | flag | taken by | default | meaning |  (docs/cli.md)
///   spellings  | option | command line | experiment file | Python | C++ |  (docs/methods.md)
enum class OptionTableStyle : std::uint8_t { flags, spellings };
std::string option_table_markdown(OptionTableStyle style);

/// The option called `name` (its name or Python name); throws UsageError naming the valid ones.
const OptionInfo& option_info(std::string_view name);

/// The neighbourhood option's text of a point neighbourhood ("knn=12", "radius=0.1",
/// "radius=2.5s"), as the results' rings column names it; "" for a ring neighbourhood.
std::string point_rule_text(const NeighbourhoodSpec& spec);

/// A value as Python or C++ hands it over.
using OptionValue = std::variant<bool, long long, double, std::string>;

/// Sets option `name` from text ("2.5", "yes"/"no"/"true"/"false", "area"); throws UsageError
/// "<name>: <problem>" for a value of the wrong type or out of range.
void set_option(EstimatorOptions& options, std::string_view name, std::string_view text);
/// The same from a typed value (a bool for a boolean, an integer for an integer, a number for a
/// real, a string for a choice).
void set_option_value(EstimatorOptions& options, std::string_view name, const OptionValue& value);

/// The option's value as text, as set_option reads it back.
std::string option_text(const EstimatorOptions& options, const OptionInfo& option);
/// Whether the option has its default value.
bool option_is_default(const EstimatorOptions& options, const OptionInfo& option);

/// Checks every option's range; throws UsageError "<name>: <problem>" at the first bad one.
void validate_options(const EstimatorOptions& options);

/// What an estimator is, for the scopes: its name, whether it is a degree-d fit, whether it is a
/// fit of the paper's framework on rings (Estimator::ring_fit()).
struct OptionTarget {
  std::string name;
  bool fit = false;
  bool ring_fit = false;
  bool ball_radius = false;  ///< its registry line declares NeighbourhoodSize::ball_factor
};

/// Checks that every option set away from its default suits the method; throws UsageError
/// "<option> applies to ... only, not to '<name>'".
void check_options_apply(const EstimatorOptions& options, const OptionTarget& target);

}  // namespace curvbench
