#pragma once
// Reference solutions shared by the DAN and the 2D finite-volume tests.
//
// point_mass_stop: where a pile stops on a curved path: a point mass sliding
// along it from rest with Coulomb friction, the normal force including the
// centripetal term v^2 kappa (optional), integrated by RK4 with a 10 us step
// until it stops.
//
// savage_hutter_lambda: the spreading ratio lambda(T) of the Savage-Hutter
// parabolic cap, lambda'' = a / lambda^2, lambda(0) = 1, lambda'(0) = 0
// (spec runout.md), by RK4 with a fine step.
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

inline double savage_hutter_lambda(double a, double T, double step = 1e-5) {
  double lam = 1, dlam = 0;
  auto f = [&](double l) { return a / (l * l); };
  for (int k = 0; k < static_cast<int>(T / step + 0.5); ++k) {
    const double a1 = f(lam), b1 = dlam;
    const double a2 = f(lam + 0.5 * step * b1), b2 = dlam + 0.5 * step * a1;
    const double a3 = f(lam + 0.5 * step * b2), b3 = dlam + 0.5 * step * a2;
    const double a4 = f(lam + step * b3), b4 = dlam + step * a3;
    lam += step / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
    dlam += step / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
  }
  return lam;
}

}  // namespace talus::runout::reference
