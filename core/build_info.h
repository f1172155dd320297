// One-line description of the code version, compiler and build type, for output headers.
#pragma once

#include <string>

namespace curvbench {

/// e.g. "curvbench 0.1.0 (git 1a2b3c4) GNU 12.2.0 Release".
std::string build_info();

/// Current UTC date and time as ISO 8601, e.g. "2026-11-22T13:05:00Z". If the environment
/// variable SOURCE_DATE_EPOCH (reproducible-builds.org) holds a non-negative decimal number of
/// seconds since 1970-01-01T00:00:00Z, that time is used instead, so that outputs carrying the
/// date can be reproduced byte for byte; any other value is ignored.
std::string utc_timestamp();

/// "# <build_info()>, generated <utc_timestamp()>": the first line of every CSV curvbench
/// writes (its readers skip lines starting with '#').
std::string provenance_comment();

}  // namespace curvbench
