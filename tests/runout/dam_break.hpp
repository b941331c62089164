#pragma once
// The dam break on an inclined plane with Coulomb friction (Mangeney, Heinrich
// & Roche 2000), which for a horizontal frictionless bed is Ritter's (1892),
// and the front of a computed depth profile, as both runout models' front
// tests use them.
//
// Along the plane (x downslope from the dam, bed-normal depth h, earth
// pressure k = 1), with c0 = sqrt(g cos(theta) h0) and the deceleration
// m = g (cos(theta) tan(delta) - sin(theta)) (< 0: the reservoir slides):
//   h = (2 c0 - x / t - m t / 2)^2 / (9 g cos(theta))
//   for -c0 t - m t^2 / 2 <= x <= 2 c0 t - m t^2 / 2,
// valid while everything moves downslope (one sign of friction).
#include <cmath>
#include <cstddef>
#include <vector>

namespace talus::runout::reference {

struct DamBreak {
  double h0 = 0.1;     // reservoir depth, bed-normal (m)
  double theta = 0.0;  // plane inclination (rad)
  double delta = 0.0;  // bed friction angle (rad)
  double g = 9.81;

  double c0() const { return std::sqrt(g * std::cos(theta) * h0); }
  double deceleration() const { return g * (std::cos(theta) * std::tan(delta) - std::sin(theta)); }
  // Where the exact depth falls through eps at time t: the exact front
  // 2 c0 t - m t^2 / 2 less 3 t sqrt(g cos(theta) eps).
  double depth_crossing(double eps, double t) const {
    return 2.0 * c0() * t - 0.5 * deceleration() * t * t -
           3.0 * t * std::sqrt(g * std::cos(theta) * eps);
  }
};

// Ritter (1892): h = (2 c0 - x / t)^2 / (9 g) for -c0 t <= x <= 2 c0 t (dam
// at x = 0, reservoir of depth h0 at x < 0, horizontal frictionless bed).
inline double ritter_depth(double x, double t, double h0, double g = 9.81) {
  const double c0 = std::sqrt(g * h0);
  if (x <= -c0 * t) return h0;
  if (x >= 2.0 * c0 * t) return 0.0;
  const double a = 2.0 * c0 - x / t;
  return a * a / (9.0 * g);
}

// The front of a depth profile given at increasing positions: the farthest
// point where the depth, linear between the samples, exceeds eps.
inline double front_at_depth(const std::vector<double>& x, const std::vector<double>& depth,
                             double eps) {
  for (std::size_t k = depth.size(); k-- > 0;) {
    if (depth[k] <= eps) continue;
    if (k + 1 == depth.size()) return x[k];
    return x[k] + (x[k + 1] - x[k]) * (depth[k] - eps) / (depth[k] - depth[k + 1]);
  }
  return x.empty() ? 0.0 : x.front();
}

// The order of convergence observed over two halvings of the cell size, from
// the errors at the coarsest and at the finest size.
inline double observed_order(double coarse, double fine) {
  return 0.5 * std::log2(std::abs(coarse) / std::abs(fine));
}

}  // namespace talus::runout::reference
