#pragma once
// Energy watch of an MPM run (the DEM driver's counterpart): a run whose
// kinetic energy grows past a multiple of all the energy it could release
// from its start state is unstable and is stopped with a diagnosis, instead
// of running on until points fly off the grid.
#include "talus/mpm/solver.hpp"

namespace talus::mpm {

// Kinetic energy of the material points and membrane nodes.
template <int D>
double total_kinetic_energy(const Solver<D>& s);

// What the state can turn into motion: its kinetic energy, the elastic energy
// of its stresses (sigma : C^-1 : sigma / 2, isotropic, per point volume),
// and the potential energy of every point and membrane node down to the
// grid's lowest corner along gravity.
template <int D>
double available_energy(const Solver<D>& s);

// The work all rigid bodies have done on the material (RigidBody::work).
template <int D>
double rigid_work(const Solver<D>& s);

// What the kinetic energy is checked against: the energy available when the
// run (or its resumed part) started, and the rigid bodies' work then.
struct EnergyBudget {
  double available = 0.0;
  double rigid_work_at_start = 0.0;
};
template <int D>
EnergyBudget energy_budget(const Solver<D>& s);

// Throws RunError when the kinetic energy exceeds factor times the budget's
// available energy plus the work the rigid bodies have done since (when
// positive; factor <= 0: never). The message names the time step and, for a
// Drucker-Prager material whose dilatancy lets plastic flow do negative work,
// that angle.
template <int D>
void check_energy(const Solver<D>& s, const EnergyBudget& budget, double factor);

// Largest dilatancy angle (rad) at which the Drucker-Prager plastic work
// sqrt(J2) + 9 sin(psi) p stays non-negative on the cone
// sqrt(J2) = k_c - 3 alpha p at every mean stress p <= 0 (mpm.md's potential
// g = sqrt(J2) + 3 I1 sin(psi)): sin(psi) <= alpha / 3.
double dissipative_dilatancy_limit(double phi);

}  // namespace talus::mpm
