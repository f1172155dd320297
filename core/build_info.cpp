#include "core/build_info.h"

#include <cstdlib>
#include <ctime>

#include "curvbench/version.h"

namespace curvbench {

namespace {

// SOURCE_DATE_EPOCH if set to a decimal number of seconds that fits a time_t, else now.
std::time_t output_time() {
  const char* env = std::getenv("SOURCE_DATE_EPOCH");
  if (env != nullptr && *env != '\0') {
    std::time_t t = 0;
    bool valid = true;
    for (const char* p = env; *p != '\0' && valid; ++p) {
      if (*p < '0' || *p > '9' || t > (static_cast<std::time_t>(253402300799) - (*p - '0')) / 10)
        valid = false;  // not a digit, or after 9999-12-31T23:59:59Z
      else
        t = 10 * t + (*p - '0');
    }
    if (valid) return t;
  }
  return std::time(nullptr);
}

}  // namespace

std::string build_info() {
  return std::string("curvbench ") + kVersion + " (git " + kGitDescribe + ") " + kCompiler + " " +
         kBuildType;
}

std::string utc_timestamp() {
  const std::time_t t = output_time();
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string provenance_comment() {
  return "# " + build_info() + ", generated " + utc_timestamp();
}

}  // namespace curvbench
