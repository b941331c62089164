#include "talus/run/loop.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <limits>

#include "talus/core/error.hpp"

namespace talus::run {

RunLoop::RunLoop(Simulation& sim, std::vector<Observer*> observers)
    : sim_(sim), observers_(std::move(observers)) {}

void RunLoop::start(bool fresh) {
  sim_.start(fresh);
  schedules_ = sim_.schedules();
  end_time_ = sim_.end_time();
  const double t = sim_.time(), tol = sim_.tolerance();
  next_series_ = schedules_.series.next_after(t, tol);
  next_snapshot_ = schedules_.snapshots.next_after(t, tol);
  next_checkpoint_ = schedules_.checkpoints.next_after(t, tol);
  clock_ = ProgressClock(progress_seconds, sim_.steps());
  // A resumed run's start time was written by the interrupted run.
  if (fresh) {
    series();
    if (schedules_.snapshots.enabled()) {
      for (auto* o : observers_) o->on_snapshot();
      sim_.outputs().on_snapshot();
      last_snapshot_time_ = t;
    }
  }
  finished_ = sim_.stopped() || t >= end_time_ - tol;
  if (finished_) sim_.finish();
}

void RunLoop::flush() {
  for (auto* o : observers_) o->on_progress();
  sim_.outputs().on_progress();
}

void RunLoop::checkpoint() {
  if (sim_.time() != last_series_time_) series();
  for (auto* o : observers_) o->on_checkpoint();
  sim_.outputs().on_checkpoint();
}

void RunLoop::series() {
  for (auto* o : observers_) o->on_series();
  sim_.outputs().on_series();
  sim_.after_series();
  last_series_time_ = sim_.time();
  next_series_ = schedules_.series.next_after(last_series_time_, sim_.tolerance());
}

void RunLoop::outputs_due(bool last) {
  const double t = sim_.time(), tol = sim_.tolerance();
  bool series_now = false;
  if ((last || t >= next_series_ - tol) && t != last_series_time_) {
    series();
    series_now = true;
  }
  if (schedules_.snapshots.enabled() && (last || t >= next_snapshot_ - tol) &&
      t != last_snapshot_time_) {
    for (auto* o : observers_) o->on_snapshot();
    sim_.outputs().on_snapshot();
    last_snapshot_time_ = t;
    next_snapshot_ = schedules_.snapshots.next_after(t, tol);
  }
  if (t >= next_checkpoint_ - tol) {
    checkpoint_pending_ = true;
    next_checkpoint_ = schedules_.checkpoints.next_after(t, tol);
  }
  // Checkpoints fall on series rows: observers average over the interval since
  // their last row, and a resumed run must start that interval where the
  // uninterrupted run did. None at the end: the run is complete.
  if (checkpoint_pending_ && series_now && !last) {
    for (auto* o : observers_) o->on_checkpoint();
    sim_.outputs().on_checkpoint();
    checkpoint_pending_ = false;
  }
}

RunStats RunLoop::advance(double until, std::int64_t steps) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  RunStats done_here;
  const std::int64_t first = sim_.steps();
  const double tol = sim_.tolerance();
  while (!finished_) {
    const std::int64_t taken = sim_.steps() - first;
    if ((steps >= 0 && taken >= steps) || sim_.time() >= until - tol) break;
    double target = std::min({next_series_, next_checkpoint_, end_time_, until});
    if (schedules_.snapshots.periodic()) target = std::min(target, next_snapshot_);
    const std::int64_t before = sim_.steps();
    sim_.advance(target, tol,
                 steps >= 0 ? steps - taken : std::numeric_limits<std::int64_t>::max());
    // Every target lies ahead of the clock, so a call that takes no step is a
    // method that cannot advance: stop rather than spin.
    if (sim_.steps() == before && !sim_.stopped())
      throw RunError(fmt::format("t = {:.9g} s: the method took no step towards t = {:.9g} s",
                                 sim_.time(), target));
    const bool last = sim_.stopped() || sim_.time() >= end_time_ - tol;
    outputs_due(last);
    finished_ = last;
    if (finished_) sim_.finish();
    if (clock_.due(last)) {
      for (auto* o : observers_) o->on_progress();
      sim_.outputs().on_progress();
      if (progress)
        progress({sim_.time(), end_time_, clock_.rate(sim_.steps()), sim_.time_step(),
                  sim_.kinetic_energy()});
    }
  }
  done_here.steps = sim_.steps() - first;
  done_here.wall_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  done_here.stopped_early = sim_.stopped();
  total_.steps += done_here.steps;
  total_.wall_seconds += done_here.wall_seconds;
  total_.stopped_early = done_here.stopped_early;
  return done_here;
}

}  // namespace talus::run
