#pragma once
// The reference for where a pile stops on a curved path: a point mass sliding
// along it from rest with Coulomb friction, the normal force including the
// centripetal term v^2 kappa (optional), integrated by RK4 with a 10 us step
// until it stops. Shared by the DAN and the 2D finite-volume tests.
#include <algorithm>
#include <cmath>

#include "talus/runout/path.hpp"

namespace talus::runout::reference {

inline double point_mass_stop(const RunoutPath& path, double s0, double tan_phi, double g,
                              bool centripetal = true) {
  double s = s0, v = 0;
  const double h = 1e-5;
  auto accel = [&](double s_, double v_) {
    const double th = path.angle(s_);
    const double kappa = centripetal ? path.curvature(s_) : 0.0;
    const double normal = std::max(0.0, g * std::cos(th) + v_ * v_ * kappa);
    return -g * std::sin(th) - normal * tan_phi;  // v >= 0 throughout
  };
  for (int k = 0; k < 10000000; ++k) {
    const double k1v = accel(s, v), k1s = v;
    const double k2v = accel(s + 0.5 * h * k1s, v + 0.5 * h * k1v), k2s = v + 0.5 * h * k1v;
    const double k3v = accel(s + 0.5 * h * k2s, v + 0.5 * h * k2v), k3s = v + 0.5 * h * k2v;
    const double k4v = accel(s + h * k3s, v + h * k3v), k4s = v + h * k3v;
    const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (vn <= 0) return s;
    s += h / 6 * (k1s + 2 * k2s + 2 * k3s + k4s);
    v = vn;
  }
  return s;
}

}  // namespace talus::runout::reference
