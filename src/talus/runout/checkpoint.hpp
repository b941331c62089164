#pragma once
// Checkpoints of the depth-averaged runs: what a step reads that the scenario
// does not rebuild, and what the run has gathered so far, so that a resumed
// run continues bit for bit like an uninterrupted one and reports the same
// figures. DAN: the blocks (positions, velocities, earth-pressure
// coefficients, time), the energy check's memory and the tracker's results
// (front samples, maxima, arrival, run-up). fv2d: the flow state, the
// earth-pressure coefficients, the outflow, the per-cell maxima and the
// released volume. Two-phase: the same for both phases, with the rain and
// infiltration totals.
#include <cstdint>
#include <filesystem>

#include "talus/runout/dan.hpp"
#include "talus/runout/grid/fv2d.hpp"
#include "talus/runout/grid/fv2d_maxima.hpp"
#include "talus/runout/grid/two_phase_maxima.hpp"
#include "talus/runout/results.hpp"

namespace talus::runout {

// The run loop's counts that a resumed run continues.
struct StepCount {
  std::int64_t steps = 0;
  double last_time_step = 0.0;
};

void save_checkpoint(const DanModel& model, const RunoutTracker& tracker, StepCount count,
                     const std::filesystem::path& path);
// Restores into a model and tracker built from the same scenario. Throws
// InputError on a checkpoint that does not fit them.
StepCount load_checkpoint(DanModel& model, RunoutTracker& tracker,
                          const std::filesystem::path& path);

// path_results: a grid model's flume results on a path (empty otherwise).
void save_checkpoint(const Fv2dSolver& solver, const Fv2dMaxima& maxima, double released_volume,
                     const RunoutResults& path_results, StepCount count,
                     const std::filesystem::path& path);
StepCount load_checkpoint(Fv2dSolver& solver, Fv2dMaxima& maxima, double& released_volume,
                          RunoutResults& path_results, const std::filesystem::path& path);

// Released volumes of each phase, for the figures of a resumed run.
struct ReleasedVolumes {
  double solid = 0.0, fluid = 0.0;
};

void save_checkpoint(const TwoPhaseSolver& solver, const TwoPhaseMaxima& maxima,
                     ReleasedVolumes released, const RunoutResults& path_results, StepCount count,
                     const std::filesystem::path& path);
StepCount load_checkpoint(TwoPhaseSolver& solver, TwoPhaseMaxima& maxima, ReleasedVolumes& released,
                          RunoutResults& path_results, const std::filesystem::path& path);

}  // namespace talus::runout
