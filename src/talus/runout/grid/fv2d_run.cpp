#include "talus/runout/grid/fv2d_run.hpp"

#include <algorithm>
#include <cmath>

#include "talus/core/progress.hpp"

namespace talus::runout {

void Fv2dMaxima::reset(std::size_t cells) {
  height.assign(cells, 0.0), speed.assign(cells, 0.0), pressure.assign(cells, 0.0);
  peak_speed = peak_height = 0.0;
}

void Fv2dMaxima::observe(const Fv2dSolver& solver) {
  const double rho = solver.params().density;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(height.size());
  double ps = peak_speed, ph = peak_height;
#pragma omp parallel for schedule(static) reduction(max : ps, ph)
  for (std::ptrdiff_t c = 0; c < n; ++c) {
    const double hn = solver.normal_height(c), sp = solver.speed(c);
    height[c] = std::max(height[c], hn);
    speed[c] = std::max(speed[c], sp);
    pressure[c] = std::max(pressure[c], rho * sp * sp);
    ps = std::max(ps, sp), ph = std::max(ph, hn);
  }
  peak_speed = ps, peak_height = ph;
}

Fv2dRunStats run_fv2d(Fv2dSolver& solver, const Fv2dRunControl& control, Fv2dMaxima& maxima,
                      const std::vector<Fv2dObserver*>& observers) {
  ProgressClock progress(control.progress_seconds);
  Fv2dRunStats stats;
  const double end = control.duration;
  const double eps = 1e-9 * std::max(1.0, end);
  maxima.reset(solver.terrain().shape().cells());
  maxima.observe(solver);
  double next_series = solver.state().time, last_series = -1.0;
  auto series = [&](bool force) {
    const double t = solver.state().time;
    if ((!force && t + eps < next_series) || t == last_series) return;
    last_series = t;
    for (auto* o : observers) o->on_series(solver);
    while (next_series <= t + eps) next_series += std::max(control.series_interval, 1e-12);
  };
  series(true);
  while (solver.state().time < end - eps) {
    const double t = solver.state().time;
    // Steps end on the series times, so the time series is sampled exactly.
    double dt = std::min({solver.stable_time_step(), control.max_time_step, end - t});
    if (next_series > t + eps) dt = std::min(dt, next_series - t);
    solver.step(dt);
    ++stats.steps;
    maxima.observe(solver);
    if (control.stop_at_rest && solver.at_rest()) {
      stats.stopped_at_rest = true;
      break;
    }
    series(false);
    if (progress.due())
      for (auto* o : observers)
        o->on_progress(solver.state().time, end, progress.rate(stats.steps));
  }
  series(true);
  stats.wall_seconds = progress.elapsed();
  for (auto* o : observers) o->on_progress(end, end, progress.rate(stats.steps));
  return stats;
}

}  // namespace talus::runout
