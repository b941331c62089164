#pragma once
// What a hazard map needs from a 2D run: per cell, the maxima over the run of
// the flow height (bed-normal), the speed (bed-parallel) and the impact
// pressure rho |u|^2 (the "pressure" of hazard maps, as RAMMS reports it),
// and the arrival time: when the bed-normal height first exceeded
// kArrivalHeight (NaN where it never did; 0 in the release). The same 1 cm
// bounds the affected area in summary.json.
#include <vector>

#include "talus/runout/grid/fv2d.hpp"

namespace talus::runout {

struct Fv2dMaxima {
  static constexpr double kArrivalHeight = 0.01;  // m
  std::vector<double> height, speed, pressure;    // per cell, over the whole run
  std::vector<double> arrival;                    // s, per cell; NaN: never reached
  double peak_speed = 0.0, peak_height = 0.0;     // over all cells and times
  double peak_momentum = 0.0;  // of Fv2dSolver::momentum_sum, where a stop rule reads it
  void reset(std::size_t cells);
  // Takes the solver's state of this moment into the maxima, on this rank's
  // rows (Fv2dSolver::distribute).
  void observe(const Fv2dSolver& solver);
  // Completes the maps and the peaks on every rank of a distributed solver
  // (collective); nothing on one rank.
  void gather(const Fv2dSolver& solver);
};

}  // namespace talus::runout
