#pragma once
// Turns validated scenario parameters into a ready-to-run DEM system: walls,
// particles from their sources, time step checked against the critical one,
// packings settled under gravity. Physics checks that need the particles live
// here and throw InputError before anything runs.
#include <memory>

#include "talus/dem/params.hpp"
#include "talus/dem/stepper.hpp"
#include "talus/dem/system.hpp"

namespace talus::dem {

template <int D>
struct DemRun {
  DemSystem<D> system;
  std::unique_ptr<StepperBase<D>> stepper;
};

struct BuildOptions {
  int threads = 1;
  bool settle = true;  // false when the state comes from a checkpoint
  // false when it comes from a checkpoint: no particles are placed (a random
  // fill relaxes for seconds), and the step stays the checkpoint's.
  bool place = true;
};

template <int D>
std::unique_ptr<DemRun<D>> build_dem(const DemScenario& scenario, const BuildOptions& options);

// The deterministic lattice jitter of the peer benchmark (../shared/peers/README.md §1):
// h(i,j,k,c) = frac(43758.5453 sin(12.9898 i + 78.233 j + 37.719 k + 4.1414 c)).
double peer_jitter_hash(int i, int j, int k, int c);

}  // namespace talus::dem
