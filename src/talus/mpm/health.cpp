#include "talus/mpm/health.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "talus/core/error.hpp"
#include "talus/core/space.hpp"

namespace talus::mpm {

namespace {

// sigma : C^-1 : sigma / 2 per unit volume: p^2 / (2K) + J2 / (2G).
double elastic_energy_density(const Material& m, const Mat3& stress) {
  const double p = stress.trace() / 3.0, j = j2(stress);
  return std::visit(
      [&](const auto& model) {
        using T = std::decay_t<decltype(model)>;
        if constexpr (std::is_same_v<T, NewtonianFluid>)
          return p * p / (2.0 * model.bulk);
        else
          return p * p / (2.0 * model.k.bulk) + j / (2.0 * model.k.shear);
      },
      m);
}

}  // namespace

double dissipative_dilatancy_limit(double phi) {
  return std::asin(DruckerPrager::alpha(phi) / 3.0);
}

template <int D>
double total_kinetic_energy(const Solver<D>& s) {
  double e = kinetic_energy(s.particles);
  for (const auto& m : s.membranes)
    for (std::size_t i = 0; i < m.x.size(); ++i) e += 0.5 * m.mass[i] * m.v[i].squaredNorm();
  return e;
}

template <int D>
double available_energy(const Solver<D>& s) {
  using Vec = typename Space<D>::Vec;
  const Vec g = s.gravity();
  // The grid corner furthest along gravity.
  Vec low;
  for (int d = 0; d < D; ++d) low[d] = g[d] > 0.0 ? s.grid.hi[d] : s.grid.lo[d];
  double e = total_kinetic_energy(s);
  const auto& p = s.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    e += p.mass[i] * g.dot(low - p.x[i]);
    e += p.volume[i] * elastic_energy_density(s.materials[p.material[i]], p.state[i].stress);
  }
  for (const auto& m : s.membranes)
    for (std::size_t i = 0; i < m.x.size(); ++i) e += m.mass[i] * g.dot(low - m.x[i]);
  return e;
}

template <int D>
double rigid_work(const Solver<D>& s) {
  double w = 0.0;
  for (const auto& r : s.rigid_bodies) w += r.work;
  return w;
}

template <int D>
EnergyBudget energy_budget(const Solver<D>& s) {
  return {available_energy(s), rigid_work(s)};
}

template <int D>
void check_energy(const Solver<D>& s, const EnergyBudget& budget, double factor) {
  if (factor <= 0.0) return;
  const double ke = total_kinetic_energy(s);
  const double put_in = std::max(0.0, rigid_work(s) - budget.rigid_work_at_start);
  const double available = budget.available + put_in;
  if (std::isfinite(ke) && ke <= factor * available) return;
  const std::string bodies =
      put_in > 0.0 ? fmt::format(", plus {:.4g} J of work the rigid bodies have done since", put_in)
                   : std::string();
  std::string hint;
  for (const auto& m : s.materials)
    if (const auto* dp = std::get_if<DruckerPrager>(&m);
        dp && dp->psi > dissipative_dilatancy_limit(dp->phi))
      hint = fmt::format(
          "; a Drucker-Prager dilatancy angle of {:.3g} deg is above {:.3g} deg, where the "
          "plastic potential sqrt(J2) + 3 I1 sin(psi) makes plastic flow under compression "
          "release energy (use a smaller dilatancy_angle or model = \"mohr_coulomb\")",
          rad2deg(dp->psi), rad2deg(dissipative_dilatancy_limit(dp->phi)));
  throw RunError(fmt::format(
      "t = {:.6g} s: kinetic energy {:.4g} J exceeds {} times the energy the run could release "
      "from its start ({:.4g} J: kinetic, elastic, and potential down to the grid's lowest "
      "corner{}): the run is unstable. Check the time step (last {:.4g} s; [run] cfl) and the "
      "material constants{}",
      s.time, ke, factor, budget.available, bodies, s.last_dt, hint));
}

template double total_kinetic_energy<2>(const Solver<2>&);
template double total_kinetic_energy<3>(const Solver<3>&);
template double available_energy<2>(const Solver<2>&);
template double available_energy<3>(const Solver<3>&);
template double rigid_work<2>(const Solver<2>&);
template double rigid_work<3>(const Solver<3>&);
template EnergyBudget energy_budget<2>(const Solver<2>&);
template EnergyBudget energy_budget<3>(const Solver<3>&);
template void check_energy<2>(const Solver<2>&, const EnergyBudget&, double);
template void check_energy<3>(const Solver<3>&, const EnergyBudget&, double);

}  // namespace talus::mpm
