#pragma once
// Advances a DemSystem in time. The contact model is a template parameter, so
// the per-contact work is inlined; the scenario picks the model once, through
// make_stepper, and the run loop calls advance() in chunks.
#include <memory>
#include <vector>

#include "talus/dem/system.hpp"

namespace talus::dem {

// The force of one touching particle pair in the current state.
struct PairContactForce {
  int i = 0, j = 0;         // particle indices (the current, cell-sorted order)
  double normal = 0.0;      // f_n along the normal, > 0 pushes the pair apart
  double tangential = 0.0;  // |f_t|
  double friction = 0.0;    // the pair's Coulomb coefficient (|f_t| <= friction |f_n|)
};

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
  // The forces of the touching particle pairs (force-network analysis; not a
  // hot path): the contact law evaluated on a copy of each pair's history
  // without advancing it, so the state is left as it was.
  virtual std::vector<PairContactForce> pair_contact_forces() const = 0;
  // Brings the neighbour list and contact history into the system (before a
  // checkpoint): the GPU stepper keeps them on the device between steps; the
  // CPU stepper's are always there.
  virtual void sync_lists() {}
};

template <int D>
std::unique_ptr<StepperBase<D>> make_stepper(DemSystem<D>& system);

}  // namespace talus::dem
