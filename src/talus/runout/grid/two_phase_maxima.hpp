#pragma once
// What a hazard map of a two-phase run needs, per cell, over the whole run:
// the maxima of the mixture's and each phase's bed-normal height, of each
// phase's bed-parallel speed, and of the impact pressures: each phase's
// alpha_p rho_p |u_p|^2 (its share of the mixture's dynamic pressure; rho v^2
// of a pure phase) and the mixture's, their sum; and the arrival time, when
// the mixture's bed-normal height first exceeded kArrivalHeight (NaN where
// it never did; 0 in the release). As Fv2dMaxima for the single-phase model.
#include <vector>

#include "talus/runout/grid/two_phase.hpp"

namespace talus::runout {

struct TwoPhaseMaxima {
  static constexpr double kArrivalHeight = 0.01;  // m, as fv2d
  std::vector<double> height, solid_height, fluid_height;
  std::vector<double> solid_speed, fluid_speed;
  std::vector<double> pressure, solid_pressure, fluid_pressure;
  std::vector<double> arrival;                 // s; NaN: never reached
  double peak_speed = 0.0, peak_height = 0.0;  // over all cells, phases and times
  void reset(std::size_t cells);
  void observe(const TwoPhaseSolver& solver);
};

}  // namespace talus::runout
