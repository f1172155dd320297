#include "core/text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "core/errors.h"

namespace curvbench {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  return ascii_lower(std::move(ext));
}

std::string ascii_lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string format_g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

double parse_double(const std::string& s, const std::string& where) {
  if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s == "-inf") return -std::numeric_limits<double>::infinity();
  try {
    size_t pos = 0;
    const double x = std::stod(s, &pos);
    if (pos == s.size()) return x;
  } catch (const std::exception&) {
  }
  throw InputError(where + ": '" + s + "' is not a number");
}

long long parse_integer(const std::string& s, const std::string& where) {
  try {
    size_t pos = 0;
    const long long x = std::stoll(s, &pos);
    if (pos == s.size()) return x;
  } catch (const std::exception&) {
  }
  throw InputError(where + ": '" + s + "' is not an integer");
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '/' && i > 0 && s[i - 1] == '<') {
      out += "\\/";
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace curvbench
