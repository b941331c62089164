#pragma once
// Small builders shared by the 2D solver tests.
#include <cmath>
#include <functional>
#include <vector>

#include "talus/runout/grid/fv2d.hpp"

namespace talus::runout::testing {

// Cell centres at x = (i + 1/2) dx, y = (j + 1/2) dy.
inline std::vector<double> sample(const GridShape& g,
                                  const std::function<double(double, double)>& f) {
  std::vector<double> out(g.cells());
  for (std::size_t j = 0; j < g.ny; ++j)
    for (std::size_t i = 0; i < g.nx; ++i)
      out[g.index(i, j)] = f((i + 0.5) * g.dx, (j + 0.5) * g.dy);
  return out;
}

inline Fv2dParams frictionless() {
  Fv2dParams p;
  p.rheology.tan_friction = 0.0;
  p.pressure.mode = EarthPressureMode::Constant;
  p.pressure.constant = 1.0;
  return p;
}

inline Fv2dParams frictional(double phi_b_deg, double phi_i_deg) {
  Fv2dParams p;
  p.rheology.law = RheologyLaws::index_of(FrictionalRheology::name);
  p.rheology.tan_friction = std::tan(phi_b_deg * M_PI / 180.0);
  p.pressure.mode = EarthPressureMode::SavageHutter;
  p.pressure.phi_internal = phi_i_deg * M_PI / 180.0;
  p.pressure.tan_phi_basal = p.rheology.tan_friction;
  return p;
}

// Runs to time `end` with CFL steps; calls check after every step.
inline int run_to(Fv2dSolver& s, double end,
                  const std::function<void(const Fv2dSolver&)>& check = {}) {
  int steps = 0;
  while (s.state().time < end - 1e-12) {
    s.step(std::min(s.stable_time_step(), end - s.state().time));
    ++steps;
    if (check) check(s);
  }
  return steps;
}

}  // namespace talus::runout::testing
