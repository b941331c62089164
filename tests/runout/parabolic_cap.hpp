#pragma once
// Savage & Hutter's (1989) parabolic cap as the 2D solvers' tests set it up
// (test_fv2d_analytic.cpp, test_two_phase_limits.cpp), on a strip one cell
// wide along x. On a plane of inclination zeta with bed friction delta and a
// constant K a parabolic pile stays parabolic: along the slope its centre
// moves with g (sin - tan cos) and its half-length is lambda L0 with
// lambda'' = 2 K g cos h0 / (L0^2 lambda^2). Over the horizontal plane (the
// solvers' frame) the pile is the same parabola with the vertical thickness
// H = h / cos(zeta) and horizontal half-length lambda L0 cos(zeta); its second
// moment about the centre is (lambda L0 cos)^2 / 5. u0 downslope at the start
// keeps all of it moving downslope (one sign of friction) over the 1.5 s the
// tests compare.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "fv2d_helpers.hpp"
#include "point_mass.hpp"
#include "talus/core/space.hpp"

namespace talus::runout::reference {

struct ParabolicCap {
  double zeta = deg2rad(35), delta = deg2rad(25), phi_internal = deg2rad(35);
  double h0 = 0.1, L0 = 1.0, u0 = 1.0;  // bed-normal height, half-length, speed (m, m/s)
  double xc0 = 1.5;                     // horizontal position of the centre at the start
  double g = 9.81;

  double k() const { return earth_pressure_limits(phi_internal, std::tan(delta)).active; }
  double cos_zeta() const { return std::cos(zeta); }
  GridShape grid(double dx) const {
    return {static_cast<std::size_t>(std::lround(9.0 / dx)), 1, dx, dx};
  }
  std::vector<double> bed(const GridShape& grid) const {
    return testing::sample(grid, [&](double x, double) { return -std::tan(zeta) * x; });
  }
  // The vertical thickness at the start.
  std::vector<double> depth(const GridShape& grid) const {
    const double c = cos_zeta();
    return testing::sample(grid, [&](double x, double) {
      const double r = (x - xc0) / (L0 * c);
      return std::max(0.0, h0 / c * (1.0 - r * r));
    });
  }
  // The exact spreading ratio and (horizontal) centre at time t.
  double lambda(double t) const {
    return savage_hutter_lambda(2 * k() * g * cos_zeta() * h0 / (L0 * L0), t);
  }
  double centre(double t) const {
    const double a = g * (std::sin(zeta) - std::tan(delta) * cos_zeta());
    return xc0 + (u0 * t + 0.5 * a * t * t) * cos_zeta();
  }

  // A computed profile's centre of mass and its lambda from the second
  // moment; v0: the released volume per unit width.
  struct Moments {
    double centre, lambda;
  };
  Moments moments(const std::vector<double>& h, double dx, double v0) const {
    double m = 0.0, mx = 0.0;
    for (std::size_t i = 0; i < h.size(); ++i) m += h[i], mx += h[i] * (i + 0.5) * dx;
    const double xm = mx / m;
    double m2 = 0.0;
    for (std::size_t i = 0; i < h.size(); ++i) {
      const double x = (i + 0.5) * dx;
      m2 += h[i] * dx * (x - xm) * (x - xm);
    }
    return {xm, std::sqrt(5.0 * m2 / v0) / (L0 * cos_zeta())};
  }
};

}  // namespace talus::runout::reference
