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

// Throws RunError on a non-finite velocity, or when the kinetic energy exceeds
// `factor` (> 0) times `available` while no wall moves.
template <int D>
void check_health(const DemRun<D>& run, double available, double factor);

}  // namespace talus::dem
