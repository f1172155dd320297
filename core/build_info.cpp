#include "core/build_info.h"

#include <ctime>

#include "curvbench/version.h"

namespace curvbench {

std::string build_info() {
  return std::string("curvbench ") + kVersion + " (git " + kGitDescribe + ") " + kCompiler + " " +
         kBuildType;
}

std::string utc_timestamp() {
  std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string provenance_comment() {
  return "# " + build_info() + ", generated " + utc_timestamp();
}

}  // namespace curvbench
