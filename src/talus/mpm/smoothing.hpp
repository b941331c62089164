#pragma once
// Volumetric strain smoothing (Jassim 2011; Jassim, Stolle & Vermeer 2013,
// the scheme of Anura3D): the volumetric strain rate tr(L_p) of the points in
// a cell is replaced by its volume-weighted mean over the cell before the
// stress update, the deviatoric part is kept. With several points per cell
// and a nearly incompressible material the points of one cell otherwise take
// independent volume changes that the few nodal velocities cannot represent,
// and their pressures oscillate from point to point (checkerboard, volumetric
// locking). In 2D (plane strain) only the in-plane diagonal is changed.
#include <vector>

#include "talus/mpm/grid.hpp"
#include "talus/mpm/particles.hpp"

namespace talus::mpm {

// scratch: per-cell sums, resized as needed (kept by the caller between steps).
template <int D>
void smooth_volumetric_strain(const Grid<D>& grid, Particles<D>& particles,
                              std::vector<double>& scratch);

}  // namespace talus::mpm
