#pragma once
// What a hazard map needs from a 2D run: per cell, the maxima over the run of
// the flow height (bed-normal), the speed (bed-parallel) and the impact
// pressure rho |u|^2 (the "pressure" of hazard maps, as RAMMS reports it).
#include <vector>

#include "talus/runout/grid/fv2d.hpp"

namespace talus::runout {

struct Fv2dMaxima {
  std::vector<double> height, speed, pressure;  // per cell, over the whole run
  double peak_speed = 0.0, peak_height = 0.0;   // over all cells and times
  void reset(std::size_t cells);
  void observe(const Fv2dSolver& solver);
};

}  // namespace talus::runout
