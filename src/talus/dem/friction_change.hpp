#pragma once
// A change of the grains' friction during the run (the beam's mu_init -> mu_p,
// Götz 2024 §5.3): from `time` on, the given materials have `friction`.
#include <vector>

#include "talus/dem/builder.hpp"

namespace talus::dem {

struct FrictionChange {
  double time = 0.0;
  double friction = 0.0;
  std::vector<int> materials;
};

// The stepper keeps its contact coefficients from construction on, so a new
// one takes the changed materials; the state (forces and contact histories)
// lives in the system and carries over as it does from a checkpoint.
template <int D>
void apply_friction_change(DemRun<D>& run, const FrictionChange& f) {
  for (int k : f.materials) run.system.materials[k].friction = f.friction;
  run.stepper = make_stepper(run.system);
}

}  // namespace talus::dem
