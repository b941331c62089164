#include "talus/mpm/driver.hpp"

#include <algorithm>
#include <cmath>

#include "talus/core/progress.hpp"
#include "talus/mpm/health.hpp"

namespace talus::mpm {

template <int D>
double front_x(const Particles<D>& p) {
  double x = -1e300;
  for (const auto& xi : p.x) x = std::max(x, xi[0]);
  return x;
}

template <int D>
double top(const Particles<D>& p, const typename Space<D>::Vec& gravity) {
  const double g = gravity.norm();
  const auto up = g > 0 ? (-gravity / g).eval() : Space<D>::Vec::Unit(D - 1).eval();
  double t = -1e300;
  for (const auto& xi : p.x) t = std::max(t, up.dot(xi));
  return t;
}

template <int D>
MpmRunStats run_mpm(Solver<D>& s, const MpmRunControl& c, const std::vector<MpmObserver<D>*>& obs,
                    bool fresh) {
  ProgressClock progress(c.progress_seconds, s.steps);
  if (fresh) {
    for (auto* o : obs) o->on_series(s);
    if (c.snapshot_interval >= 0.0)
      for (auto* o : obs) o->on_snapshot(s);
  }
  const std::int64_t start = s.steps;
  const double blowup = drives_energy_in(s) ? 0.0 : c.ke_blowup_factor;
  const double available = blowup > 0.0 ? available_energy(s) : 0.0;
  // Next output times are counted in intervals from t = 0, so rounding of the
  // variable step never accumulates.
  auto next_after = [&](double interval) {
    return interval > 0.0 ? (std::floor(s.time / interval + 1e-9) + 1.0) * interval : 0.0;
  };
  double next_series = next_after(c.series_interval);
  double next_snapshot = next_after(c.snapshot_interval);
  double next_checkpoint = next_after(c.checkpoint_interval);
  while (s.time < c.duration * (1.0 - 1e-12)) {
    double dt = s.time_step();
    // Land exactly on the end time.
    if (s.time + dt > c.duration) dt = c.duration - s.time;
    s.step(dt);
    const bool last = s.time >= c.duration * (1.0 - 1e-12);
    // Every 10th step: an O(n) sum beside a step of many O(n) passes.
    if (blowup > 0.0 && (s.steps % 10 == 0 || last)) check_energy(s, available, blowup);
    if (last || s.time >= next_series) {
      for (auto* o : obs) o->on_series(s);
      next_series = next_after(c.series_interval);
    }
    if (c.snapshot_interval >= 0.0 &&
        (last || (c.snapshot_interval > 0.0 && s.time >= next_snapshot))) {
      for (auto* o : obs) o->on_snapshot(s);
      next_snapshot = next_after(c.snapshot_interval);
    }
    // After the outputs of this time, so that a resumed run keeps them.
    if (c.checkpoint_interval > 0.0 && !last && s.time >= next_checkpoint) {
      for (auto* o : obs) o->on_checkpoint(s);
      next_checkpoint = next_after(c.checkpoint_interval);
    }
    if (progress.due(last))
      for (auto* o : obs) o->on_progress(s.time, c.duration, progress.rate(s.steps));
  }
  MpmRunStats st;
  st.steps = s.steps - start;
  st.wall_seconds = progress.elapsed();
  return st;
}

template MpmRunStats run_mpm<2>(Solver<2>&, const MpmRunControl&,
                                const std::vector<MpmObserver<2>*>&, bool);
template MpmRunStats run_mpm<3>(Solver<3>&, const MpmRunControl&,
                                const std::vector<MpmObserver<3>*>&, bool);
template double front_x<2>(const Particles<2>&);
template double front_x<3>(const Particles<3>&);
template double top<2>(const Particles<2>&, const Space<2>::Vec&);
template double top<3>(const Particles<3>&, const Space<3>::Vec&);

}  // namespace talus::mpm
