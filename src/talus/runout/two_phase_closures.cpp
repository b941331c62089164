#include "talus/runout/two_phase_closures.hpp"

#include <cmath>

namespace talus::runout::two_phase {

double julien_obrien_viscosity(double alpha, double beta, double solid_fraction) {
  return alpha * std::exp(beta * solid_fraction);
}

double zanke_settling_velocity(double d, double rho_s, double rho_f, double eta, double g) {
  if (!(rho_s > rho_f) || !(eta > 0.0) || !(d > 0.0)) return 0.0;
  const double x = 0.01 * (rho_s - rho_f) * rho_f * g * d * d * d / (eta * eta);
  // sqrt(1 + x) - 1 written as x / (sqrt(1 + x) + 1): no cancellation for
  // small grains in viscous fluid (x << 1, Stokes' regime).
  return 10.0 * eta / (d * rho_f) * x / (std::sqrt(1.0 + x) + 1.0);
}

double richardson_zaki_exponent(double re) {
  if (re < 0.2) return 4.65;
  if (re < 1.0) return 4.4 * std::pow(re, -0.03);
  if (re < 500.0) return 4.4 * std::pow(re, -0.1);
  return 2.4;
}

double drag_coefficient(const DragParams& p, double alpha_s, double alpha_f, double eta) {
  if (!(alpha_s > 0.0) || !(alpha_f > 0.0) || !(p.solid_density > p.fluid_density)) return 0.0;
  const double rho_s = p.solid_density, rho_f = p.fluid_density;
  const double u_t = zanke_settling_velocity(p.grain_diameter, rho_s, rho_f, eta, p.gravity);
  const double re = eta > 0.0 ? rho_f * p.grain_diameter * u_t / (alpha_f * eta) : 0.0;
  const double gamma = rho_f / rho_s;
  const double ratio = alpha_f / alpha_s;
  const double f = gamma / 180.0 * ratio * ratio * ratio * re;
  const double g = std::pow(alpha_f, richardson_zaki_exponent(re) - 1.0);
  const double big_p = p.mixing_exponent == 1.0 ? alpha_s : std::pow(alpha_s, p.mixing_exponent);
  const double s_p = (big_p / alpha_s + (1.0 - big_p) / alpha_f) * p.smoothing_speed;
  const double denominator = u_t * (big_p * f + (1.0 - big_p) * g) + s_p;
  const double scale = p.exponent == 2 ? denominator * denominator : denominator;
  return alpha_s * alpha_f * (rho_s - rho_f) * p.gravity / scale;
}

double virtual_mass_coefficient(double alpha_s, double alpha_f) {
  return 0.5 * (1.0 + 2.0 * alpha_s) / alpha_f;
}

double virtual_mass_relative_factor(double alpha_s, double alpha_f, double gamma) {
  if (!(alpha_s > 0.0)) return 1.0;
  const double a2 = 2.0 * alpha_f * alpha_f;
  return a2 / (a2 + (1.0 + 2.0 * alpha_s) * (gamma * alpha_f + alpha_s));
}

}  // namespace talus::runout::two_phase
