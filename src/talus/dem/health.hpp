#pragma once
// The DEM run's health: NaN and energy blow-up stop it with a diagnosis
// instead of producing garbage.
#include "talus/dem/builder.hpp"

namespace talus::dem {

// Energy the particles could at most turn into motion: their kinetic energy
// plus their potential energy above the lowest particle or wall point, never
// below that of the whole mass moving at 1 m/s or lifted by one diameter.
template <int D>
double available_energy(const DemSystem<D>& system);

// The work all walls have done on the particles so far (geometry::Wall::work).
template <int D>
double wall_work(const DemSystem<D>& system);

// What the kinetic energy is checked against: the energy available when the
// run (or its resumed part) started, and the walls' work then.
struct EnergyBudget {
  double available = 0.0;
  double wall_work_at_start = 0.0;
  double removed_at_start = 0.0;  // DemSystem::removed_kinetic_energy
};
template <int D>
EnergyBudget energy_budget(const DemSystem<D>& system);

// Throws RunError on a non-finite velocity, or when the kinetic energy, with
// what particles removed since the budget was taken carried out, exceeds
// `factor` (> 0) times the budget's available energy plus the work the walls
// have done since (when that is positive): the particles cannot gain more
// than they had and what moving walls gave them.
template <int D>
void check_health(const DemRun<D>& run, const EnergyBudget& budget, double factor);

}  // namespace talus::dem
