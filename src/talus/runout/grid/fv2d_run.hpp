#pragma once
// The 2D time loop and what a hazard map needs from it: per cell, the maxima
// over the run of the flow height (bed-normal), the speed (bed-parallel) and
// the impact pressure rho |u|^2 (the "pressure" of hazard maps, as RAMMS
// reports it), and the final deposit. Files are the observers' business.
#include <cstdint>
#include <vector>

#include "talus/runout/grid/fv2d.hpp"

namespace talus::runout {

struct Fv2dMaxima {
  std::vector<double> height, speed, pressure;  // per cell, over the whole run
  double peak_speed = 0.0, peak_height = 0.0;   // over all cells and times
  void reset(std::size_t cells);
  void observe(const Fv2dSolver& solver);
};

class Fv2dObserver {
 public:
  virtual ~Fv2dObserver() = default;
  virtual void on_series(const Fv2dSolver&) {}
  virtual void on_progress(double /*time*/, double /*end*/, double /*steps_per_s*/) {}
};

struct Fv2dRunControl {
  double duration = 10.0;         // s
  double max_time_step = 0.1;     // s; caps the CFL step (and steps of a still pile)
  double series_interval = 0.1;   // s
  bool stop_at_rest = true;       // end once no cell moves
  double progress_seconds = 1.0;  // wall seconds between progress calls
};

struct Fv2dRunStats {
  int64_t steps = 0;
  double wall_seconds = 0.0;
  bool stopped_at_rest = false;
};

// Runs to control.duration (or rest). `maxima` is reset and filled.
Fv2dRunStats run_fv2d(Fv2dSolver& solver, const Fv2dRunControl& control, Fv2dMaxima& maxima,
                      const std::vector<Fv2dObserver*>& observers);

}  // namespace talus::runout
