#pragma once
// The DAN time loop: advances a model to the end time (or until every block
// is at rest), feeds the tracker every step and calls the observers (series,
// snapshots, progress) at their intervals. Files are the observers' business.
#include <cstdint>
#include <vector>

#include "talus/runout/dan.hpp"
#include "talus/runout/results.hpp"

namespace talus::runout {

class DanObserver {
 public:
  virtual ~DanObserver() = default;
  virtual void on_series(const DanModel&) {}
  virtual void on_snapshot(const DanModel&) {}
  virtual void on_progress(double /*time*/, double /*end*/, double /*steps_per_s*/) {}
};

struct DanRunControl {
  double duration = 1.0;   // s
  double time_step = 0.0;  // s; 0 = from stable_time_step(courant) every step
  double courant = 0.5;
  double series_interval = 0.01;   // s; also the front sampling
  double snapshot_interval = 0.0;  // s; 0 = first and last only
  bool stop_at_rest = true;        // end early once every block has stopped
  double progress_seconds = 1.0;   // wall seconds between progress calls
};

struct DanRunStats {
  int64_t steps = 0;
  double wall_seconds = 0.0;
  bool stopped_at_rest = false;
};

DanRunStats run_dan(DanModel& model, const DanRunControl& control, RunoutTracker& tracker,
                    const std::vector<DanObserver*>& observers);

}  // namespace talus::runout
