// A fixture for the test harness.WingIncludesCatchesViolation: a claims file including the
// report wing, which cmake/check_wing_includes.cmake must reject. Never compiled.
#pragma once
#include "harness/model/experiment.h"
#include "harness/report/model.h"
