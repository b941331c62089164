#include "talus/dem/health.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "talus/core/error.hpp"

namespace talus::dem {

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
double wall_work(const DemSystem<D>& s) {
  double sum = 0.0;
  for (const auto& w : s.walls) sum += w.work;
  return sum;
}

template <int D>
EnergyBudget energy_budget(const DemSystem<D>& s) {
  return {available_energy(s), wall_work(s), s.removed_kinetic_energy};
}

template <int D>
void check_health(const DemRun<D>& run, const EnergyBudget& budget, double factor) {
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
  if (!(factor > 0.0)) return;
  const double put_in = std::max(0.0, wall_work(s) - budget.wall_work_at_start);
  const double gained = ke + (s.removed_kinetic_energy - budget.removed_at_start);
  if (gained <= factor * (budget.available + put_in)) return;
  const std::string removed =
      gained > ke ? fmt::format(" (with {:.4g} J carried out of the domain by removed particles)",
                                gained - ke)
                  : std::string();
  const std::string walls =
      put_in > 0.0
          ? fmt::format(" plus the work the moving walls have done since ({:.4g} J)", put_in)
          : std::string();
  throw RunError(fmt::format(
      "t = {:.6g} s: kinetic energy {:.4g} J{} exceeds {} times the energy available at the "
      "start ({:.4g} J){}: the run is unstable. Reduce the time step (now {:.4g} s, critical "
      "{:.4g} s)",
      s.time, gained, removed, factor, budget.available, walls, s.dt,
      run.system.critical_time_step));
}

template double available_energy<2>(const DemSystem<2>&);
template double available_energy<3>(const DemSystem<3>&);
template double wall_work<2>(const DemSystem<2>&);
template double wall_work<3>(const DemSystem<3>&);
template EnergyBudget energy_budget<2>(const DemSystem<2>&);
template EnergyBudget energy_budget<3>(const DemSystem<3>&);
template void check_health<2>(const DemRun<2>&, const EnergyBudget&, double);
template void check_health<3>(const DemRun<3>&, const EnergyBudget&, double);

}  // namespace talus::dem
