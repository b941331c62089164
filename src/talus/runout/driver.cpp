#include "talus/runout/driver.hpp"

#include <algorithm>
#include <cmath>

#include "talus/core/progress.hpp"

namespace talus::runout {

DanRunStats run_dan(DanModel& model, const DanRunControl& control, RunoutTracker& tracker,
                    const std::vector<DanObserver*>& observers) {
  ProgressClock progress(control.progress_seconds);
  DanRunStats stats;
  const double end = control.duration;
  // Output times are multiples of the intervals; a step never jumps past one
  // by more than the step itself (the sample is taken after that step).
  double next_series = model.blocks().time, next_snapshot = model.blocks().time;
  double last_series = -1.0, last_snapshot = -1.0;  // times already written
  auto emit = [&](bool force) {
    const double t = model.blocks().time;
    const double eps = 1e-9 * std::max(1.0, end);
    if ((t + eps >= next_series || force) && t != last_series) {
      last_series = t;
      tracker.sample_front(model);
      for (auto* o : observers) o->on_series(model);
      while (next_series <= t + eps) next_series += std::max(control.series_interval, 1e-12);
    }
    const bool snap_due = control.snapshot_interval > 0 && t + eps >= next_snapshot;
    if ((snap_due || force) && t != last_snapshot) {
      last_snapshot = t;
      for (auto* o : observers) o->on_snapshot(model);
      while (control.snapshot_interval > 0 && next_snapshot <= t + eps)
        next_snapshot += control.snapshot_interval;
    }
  };
  tracker.observe_step(model);
  emit(true);
  while (model.blocks().time < end - 1e-12) {
    double dt = control.time_step > 0 ? control.time_step : model.stable_time_step(control.courant);
    dt = std::min(dt, end - model.blocks().time);
    model.step(dt);
    ++stats.steps;
    tracker.observe_step(model);
    if (control.stop_at_rest && model.at_rest()) {
      stats.stopped_at_rest = true;
      break;
    }
    emit(false);
    if (progress.due())
      for (auto* o : observers)
        o->on_progress(model.blocks().time, end, progress.rate(stats.steps));
  }
  emit(true);
  tracker.finish(model);
  stats.wall_seconds = progress.elapsed();
  for (auto* o : observers) o->on_progress(end, end, progress.rate(stats.steps));
  return stats;
}

}  // namespace talus::runout
