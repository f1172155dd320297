// One-line description of the code version, compiler and build type, for output headers.
#pragma once

#include <string>

namespace curvbench {

/// e.g. "curvbench 0.1.0 (git 1a2b3c4) GNU 12.2.0 Release".
std::string build_info();

/// Current UTC date and time as ISO 8601, e.g. "2026-11-22T13:05:00Z".
std::string utc_timestamp();

/// "# <build_info()>, generated <utc_timestamp()>": the first line of every CSV curvbench
/// writes (its readers skip lines starting with '#').
std::string provenance_comment();

}  // namespace curvbench
