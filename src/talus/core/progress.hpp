#pragma once
// Wall-clock pacing shared by the solver loops: a loop asks once per step (or
// per block of steps) whether a progress report is due, so the observers are
// called every `interval` wall seconds however fast or slow the steps are.

#include <chrono>
#include <cstdint>

namespace talus {

class ProgressClock {
 public:
  // `first_step`: the step count the loop starts from (a resumed run does not
  // count the steps before it in its rate).
  explicit ProgressClock(double interval_seconds, int64_t first_step = 0)
      : interval_(interval_seconds), first_step_(first_step), start_(Clock::now()), last_(start_) {}

  // True when `interval` wall seconds have passed since the last report (or
  // `force`); restarts the interval then.
  bool due(bool force = false) {
    const auto now = Clock::now();
    if (!force && seconds(last_, now) < interval_) return false;
    last_ = now;
    return true;
  }

  double elapsed() const { return seconds(start_, Clock::now()); }

  // Steps per wall second since the start (0 before any time has passed).
  double rate(int64_t step) const {
    const double s = elapsed();
    return s > 0 ? static_cast<double>(step - first_step_) / s : 0.0;
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  }
  double interval_;
  int64_t first_step_;
  Clock::time_point start_, last_;
};

}  // namespace talus
