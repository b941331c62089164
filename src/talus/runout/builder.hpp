#pragma once
// From a validated scenario to a ready DAN model and what its results need.
#include "talus/runout/results.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::runout {

struct DanSetup {
  DanModel model;
  double barrier_start_s;  // NaN when the path has no barrier
};

// Throws InputError when the path or release do not fit (e.g. a release
// polygon outside the path's horizontal range).
DanSetup build_dan(const RunoutScenario& scenario);

// The path of a scenario alone (for the flume, the same FlumeGeometry as the
// DEM scenario uses).
RunoutPath build_path(const PathSpec& spec);

}  // namespace talus::runout
