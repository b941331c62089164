#pragma once
// From a validated 2D scenario (model = "fv2d") to a ready solver; reads no
// files (io filled the grids).
#include "talus/runout/scenario.hpp"

namespace talus::runout {

Fv2dParams fv2d_params(const RunoutScenario& scenario);
// Terrain = elevation + obstacles; initial depth = the release grid.
Fv2dSolver build_fv2d(const RunoutScenario& scenario);

}  // namespace talus::runout
