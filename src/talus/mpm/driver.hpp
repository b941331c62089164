#pragma once
// The MPM run loop: advances a solver to the end time with the CFL step and
// calls the observers (series, snapshots, progress) at their intervals of
// simulated time. Health checks: non-finite velocities and points leaving the
// grid are the solver's, energy blow-up the loop's (health.hpp); each stops
// the run with a RunError.
#include <cstdint>
#include <vector>

#include "talus/mpm/solver.hpp"

namespace talus::mpm {

template <int D>
class MpmObserver {
 public:
  virtual ~MpmObserver() = default;
  virtual void on_series(const Solver<D>&) {}
  virtual void on_snapshot(const Solver<D>&) {}
  virtual void on_checkpoint(const Solver<D>&) {}
  virtual void on_progress(double /*time*/, double /*end*/, double /*steps_per_s*/) {}
};

struct MpmRunControl {
  double duration = 0.0;
  double series_interval = 0.0;      // 0: every step
  double snapshot_interval = 0.0;    // 0: first and last only; < 0: none
  double checkpoint_interval = 0.0;  // 0: none (never at the end: the run is complete)
  double progress_seconds = 1.0;
  // Stop when the kinetic energy exceeds this many times the energy the start
  // state could release (health.hpp); <= 0: never. Not checked while a rigid
  // body is driven (it feeds energy in).
  double ke_blowup_factor = 10.0;
};

struct MpmRunStats {
  std::int64_t steps = 0;
  double wall_seconds = 0.0;
};

// fresh = false continues a run restored from a checkpoint: no outputs at its
// start time (the interrupted run wrote them).
template <int D>
MpmRunStats run_mpm(Solver<D>& solver, const MpmRunControl& control,
                    const std::vector<MpmObserver<D>*>& observers, bool fresh = true);

// Metrics of the point cloud: the furthest point along +x (with half a point
// spacing added by the caller if wanted) and the highest point along -gravity.
template <int D>
double front_x(const Particles<D>& p);
template <int D>
double top(const Particles<D>& p, const typename Space<D>::Vec& gravity);

}  // namespace talus::mpm
