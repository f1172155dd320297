// Typed exceptions (public: installed with <curvbench/curvbench.h>). The command line maps them
// to exit codes: InputError and UsageError -> 2, anything else -> 1 (internal failure); the
// Python module to curvbench.InputError / curvbench.UsageError (both ValueError subclasses).
#pragma once

#include <stdexcept>
#include <string>

namespace curvbench {

/// Bad input data: unreadable or malformed file, invalid mesh, NaN coordinate, ...
/// what() is one line naming the file (when there is one) and the problem.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad usage: unknown method, invalid degree, inconsistent options.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace curvbench
