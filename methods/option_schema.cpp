#include "methods/option_schema.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <span>
#include <type_traits>

#include "core/errors.h"
#include "core/text.h"
#include "methods/estimator.h"

namespace curvbench {

namespace {

// ---- the text of one value, per type ------------------------------------------------------------

template <class T>
struct ValueText;

template <>
struct ValueText<bool> {
  static constexpr OptionType type = OptionType::boolean;
  static bool parse(std::string_view s, const std::string& name) {
    if (s == "yes" || s == "true" || s == "1") return true;
    if (s == "no" || s == "false" || s == "0") return false;
    throw UsageError(name + ": expected yes or no, got '" + std::string(s) + "'");
  }
  static std::string text(bool b) { return b ? "yes" : "no"; }
};

template <>
struct ValueText<int> {
  static constexpr OptionType type = OptionType::integer;
  static int parse(std::string_view s, const std::string& name) {
    int x = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
    if (ec != std::errc() || end != s.data() + s.size() || s.empty())
      throw UsageError(name + ": '" + std::string(s) + "' is not an integer");
    return x;
  }
  static std::string text(int x) { return std::to_string(x); }
};

template <>
struct ValueText<double> {
  static constexpr OptionType type = OptionType::real;
  static double parse(std::string_view s, const std::string& name) {
    try {
      return parse_double(std::string(s), name);
    } catch (const InputError&) {
      throw UsageError(name + ": '" + std::string(s) + "' is not a number");
    }
  }
  static std::string text(double x) {  // the shortest text that reads back to x
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
  }
};

template <>
struct ValueText<PointNeighbourhood> {
  static constexpr OptionType type = OptionType::text;
  static PointNeighbourhood parse(std::string_view s, const std::string& name) {
    using Kind = PointNeighbourhood::Kind;
    const auto bad = [&] {
      return UsageError(name + ": '" + std::string(s) +
                        "' is not knn=K, radius=R or radius=Cs (e.g. knn=20, radius=2.5s)");
    };
    if (s == "default") return {};
    PointNeighbourhood out;
    std::string_view value;
    if (s.starts_with("knn=")) {
      out.kind = Kind::knn;
      value = s.substr(4);
    } else if (s.starts_with("radius=")) {
      out.kind = Kind::radius;
      value = s.substr(7);
      if (value.ends_with('s')) {
        out.kind = Kind::radius_spacing;
        value.remove_suffix(1);
      }
    } else {
      throw bad();
    }
    if (out.kind == Kind::knn) {
      int k = 0;
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), k);
      if (ec != std::errc() || end != value.data() + value.size() || value.empty() || k < 1)
        throw UsageError(name + ": knn=" + std::string(value) + ": K must be a whole number >= 1");
      out.size = k;
      return out;
    }
    double r = 0.0;
    try {
      r = parse_double(std::string(value), name);
    } catch (const InputError&) {
      throw bad();
    }
    if (!(r > 0.0) || !std::isfinite(r))
      throw UsageError(name + ": the radius must be a positive number, got '" + std::string(value) +
                       "'");
    out.size = r;
    return out;
  }
  static std::string text(const PointNeighbourhood& p) {
    using Kind = PointNeighbourhood::Kind;
    switch (p.kind) {
      case Kind::none:
        return "default";
      case Kind::knn:
        return "knn=" + std::to_string(static_cast<long long>(p.size));
      case Kind::radius:
        return "radius=" + ValueText<double>::text(p.size);
      case Kind::radius_spacing:
        return "radius=" + ValueText<double>::text(p.size) + "s";
    }
    return "default";
  }
};

// A choice: an enum whose value i is called names[i] (its k...Names array).
template <class E>
struct EnumNames;
template <>
struct EnumNames<VertexNormals> {
  static constexpr std::span<const char* const> names{kVertexNormalsNames};
};
template <>
struct EnumNames<PointNormalSource> {
  static constexpr std::span<const char* const> names{kPointNormalSourceNames};
};
template <>
struct EnumNames<Kernel> {
  static constexpr std::span<const char* const> names{kKernelNames};
};

template <class E>
requires std::is_enum_v<E>
struct ValueText<E> {
  static constexpr OptionType type = OptionType::choice;
  static E parse(std::string_view s, const std::string& name) {
    const auto names = EnumNames<E>::names;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (s == names[i]) return static_cast<E>(i);
    std::string valid;
    for (const char* n : names) valid += (valid.empty() ? "" : ", ") + std::string(n);
    throw UsageError(name + ": unknown value '" + std::string(s) + "' (valid: " + valid + ")");
  }
  static std::string text(E v) { return EnumNames<E>::names[static_cast<std::size_t>(v)]; }
  static std::vector<std::string> choices() {
    return {EnumNames<E>::names.begin(), EnumNames<E>::names.end()};
  }
};

// vertex-normals: a weighting's name, or the label of a degree-d fit whose normals the operator
// takes, kept as the fit's own label in lower case ("LHF-3" -> "lhf-3", "lhf" -> "lhf-2").
template <>
struct ValueText<VertexNormalSource> {
  using Weighting = ValueText<VertexNormals>;
  static constexpr OptionType type = OptionType::choice;
  static VertexNormalSource parse(std::string_view s, const std::string& name) {
    for (const char* w : kVertexNormalsNames)
      if (s == w) return Weighting::parse(s, name);
    const std::string label(s);
    bool fit = false;
    try {
      fit = method_info(label).is_fit();
    } catch (const UsageError&) {
      throw UsageError(name + ": unknown value '" + label +
                       "' (valid: default, area, angle, max, or a fit's label such as lhf-3)");
    }
    if (!fit)
      throw UsageError(name + ": '" + label +
                       "' is not a fit (a fitted source is a fit's label such as lhf-3, jet-4)");
    VertexNormalSource v;
    try {
      v.fit = make_estimator(label, EstimatorOptions{})->label();
    } catch (const UsageError& e) {
      throw UsageError(name + " " + label + ": " + e.what());
    }
    for (char& c : v.fit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return v;
  }
  static std::string text(const VertexNormalSource& v) {
    return v.fitted() ? v.fit : Weighting::text(v.weighting);
  }
  static std::vector<std::string> choices() { return Weighting::choices(); }
};

// ---- one option: its description and the functions that reach its field -------------------------

struct Option {
  OptionInfo info;
  void (*set_text)(EstimatorOptions&, std::string_view, const OptionInfo&);
  void (*set_value)(EstimatorOptions&, const OptionValue&, const OptionInfo&);
  std::string (*text)(const EstimatorOptions&);
  bool (*is_default)(const EstimatorOptions&);
  void (*validate)(const EstimatorOptions&, const OptionInfo&);
};

template <class T, T EstimatorOptions::*field>
struct Access {
  using Text = ValueText<T>;
  static void check(T x, const OptionInfo& info) {
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
      const double v = static_cast<double>(x);
      if (!(v >= info.lowest && v <= info.highest))
        throw UsageError(info.name + " " + format_g(v) + ": out of range (valid: " +
                         format_g(info.lowest) + " to " + format_g(info.highest) + ")");
    }
  }
  static void set_text(EstimatorOptions& o, std::string_view s, const OptionInfo& info) {
    const T x = Text::parse(s, info.name);
    check(x, info);
    o.*field = x;
  }
  static void set_value(EstimatorOptions& o, const OptionValue& v, const OptionInfo& info) {
    const auto wrong = [&](const char* want) {
      return UsageError(info.name + ": expected " + want);
    };
    T x{};
    if constexpr (std::is_same_v<T, bool>) {
      if (!std::holds_alternative<bool>(v)) throw wrong("True or False");
      x = std::get<bool>(v);
    } else if constexpr (std::is_same_v<T, int>) {
      if (!std::holds_alternative<long long>(v)) throw wrong("an integer");
      const long long i = std::get<long long>(v);
      check(static_cast<T>(std::clamp<long long>(i, -(1LL << 30), 1LL << 30)), info);
      x = static_cast<int>(i);
    } else if constexpr (std::is_same_v<T, double>) {
      if (std::holds_alternative<long long>(v))
        x = static_cast<double>(std::get<long long>(v));
      else if (std::holds_alternative<double>(v))
        x = std::get<double>(v);
      else
        throw wrong("a number");
    } else {
      if (!std::holds_alternative<std::string>(v)) throw wrong("a string");
      x = Text::parse(std::get<std::string>(v), info.name);
    }
    check(x, info);
    o.*field = x;
  }
  static std::string text(const EstimatorOptions& o) { return Text::text(o.*field); }
  static bool is_default(const EstimatorOptions& o) {
    return o.*field == EstimatorOptions{}.*field;
  }
  static void validate(const EstimatorOptions& o, const OptionInfo& info) { check(o.*field, info); }
  static std::vector<std::string> choices() {
    if constexpr (Text::type == OptionType::choice)
      return Text::choices();
    else
      return {};
  }
};

std::string python_name(std::string name) {
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

template <class T, T EstimatorOptions::*field>
Option make_option(const char* name, const char* field_name, std::string_view scope,
                   std::string_view role, double lowest, double highest, const char* help) {
  using A = Access<T, field>;
  OptionInfo info;
  info.name = name;
  info.field = field_name;
  info.python_name = python_name(name);
  info.type = A::Text::type;
  info.scope_name = std::string(scope);
  for (char& c : info.scope_name)
    if (c == '_') c = '-';
  if (scope == "all") {
    info.scope = OptionScope::all;
  } else if (scope == "fits") {
    info.scope = OptionScope::fits;
  } else if (scope == "ring_fits") {
    info.scope = OptionScope::ring_fits;
  } else if (scope == "operators") {
    info.scope = OptionScope::operators;
  } else if (scope == "ball_radius") {
    info.scope = OptionScope::ball_radius;
  } else {  // "normal_cycle" or "normal_cycle|icc" (the stringified macro argument)
    info.scope = OptionScope::listed;
    std::string method;
    for (const char c : info.scope_name + "|") {
      if (c != '|') {
        if (c != ' ') method += c;
      } else if (!method.empty()) {
        info.methods.push_back(method);
        method.clear();
      }
    }
    info.scope_name.clear();
    for (const std::string& m : info.methods)
      info.scope_name += (info.scope_name.empty() ? "" : "|") + m;
  }
  info.role = role == "run" ? OptionRole::run : OptionRole::result;
  info.lowest = lowest;
  info.highest = highest;
  info.choices = A::choices();
  info.default_text = A::text(EstimatorOptions{});
  info.help = help;
  return {std::move(info), &A::set_text, &A::set_value, &A::text, &A::is_default, &A::validate};
}

const std::vector<Option>& options_table() {
#define CURVBENCH_OPTION_ENTRY(type, field, name, fallback, scope, role, lowest, highest, help) \
  make_option<type, &EstimatorOptions::field>(name, #field, #scope, #role, lowest, highest, help),
  static const std::vector<Option> table = {CURVBENCH_ESTIMATOR_OPTIONS(CURVBENCH_OPTION_ENTRY)};
#undef CURVBENCH_OPTION_ENTRY
  return table;
}

const Option& find_option(std::string_view name) {
  for (const Option& o : options_table())
    if (name == o.info.name || name == o.info.python_name) return o;
  std::string valid;
  for (const Option& o : options_table()) valid += (valid.empty() ? "" : ", ") + o.info.name;
  throw UsageError("unknown option '" + std::string(name) + "' (valid: " + valid + ")");
}

// The methods a scope names: its list, or for ball_radius the registered methods whose
// neighbourhood is a ball.
std::vector<std::string> scope_methods(const OptionInfo& info) {
  if (info.scope != OptionScope::ball_radius) return info.methods;
  std::vector<std::string> names;
  for (const MethodInfo& m : method_table())
    if (m.radius == NeighbourhoodSize::ball_factor) names.push_back(m.name);
  return names;
}

std::string scope_text(const OptionInfo& info) {
  if (info.scope == OptionScope::fits) return "the fits only (the methods with a degree)";
  if (info.scope == OptionScope::ring_fits)
    return "the fits of the weighted least-squares framework only (lhf, lop, lscm)";
  if (info.scope == OptionScope::operators) return "the discrete operators only";
  const std::vector<std::string> methods = scope_methods(info);
  std::string names;
  for (size_t i = 0; i < methods.size(); ++i) {
    if (i > 0) names += i + 1 == methods.size() ? " and " : ", ";
    names += "'" + methods[i] + "'";
  }
  return (methods.size() == 1 ? "method " : "methods ") + names + " only" +
         (info.scope == OptionScope::ball_radius ? " (the methods sized by a ball)" : "");
}

}  // namespace

const std::vector<OptionInfo>& estimator_option_schema() {
  static const std::vector<OptionInfo> infos = [] {
    std::vector<OptionInfo> out;
    for (const Option& o : options_table()) out.push_back(o.info);
    return out;
  }();
  return infos;
}

namespace {

// A markdown table cell: '|' escaped.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string taken_by(const OptionInfo& o) {
  switch (o.scope) {
    case OptionScope::all:
      return "all";
    case OptionScope::fits:
      return "fits";
    case OptionScope::ring_fits:
      return "ring fits";
    case OptionScope::operators:
      return "operators";
    case OptionScope::ball_radius:
      return "ball-sized methods";  // a scope, not a list: a new ball-sized method changes nothing
    case OptionScope::listed:
      break;
  }
  std::string names;
  for (const std::string& m : scope_methods(o)) names += (names.empty() ? "" : ", ") + m;
  return names;
}

// The value a flag or key takes: N (integer), X (number), RULE (a text with its own syntax,
// the help says which), or the choices.
std::string value_word(const OptionInfo& o) {
  switch (o.type) {
    case OptionType::text:
      return "RULE";
    case OptionType::integer:
      return "N";
    case OptionType::real:
      return "X";
    case OptionType::choice: {
      std::string c;
      for (const std::string& v : o.choices) c += (c.empty() ? "" : "|") + v;
      return c;
    }
    case OptionType::boolean:
      break;
  }
  return "";
}

// A boolean's flag sets it away from its default: --noisy (default no), --no-adaptive (yes).
std::string flag(const OptionInfo& o) {
  if (o.type == OptionType::boolean)
    return o.default_text == "yes" ? "--no-" + o.name : "--" + o.name;
  return "--" + o.name + " " + value_word(o);
}

std::string away_from_default(const OptionInfo& o) {
  if (o.type == OptionType::boolean) return o.default_text == "yes" ? "no" : "yes";
  return value_word(o);
}

}  // namespace

std::string option_table_markdown(OptionTableStyle style) {
  std::string md = style == OptionTableStyle::flags
                       ? "| flag | taken by | default | meaning |\n|---|---|---|---|\n"
                       : "| option | command line | experiment file | Python | C++ "
                         "(`EstimatorOptions`) |\n|---|---|---|---|---|\n";
  for (const Option& entry : options_table()) {
    const OptionInfo& o = entry.info;
    if (style == OptionTableStyle::flags) {
      md += "| `" + cell(flag(o)) + "` | " + taken_by(o) + " | " + cell(o.default_text) + " | " +
            cell(o.help) + " |\n";
      continue;
    }
    const std::string value = away_from_default(o);
    const std::string python = o.type == OptionType::boolean  ? (value == "yes" ? "True" : "False")
                               : o.type == OptionType::choice ? "\"" + o.choices.back() + "\""
                               : o.type == OptionType::text   ? "\"" + value + "\""
                                                              : value;
    md += "| " + o.name + " (" + taken_by(o) + ") | `" + cell(flag(o)) + "` | " +
          (o.role == OptionRole::run ? std::string("-") : "`" + o.name + "=" + cell(value) + "`") +
          " | `" + o.python_name + "=" + cell(python) + "` | `" + o.field + "` |\n";
  }
  return md;
}

const OptionInfo& option_info(std::string_view name) {
  return find_option(name).info;
}

void set_option(EstimatorOptions& options, std::string_view name, std::string_view text) {
  const Option& o = find_option(name);
  o.set_text(options, text, o.info);
}

void set_option_value(EstimatorOptions& options, std::string_view name, const OptionValue& value) {
  const Option& o = find_option(name);
  o.set_value(options, value, o.info);
}

std::string option_text(const EstimatorOptions& options, const OptionInfo& option) {
  return find_option(option.name).text(options);
}

bool option_is_default(const EstimatorOptions& options, const OptionInfo& option) {
  return find_option(option.name).is_default(options);
}

void validate_options(const EstimatorOptions& options) {
  for (const Option& o : options_table()) o.validate(options, o.info);
}

void check_options_apply(const EstimatorOptions& options, const OptionTarget& target) {
  for (const Option& o : options_table()) {
    const OptionInfo& info = o.info;
    const bool applies =
        info.scope == OptionScope::all || (info.scope == OptionScope::fits && target.fit) ||
        (info.scope == OptionScope::ring_fits && target.ring_fit) ||
        (info.scope == OptionScope::operators && !target.fit) ||
        (info.scope == OptionScope::ball_radius && target.ball_radius) ||
        (info.scope == OptionScope::listed &&
         std::find(info.methods.begin(), info.methods.end(), target.name) != info.methods.end());
    if (!applies && !o.is_default(options))
      throw UsageError(info.name + " applies to " + scope_text(info) + ", not to '" + target.name +
                       "'");
  }
}

std::string point_rule_text(const NeighbourhoodSpec& spec) {
  using Points = NeighbourhoodSpec::Points;
  using Kind = PointNeighbourhood::Kind;
  switch (spec.points) {
    case Points::none:
      return "";
    case Points::knn:
      return ValueText<PointNeighbourhood>::text({Kind::knn, spec.size});
    case Points::radius:
      return ValueText<PointNeighbourhood>::text({Kind::radius, spec.size});
    case Points::radius_spacing:
      return ValueText<PointNeighbourhood>::text({Kind::radius_spacing, spec.size});
  }
  return "";
}

}  // namespace curvbench
