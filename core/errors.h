// The typed exceptions live in the public header set (include/curvbench/errors.h), so that the
// library throws exactly the types its users catch.
#pragma once

#include "curvbench/errors.h"
