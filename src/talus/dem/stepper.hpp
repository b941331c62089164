#pragma once
// Advances a DemSystem in time. The contact model is a template parameter, so
// the per-contact work is inlined; the scenario picks the model once, through
// make_stepper, and the run loop calls advance() in chunks.
#include <memory>

#include "talus/dem/system.hpp"

namespace talus::dem {

template <int D>
class StepperBase {
 public:
  virtual ~StepperBase() = default;
  // Computes the forces of the current state (once, before the first step of a
  // fresh run; a resumed run has them from its checkpoint).
  virtual void prime() = 0;
  // Picks up a state restored from a checkpoint (forces and lists included).
  virtual void resume() = 0;
  virtual void advance(int64_t steps) = 0;
  // Rebuilds the neighbour list now (re-sorts particles, removes escaped ones).
  virtual void rebuild() = 0;
  // Smallest critical time step over all material pairs present, for impacts
  // at v_ref (Hertz laws); PFC's sqrt(m/k) for linear contacts; divided by
  // sqrt(2D) for the 2D contacts a particle has in a dense packing.
  virtual double critical_time_step(double v_ref) const = 0;
};

template <int D>
std::unique_ptr<StepperBase<D>> make_stepper(DemSystem<D>& system);

}  // namespace talus::dem
