#include "talus/runout/grid/two_phase_maxima.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace talus::runout {

void TwoPhaseMaxima::reset(std::size_t cells) {
  for (auto* v : {&height, &solid_height, &fluid_height, &solid_speed, &fluid_speed, &pressure,
                  &solid_pressure, &fluid_pressure})
    v->assign(cells, 0.0);
  arrival.assign(cells, std::numeric_limits<double>::quiet_NaN());
  peak_speed = peak_height = 0.0;
}

void TwoPhaseMaxima::observe(const TwoPhaseSolver& solver) {
  const auto& d = solver.params().drag;
  const auto& st = solver.state();
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(height.size());
  const double t = st.time;
  double ps = peak_speed, ph = peak_height;
#pragma omp parallel for schedule(static) reduction(max : ps, ph)
  for (std::ptrdiff_t c = 0; c < n; ++c) {
    const double hs = solver.normal_height(c, Phase::Solid);
    const double hf = solver.normal_height(c, Phase::Fluid);
    const double vs = solver.speed(c, Phase::Solid), vf = solver.speed(c, Phase::Fluid);
    const double h = hs + hf, depth = st.hs[c] + st.hf[c];
    const double alpha_s = depth > 0.0 ? st.hs[c] / depth : 0.0;
    const double p_solid = alpha_s * d.solid_density * vs * vs;
    const double p_fluid = (depth > 0.0 ? 1.0 - alpha_s : 0.0) * d.fluid_density * vf * vf;
    height[c] = std::max(height[c], h);
    solid_height[c] = std::max(solid_height[c], hs);
    fluid_height[c] = std::max(fluid_height[c], hf);
    solid_speed[c] = std::max(solid_speed[c], vs);
    fluid_speed[c] = std::max(fluid_speed[c], vf);
    solid_pressure[c] = std::max(solid_pressure[c], p_solid);
    fluid_pressure[c] = std::max(fluid_pressure[c], p_fluid);
    pressure[c] = std::max(pressure[c], p_solid + p_fluid);
    if (h > kArrivalHeight && std::isnan(arrival[c])) arrival[c] = t;
    ps = std::max({ps, vs, vf}), ph = std::max(ph, h);
  }
  peak_speed = ps, peak_height = ph;
}

}  // namespace talus::runout
