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
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(height.size());
  const double t = solver.state().time;
  double ps = peak_speed, ph = peak_height;
#pragma omp parallel for schedule(static) reduction(max : ps, ph)
  for (std::ptrdiff_t c = 0; c < n; ++c) {
    const double hn = solver.normal_height(c), sp = solver.speed(c);
    height[c] = std::max(height[c], hn);
    speed[c] = std::max(speed[c], sp);
    pressure[c] = std::max(pressure[c], rho * sp * sp);
    if (hn > kArrivalHeight && std::isnan(arrival[c])) arrival[c] = t;
    ps = std::max(ps, sp), ph = std::max(ph, hn);
  }
  peak_speed = ps, peak_height = ph;
}

}  // namespace talus::runout
