#include "talus/runout/grid/fv2d_maxima.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace talus::runout {

void Fv2dMaxima::reset(std::size_t cells) {
  height.assign(cells, 0.0), speed.assign(cells, 0.0), pressure.assign(cells, 0.0);
  arrival.assign(cells, std::numeric_limits<double>::quiet_NaN());
  peak_speed = peak_height = peak_momentum = 0.0;
}

void Fv2dMaxima::observe(const Fv2dSolver& solver) {
  const double rho = solver.params().density;
  // This rank's rows (all of them on one rank); gather() completes the rest.
  const auto nx = static_cast<std::ptrdiff_t>(solver.terrain().shape().nx);
  const std::ptrdiff_t first = solver.first_row() * nx, end = solver.end_row() * nx;
  const double t = solver.state().time;
  double ps = peak_speed, ph = peak_height;
#pragma omp parallel for schedule(static) reduction(max : ps, ph)
  for (std::ptrdiff_t c = first; c < end; ++c) {
    const double hn = solver.normal_height(c), sp = solver.speed(c);
    height[c] = std::max(height[c], hn);
    speed[c] = std::max(speed[c], sp);
    pressure[c] = std::max(pressure[c], rho * sp * sp);
    if (hn > kArrivalHeight && std::isnan(arrival[c])) arrival[c] = t;
    ps = std::max(ps, sp), ph = std::max(ph, hn);
  }
  peak_speed = ps, peak_height = ph;
}

void Fv2dMaxima::gather(const Fv2dSolver& solver) {
  const auto& ranks = solver.ranks();
  if (ranks.size() == 1) return;
  std::vector<std::size_t> counts, offsets;
  solver.blocks().layout(solver.terrain().shape().nx, counts, offsets);
  for (auto* a : {&height, &speed, &pressure, &arrival})
    ranks.all_gather(a->data(), counts, offsets);
  peak_speed = ranks.max(peak_speed), peak_height = ranks.max(peak_height);
}

}  // namespace talus::runout
