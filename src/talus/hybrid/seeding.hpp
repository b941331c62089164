#pragma once
// Particles from a depth map (van den Bout et al. 2021 §2.4.2): every
// particle has the same volume V, and a cell of depth d gets round(d A / V)
// particles placed by the R2 sequence (r2_sequence.hpp), so the kernel sum of
// their masses gives back the depth.
#include <vector>

#include "talus/hybrid/particles.hpp"
#include "talus/runout/grid/terrain.hpp"

namespace talus::hybrid {

struct Seeded {
  Particles particles;
  double spacing = 0.0;  // sqrt(A / n) of the fullest cell: the d0 of the artificial stress
};

// depth: per cell of `shape` (m, >= 0); density: rho_c (kg/m^3); velocity:
// every particle's initial one. Throws InputError for a size mismatch, a bad
// depth, volume or density, or a depth that gives no particle at all.
Seeded seed_particles(const runout::GridShape& shape, const std::vector<double>& depth,
                      double particle_volume, double density, double u0 = 0.0, double v0 = 0.0);

}  // namespace talus::hybrid
