#pragma once
// A grid model (fv2d, two-phase) on a flume path instead of rasters: the
// flume's bed extruded across its width (path_terrain.hpp) and its release
// (the triangle behind the gate, or a polygon in the path's plane) as the
// released depth; and the 1D results a flume comparison reads (front along
// the path, run-up on the barrier, deposit and tail; results.hpp) taken from
// the grid's first row, so that `talus compare` puts the grid models beside
// DAN, DEM and MPM.
#include <vector>

#include "talus/runout/path.hpp"
#include "talus/runout/results.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::runout {

// Fills scenario.grid (shape, elevation, release depth, corner) from its
// path and release; grid.on_path, cell_size and rows must be set. Throws
// InputError for a path the extrusion cannot take.
void grid_from_path(RunoutScenario& scenario);

// The 1D results of a grid run on a path: sampled from the bed-normal depth
// of the grid's first row (the rows of a straight channel between walls stay
// alike). As RunoutTracker for DAN.
class PathGridTracker {
 public:
  explicit PathGridTracker(const RunoutScenario& scenario);
  // Every step: maxima and the front's arrival and run-up on the barrier.
  // depth: bed-normal depth per cell; speed: largest speed of the step.
  void observe_step(double time, const std::vector<double>& depth, double speed);
  void sample_front(double time, const std::vector<double>& depth);  // at the series interval
  // Deposit, final run-up and tail; at_rest: the run ended at rest.
  const RunoutResults& finish(double time, const std::vector<double>& depth, bool at_rest);
  const RunoutResults& results() const { return r_; }
  const RunoutPath& path() const { return path_; }
  double final_front_s() const { return final_front_; }  // set by finish
  // Continues from a checkpoint: what the interrupted run had gathered.
  void restore(RunoutResults results) { r_ = std::move(results); }

 private:
  double front_s(const std::vector<double>& depth) const;
  RunoutPath path_;
  const GridSpec& grid_;
  double barrier_s_, tail_fraction_;
  RunoutResults r_;
  double final_front_ = kNotReached;
};

}  // namespace talus::runout
