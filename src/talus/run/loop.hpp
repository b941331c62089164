#pragma once
// The one run loop: owns simulated time, the output schedule, checkpoints and
// progress for every method. It can run to the end, or be advanced by a number
// of steps or to a time and entered again (the Python API and MPI build on
// that); outputs fall on the same times however it is driven.
#include <cstdint>
#include <functional>
#include <vector>

#include "talus/core/progress.hpp"
#include "talus/run/simulation.hpp"

namespace talus::run {

struct RunStats {
  std::int64_t steps = 0;      // taken by this loop (a resumed run's own)
  double wall_seconds = 0.0;   // in the time-stepping loop only
  bool stopped_early = false;  // the method ended before its end time
};

struct Progress {
  double time, end, steps_per_s, time_step, kinetic_energy;
};

class RunLoop {
 public:
  // `observers`: the experiments' observers, called before the method's own
  // outputs (so that their files are flushed when the checkpoint is written).
  RunLoop(Simulation& sim, std::vector<Observer*> observers);

  // Before the first advance: a fresh run writes its outputs at the start time.
  void start(bool fresh);
  // Runs to the end (or until the method stops).
  RunStats run() { return advance(end_time_, -1); }
  // Up to `steps` steps (<0: no limit), not past `until`. Returns what this call did.
  RunStats advance(double until, std::int64_t steps);
  bool done() const { return finished_; }
  // Flushes every observer's files (what on_progress flushes), for a run
  // its caller ends before the end.
  void flush();
  // Writes a checkpoint now, between two advances, as at a scheduled one: on
  // a series row, which is written first unless there is one at this time.
  void checkpoint();
  // Everything this loop has done so far.
  const RunStats& stats() const { return total_; }

  std::function<void(const Progress&)> progress;  // every progress_seconds of wall time
  double progress_seconds = 1.0;

 private:
  void outputs_due(bool last);
  void series();

  Simulation& sim_;
  std::vector<Observer*> observers_;
  Schedules schedules_;
  double end_time_ = 0.0;
  double next_series_ = 0.0, next_snapshot_ = 0.0, next_checkpoint_ = 0.0;
  bool checkpoint_pending_ = false;
  double last_series_time_ = -1.0, last_snapshot_time_ = -1.0;
  bool finished_ = false;
  RunStats total_;
  ProgressClock clock_{1.0};
};

}  // namespace talus::run
