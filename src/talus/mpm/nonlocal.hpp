#pragma once
// Non-local volume strain for the cohesion loss (after Pijaudier-Cabot &
// Bazant 1987): van den Bout's law dc = -(c0 / 2 eps_c) dV / V0 is local, so
// the dilation that breaks the bonds concentrates in a band one cell wide and
// the crack it draws changes with the cell size (docs/validation.md, clay
// block). Driven instead by the dilation averaged over a fixed length ell,
// the loss sees the band's opening divided by ell however many cells the
// band spans. The average is taken on an auxiliary lattice of spacing ell
// (volume-weighted tent functions there and back: a smooth kernel of
// half-width 2 ell, fixed in space and independent of the MPM grid).
#include <vector>

#include "talus/mpm/particles.hpp"

namespace talus::mpm {

// values[k] belongs to point list[k]; on return it holds the volume-weighted
// average over the points of `list` around that point. Serial accumulation in
// list order: the same bits for any number of threads. scratch is kept by the
// caller between steps.
template <int D>
void nonlocal_average(const Particles<D>& p, const std::vector<int>& list, double ell,
                      std::vector<double>& values, std::vector<double>& scratch);

}  // namespace talus::mpm
