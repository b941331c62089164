#pragma once
// The closures of the two-phase (solid-fluid) depth-averaged model of van den
// Bout et al. (2021, seed 001 §2.2.4-2.3.3, after Pudasaini 2012 and Pudasaini
// & Mergili 2019) for unstructured material (f_sc = f_fc = 0): the mixture's
// viscosity, a grain's settling velocity, the generalised drag between the
// phases and the virtual mass. Pure functions of the local state, so the
// solver (grid/two_phase.hpp) and the unit tests call the same code.
//
// Units: SI throughout; a drag coefficient C is such that the force per unit
// volume on the solid is C (u_f - u_s) |u_f - u_s|^(J - 1), equal and opposite
// on the fluid.

namespace talus::runout::two_phase {

// Julien & O'Brien (1997), seed eq. 72: the fluid's dynamic viscosity
// eta = alpha e^(beta alpha_s) (Pa s) at solid fraction alpha_s.
double julien_obrien_viscosity(double alpha, double beta, double solid_fraction);

// Zanke (1977), seed eq. 73: the settling velocity of a grain of diameter d
// (m) in a fluid of viscosity eta,
//   U_T = 10 eta / (d rho_f) (sqrt(1 + 0.01 (rho_s - rho_f) rho_f g d^3 / eta^2) - 1).
// 0 for a grain no denser than the fluid.
double zanke_settling_velocity(double d, double rho_s, double rho_f, double eta, double g);

// Richardson & Zaki's exponent M(Re_p) in Pitman & Le's (2005) piecewise form:
// 4.65 below Re_p = 0.2, 4.4 Re_p^-0.03 to 1, 4.4 Re_p^-0.1 to 500, 2.4 above
// (between 2.4 and 4.65, as the seed says).
double richardson_zaki_exponent(double particle_reynolds);

struct DragParams {
  double solid_density = 2700.0;  // rho_s, kg/m^3
  double fluid_density = 1000.0;  // rho_f, kg/m^3
  double gravity = 9.81;
  double grain_diameter = 1e-3;   // d, m (Zanke's settling velocity, Re_p)
  double mixing_exponent = 1.0;   // m in P = alpha_s^m (Pudasaini 2012)
  double smoothing_speed = 10.0;  // K in S_p, m/s ("K ~ 10 m/s", seed eq. 34)
  int exponent = 1;               // J: 1 linear drag, 2 quadratic
};

// Pudasaini's generalised drag coefficient (seed eq. 31, its unstructured
// part; eqs. 32-34, 64), for solid fraction alpha_s, fluid fraction alpha_f
// and fluid viscosity eta:
//   C = alpha_s alpha_f (rho_s - rho_f) g / [U_T (P F + (1 - P) G) + S_p]^J
//   F = gamma / 180 (alpha_f / alpha_s)^3 Re_p,  G = alpha_f^(M(Re_p) - 1),
//   S_p = (P / alpha_s + (1 - P) / alpha_f) K,  P = alpha_s^m,
//   Re_p = rho_f d U_T / (alpha_f eta),  gamma = rho_f / rho_s.
// 0 where either phase is absent (no interface) or the solid is no denser.
double drag_coefficient(const DragParams& p, double alpha_s, double alpha_f, double eta);

// The virtual-mass coefficient C_VM = (1 + 2 alpha_s) / (2 alpha_f) (seed
// eq. 65), singular as alpha_f -> 0.
double virtual_mass_coefficient(double alpha_s, double alpha_f);

// What virtual mass leaves of a change of the phases' relative velocity. With
// the force rho_f alpha_s C_VM (a_f - a_s) per unit volume on the solid (and
// its opposite on the fluid, seed eq. 35), accelerations a_s, a_f that other
// forces would give become a_s', a_f' with the same mixture momentum and
//   a_f' - a_s' = r (a_f - a_s),  r = 1 / (1 + C_VM (gamma + alpha_s / alpha_f)).
// Written as 2 alpha_f^2 / (2 alpha_f^2 + (1 + 2 alpha_s)(gamma alpha_f + alpha_s)),
// it is finite where C_VM is not: r -> 0 (the phases move together) as
// alpha_f -> 0, which is the guard the singularity needs. 1 without solid.
double virtual_mass_relative_factor(double alpha_s, double alpha_f, double gamma);

}  // namespace talus::runout::two_phase
