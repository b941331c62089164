#pragma once
// When outputs fall due, one rule for every method: at the multiples of the
// interval counted from t = 0 (a resumed run keeps the uninterrupted run's
// times), written at the first step that reaches one. Times come from the
// interval by multiplication, never by summing, so rounding never accumulates.
#include <cmath>
#include <limits>

namespace talus::run {

class OutputSchedule {
 public:
  // interval > 0: every interval; 0: first and last only; < 0: never.
  explicit OutputSchedule(double interval = -1.0) : interval_(interval) {}

  bool enabled() const { return interval_ >= 0.0; }
  bool periodic() const { return interval_ > 0.0; }
  double interval() const { return interval_; }

  // The first output time after t + tolerance (infinity when not periodic).
  // A time within 1e-9 intervals of a multiple counts as that multiple.
  double next_after(double t, double tolerance) const {
    if (!periodic()) return std::numeric_limits<double>::infinity();
    double k = std::floor(t / interval_ + 1e-9) + 1.0;
    while (k * interval_ <= t + tolerance) k += 1.0;
    return k * interval_;
  }

 private:
  double interval_;
};

}  // namespace talus::run
