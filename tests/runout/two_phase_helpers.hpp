#pragma once
// Small builders shared by the two-phase solver tests.
#include <algorithm>
#include <functional>
#include <vector>

#include "fv2d_helpers.hpp"
#include "talus/runout/grid/two_phase.hpp"

namespace talus::runout::testing {

// No friction, no viscosity, no drag: each phase alone is frictionless.
inline TwoPhaseParams two_phase_frictionless() {
  TwoPhaseParams p;
  p.pressure.mode = EarthPressureMode::Constant;
  p.pressure.constant = 1.0;
  p.shear_factor = 0.0;
  return p;
}

// A dry granular mass: no fluid density (gamma = 0, no buoyancy), fv2d's
// frictional law with Savage-Hutter's k between k_a and k_p.
inline TwoPhaseParams two_phase_granular(double phi_b_deg, double phi_i_deg) {
  TwoPhaseParams p;
  p.drag.fluid_density = 0.0;
  p.tan_basal_friction = std::tan(phi_b_deg * M_PI / 180.0);
  p.pressure.mode = EarthPressureMode::SavageHutter;
  p.pressure.phi_internal = phi_i_deg * M_PI / 180.0;
  p.pressure.tan_phi_basal = p.tan_basal_friction;
  return p;
}

// Runs to time `end` with CFL steps (or steps no longer than max_dt); calls
// check after every step.
inline int run_to(TwoPhaseSolver& s, double end,
                  const std::function<void(const TwoPhaseSolver&)>& check = {},
                  double max_dt = 1e300) {
  int steps = 0;
  while (s.state().time < end - 1e-12) {
    s.step(std::min({s.stable_time_step(), max_dt, end - s.state().time}));
    ++steps;
    if (check) check(s);
  }
  return steps;
}

}  // namespace talus::runout::testing
