// A family swap of a reading (readings.h): the claims read `by`'s rows where they name `family`.
#pragma once

#include <string>

namespace curvbench {

struct FamilySubstitute {
  std::string family;  ///< the family the claims name ("bump-irregular"); empty = no swap
  std::string by;      ///< the family read in its place ("bump-unstructured")
};

}  // namespace curvbench
