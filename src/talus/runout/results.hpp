#pragma once
// What a 1D runout run reports, as plain data for the output writers and for
// `talus compare` (flume.md "What a flume run must report"): the front along
// the path in time, the final deposit's surface profile, its tail, the run-up
// on the barrier and the arrival time there.
#include <limits>
#include <utility>
#include <vector>

#include "talus/runout/dan.hpp"

namespace talus::runout {

inline constexpr double kNotReached = std::numeric_limits<double>::quiet_NaN();

struct FrontSample {
  double time = 0, s = 0;  // path coordinate of the front boundary block
  double x = 0, y = 0;     // its bed point
};

// One boundary block of a deposit: its bed point, the depth normal to the bed
// and the free-surface point above it.
struct ProfilePoint {
  double s = 0, x_bed = 0, y_bed = 0, depth = 0, x_surface = 0, y_surface = 0;
};

struct RunUp {
  double elevation = kNotReached;            // highest bed elevation reached by the front (y, m)
  double s = kNotReached;                    // path coordinate of that point
  double distance_on_barrier = kNotReached;  // s - barrier start (m along the path)
  double time = kNotReached;                 // when it was reached (max during the run)
};

struct RunoutResults {
  std::vector<FrontSample> front;             // sampled at the series interval
  std::vector<ProfilePoint> deposit;          // state at the end of the run
  RunUp runup_max, runup_final;               // during the run / in the final deposit
  double tail_s = kNotReached;                // where the main deposit starts (see below)
  double tail_s_absolute = kNotReached;       // the last boundary block upstream
  double barrier_arrival_time = kNotReached;  // front passes barrier_start_s
  double rest_time = kNotReached;             // all blocks stopped
  double max_depth = 0, max_speed = 0;        // over the whole run
};

// Follows a run step by step. barrier_start_s: path coordinate where the
// barrier (the adverse slope) starts, NaN for a path without one; run-up is
// only counted beyond it. The main deposit starts at the first boundary block
// (from upstream) whose depth is at least tail_fraction of the deposit's
// largest depth, so that a thin layer stranded on the chute does not count.
class RunoutTracker {
 public:
  RunoutTracker(double barrier_start_s, double tail_fraction);
  void observe_step(const DanModel& model);  // every step: maxima, arrival
  void sample_front(const DanModel& model);  // at the series interval
  // Deposit, final run-up and tail from the model's current state.
  const RunoutResults& finish(const DanModel& model);
  const RunoutResults& results() const { return r_; }
  // Continues from a checkpoint: what the interrupted run had gathered.
  void restore(RunoutResults results) { r_ = std::move(results); }

 private:
  double barrier_s_, tail_fraction_;
  RunoutResults r_;
};

// The current surface profile: one point per boundary block.
std::vector<ProfilePoint> surface_profile(const DanModel& model);

}  // namespace talus::runout
