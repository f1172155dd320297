#include "cli/estimator_flags.h"

#include "methods/option_schema.h"

namespace curvbench::cli {

void EstimatorOptionFlags::add_to(CLI::App& app) {
  for (const OptionInfo& option : estimator_option_schema()) {
    auto given = given_;
    const std::string name = option.name;
    if (option.type == OptionType::boolean) {
      const bool default_yes = option.default_text == "yes";
      const std::string flag = default_yes ? "--no-" + name : "--" + name;
      app.add_flag_callback(
          flag, [given, name, default_yes] { (*given)[name] = default_yes ? "no" : "yes"; },
          option.help + (default_yes ? " (default: yes; this flag: no)" : ""));
      continue;
    }
    std::string help = option.help;
    if (!option.choices.empty()) {
      std::string names;
      for (const std::string& c : option.choices) names += (names.empty() ? "" : "|") + c;
      help += " [" + names + "]";
    }
    help += " (default " + option.default_text + ")";
    const char* type = option.type == OptionType::integer ? "INT"
                       : option.type == OptionType::real  ? "NUMBER"
                       : option.type == OptionType::text  ? "RULE"
                                                          : "NAME";
    app.add_option_function<std::string>(
           "--" + name, [given, name](const std::string& text) { (*given)[name] = text; }, help)
        ->type_name(type);
  }
}

EstimatorOptions EstimatorOptionFlags::options() const {
  EstimatorOptions o;
  for (const auto& [name, text] : *given_) set_option(o, name, text);
  return o;
}

}  // namespace curvbench::cli
