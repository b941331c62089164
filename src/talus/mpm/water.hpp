#pragma once
// Still water around the material below a level (the geotextile bag dropped
// from a barge; Morison et al. 1950's split of a body's water load into
// inertia and drag). What acts, and where:
//  - buoyancy, rho_w V g upward, on every point below the level (so gravity
//    stays the real one);
//  - added mass, C_a rho_w V, on the inertia of every point below the level
//    (not on its weight): the water a body must accelerate with it. Summed
//    over a body it is Morison's C_a rho_w V_body; C_a is the body's (1 for a
//    circular cylinder across its axis, pi a^2 / A for a flat plate of width
//    2a moving broadside, about 2 for the 4.2 x 1.6 m bag falling flat);
//  - drag on the membranes, the bodies' skin: each submerged node whose
//    outward normal n moves into the water, u = v . n > 0 (v the grid's
//    updated velocity at the node, membrane_grid.hpp), takes
//    -1/2 rho_w C_d A u^2 n, A its share of the membrane (its mass over the
//    areal mass); the faces moving away take nothing (their suction is in
//    C_d, a body's drag coefficient on its frontal area: about 1.2 for a
//    flat box, 2.0 for a plate broadside). An open sheet has two faces: both
//    sides count.
// Why drag on the membranes only: form drag acts on a body's surface, and a
// per-point drag on every submerged point of a continuum would count its
// interior. Points without a membrane around them take buoyancy and added
// mass only. The water itself is at rest and does not move (no coupling to
// a fluid model).
#include <cmath>
#include <limits>

#include "talus/core/space.hpp"
#include "talus/mpm/membrane.hpp"

namespace talus::mpm {

// level = -inf: no water.
struct WaterParams {
  double level = -std::numeric_limits<double>::infinity();  // m, on the up axis
  double density = 1000.0;                                  // kg/m^3
  double drag_coefficient = 0.0;                            // C_d
  double added_mass_coefficient = 0.0;                      // C_a
  bool present() const { return std::isfinite(level); }
};

// The drag on node i of membrane m moving at v (unit normal n, outward for
// a closed membrane); zero above the level.
template <int D>
typename Space<D>::Vec water_drag(const WaterParams& w, const Membrane<D>& m, std::size_t i,
                                  const typename Space<D>::Vec& v,
                                  const typename Space<D>::Vec& n) {
  using Vec = typename Space<D>::Vec;
  if (!(m.x[i][D - 1] < w.level) || m.areal_mass <= 0.0) return Vec::Zero();
  const double u = v.dot(n);
  if (m.closed && u <= 0.0) return Vec::Zero();
  const double area = m.mass[i] / m.areal_mass;
  return (-0.5 * w.density * w.drag_coefficient * area * u * std::abs(u)) * n;
}

}  // namespace talus::mpm
