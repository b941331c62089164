#pragma once
// From a validated two-phase scenario (model = "two_phase") to a ready
// solver; reads no files (io filled the grids).
#include "talus/runout/scenario.hpp"

namespace talus::runout {

// The scenario's phases and closures with the grid's numerics (order,
// courant, dry depth, edges) and gravity.
TwoPhaseParams two_phase_params(const RunoutScenario& scenario);
// Terrain = elevation + obstacles; the release's depth split into solid and
// fluid by its solid fraction.
TwoPhaseSolver build_two_phase(const RunoutScenario& scenario);

}  // namespace talus::runout
