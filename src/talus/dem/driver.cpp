#include "talus/dem/driver.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "talus/core/error.hpp"
#include "talus/core/progress.hpp"

namespace talus::dem {

RunControl make_run_control(const DemScenario& sc, double dt) {
  RunControl c;
  c.duration = sc.run.duration;
  auto steps = [dt](double interval, int64_t fallback) {
    return interval > 0.0 ? std::max<int64_t>(1, std::llround(interval / dt)) : fallback;
  };
  c.series_every = steps(sc.output.series_interval, 100);
  c.snapshot_every = sc.output.write_snapshots ? steps(sc.output.snapshot_interval, 0) : -1;
  c.checkpoint_every = steps(sc.output.checkpoint_interval, 0);
  // Checkpoints fall on series rows: observers average forces over the
  // interval since their last row, and a resumed run must start that interval
  // where the uninterrupted run did.
  if (c.checkpoint_every > 0 && c.series_every > 0)
    c.checkpoint_every = std::max<int64_t>(1, std::llround(static_cast<double>(c.checkpoint_every) /
                                                           static_cast<double>(c.series_every))) *
                         c.series_every;
  c.ke_blowup_factor = sc.run.ke_blowup_factor;
  if (sc.beam && sc.beam->bending_friction) {
    FrictionChange f{sc.beam->bending_start, *sc.beam->bending_friction, {}};
    // The grains' materials: those the particle sources name.
    for (std::size_t k = 0; k < sc.materials.size(); ++k)
      for (const auto& src : sc.sources)
        if (src.material == sc.materials[k].name) {
          f.materials.push_back(static_cast<int>(k));
          break;
        }
    c.friction_change = f;
  }
  return c;
}

namespace {

// Energy the particles could at most turn into motion: their kinetic energy
// plus their potential energy above the lowest particle or wall point.
template <int D>
double available_energy(const DemSystem<D>& s) {
  const auto& p = s.particles;
  const double g = s.gravity.norm();
  double m = 0.0, dmean = 0.0, pe = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    m += p.m[i];
    dmean += 2.0 * p.r[i];
  }
  dmean /= std::max<std::size_t>(1, p.size());
  if (g > 0.0) {
    // Heights along -gravity; wall bounds that are infinite along it are skipped.
    const auto up = (-s.gravity / g).eval();
    double floor = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < p.size(); ++i) floor = std::min(floor, up.dot(p.x[i]) - p.r[i]);
    for (const auto& w : s.walls) {
      Vec3 lo, hi;
      w.bounds(lo, hi);
      for (const Vec3& c : {lo, hi}) {
        const double h = up.dot(Space<D>::from3(c));
        if (std::isfinite(h)) floor = std::min(floor, h);
      }
    }
    for (std::size_t i = 0; i < p.size(); ++i) pe += p.m[i] * g * (up.dot(p.x[i]) - floor);
  }
  const double ke = kinetic_energy(p) + rotational_energy(p);
  // Never below the energy of the whole mass moving at 1 m/s or lifted by one diameter.
  return std::max({ke + pe, 0.5 * m, m * g * dmean});
}

template <int D>
void check_health(const DemRun<D>& run, double e_avail, double factor) {
  const auto& s = run.system;
  const double ke = kinetic_energy(s.particles);
  if (!std::isfinite(ke)) {
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      if (!s.particles.v[i].allFinite())
        throw RunError(fmt::format(
            "t = {:.6g} s: particle {} has a non-finite velocity. Check the time step (now {:.4g} "
            "s, critical {:.4g} s) and the material constants",
            s.time, s.particles.id[i], s.dt, run.system.critical_time_step));
    throw RunError(fmt::format("t = {:.6g} s: kinetic energy is not finite", s.time));
  }
  for (const auto& m : s.membranes)
    for (std::size_t i = 0; i < m.body.v.size(); ++i)
      if (!m.body.v[i].allFinite())
        throw RunError(fmt::format(
            "t = {:.6g} s: membrane '{}' particle {} has a non-finite velocity. Check the time "
            "step (now {:.4g} s, critical {:.4g} s) and the membrane constants",
            s.time, m.name, i, s.dt, run.system.critical_time_step));
  bool walls_move = false;
  for (const auto& w : s.walls) walls_move = walls_move || w.moves();
  if (factor > 0.0 && !walls_move && ke > factor * e_avail)
    throw RunError(fmt::format(
        "t = {:.6g} s: kinetic energy {:.4g} J exceeds {} times the energy available at the "
        "start ({:.4g} J): the run is unstable. Reduce the time step (now {:.4g} s, critical "
        "{:.4g} s)",
        s.time, ke, factor, e_avail, s.dt, run.system.critical_time_step));
}

int64_t next_multiple(int64_t step, int64_t every) {
  return every > 0 ? (step / every + 1) * every : std::numeric_limits<int64_t>::max();
}

// The stepper keeps its contact coefficients from construction on, so a new
// one takes the changed materials; the state (forces and contact histories)
// lives in the system and carries over as it does from a checkpoint.
template <int D>
void change_friction(DemRun<D>& run, const FrictionChange& f) {
  for (int k : f.materials) run.system.materials[k].friction = f.friction;
  run.stepper = make_stepper(run.system);
}

}  // namespace

template <int D>
RunStats run_dem(DemRun<D>& run, const RunControl& c, const std::vector<DemObserver<D>*>& obs,
                 bool fresh) {
  auto& s = run.system;
  const int64_t end = std::llround(c.duration / s.dt);
  const double e_avail = available_energy(s);
  const int64_t change_step = c.friction_change ? std::llround(c.friction_change->time / s.dt)
                                                : std::numeric_limits<int64_t>::max();
  // Due already (a resumed run past it, or a change at t = 0): before anything.
  const bool changed_before = s.step >= change_step;
  if (changed_before) change_friction(run, *c.friction_change);
  if (fresh) {
    run.stepper->prime();
    for (auto* o : obs) o->on_series(run);
    if (c.snapshot_every >= 0)
      for (auto* o : obs) o->on_snapshot(run);
  } else {
    run.stepper->resume();
  }
  const int64_t start = s.step;
  ProgressClock progress(c.progress_seconds, start);
  const int64_t health_every = std::max<int64_t>(1, std::min<int64_t>(1000, end / 100 + 1));
  while (s.step < end) {
    int64_t next = std::min(
        {end, next_multiple(s.step, c.series_every), next_multiple(s.step, c.snapshot_every),
         next_multiple(s.step, c.checkpoint_every), next_multiple(s.step, health_every)});
    if (s.step < change_step) next = std::min(next, change_step);
    run.stepper->advance(next - s.step);
    if (s.step == change_step && !changed_before) {
      change_friction(run, *c.friction_change);
      run.stepper->resume();
    }
    check_health(run, e_avail, c.ke_blowup_factor);
    const bool last = s.step == end;
    if (s.step % c.series_every == 0 || last) {
      for (auto* o : obs) o->on_series(run);
      // Before a checkpoint: a resumed run starts its first interval with
      // fresh extremes, as the uninterrupted run does (checkpoints fall on rows).
      for (auto& w : s.walls) w.reset_force_extremes();
    }
    if (c.snapshot_every >= 0 && ((c.snapshot_every > 0 && s.step % c.snapshot_every == 0) || last))
      for (auto* o : obs) o->on_snapshot(run);
    if (c.checkpoint_every > 0 && s.step % c.checkpoint_every == 0 && !last)
      for (auto* o : obs) o->on_checkpoint(run);
    if (progress.due(last))
      for (auto* o : obs) o->on_progress(s.time, end * s.dt, progress.rate(s.step));
  }
  RunStats st;
  st.steps = s.step - start;
  st.wall_seconds = progress.elapsed();
  return st;
}

template RunStats run_dem<2>(DemRun<2>&, const RunControl&, const std::vector<DemObserver<2>*>&,
                             bool);
template RunStats run_dem<3>(DemRun<3>&, const RunControl&, const std::vector<DemObserver<3>*>&,
                             bool);

}  // namespace talus::dem
