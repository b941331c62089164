#pragma once
// Earth-pressure coefficient k = sigma_xx / sigma_zz of a depth-averaged flow
// (Savage & Hutter 1989 limits with Hungr's 2008 modification; spec
// runout.md §1, Kuen 2011 eqs. 2.37-2.38).
namespace talus::runout {

struct EarthPressureLimits {
  double active = 1.0, passive = 1.0;
};

// k_{a/p} = 2 (1 -/+ sqrt(1 - cos^2(phi_i) (1 + tan^2(phi_b)))) / cos^2(phi_i) - 1.
// The root needs phi_b <= phi_i: a larger (modified) basal angle is clamped to
// phi_i, where k_a = k_p. tan_phi_b may be negative (the sign drops out).
EarthPressureLimits earth_pressure_limits(double phi_internal, double tan_phi_basal);

enum class EarthPressureMode {
  Hungr,         // k moves between k_a and k_p with the block's strain
  SavageHutter,  // k_a while the block stretches, k_p while it is compressed
  Constant       // k fixed (k = 1: hydrostatic; k = 0: no pressure)
};

struct EarthPressure {
  EarthPressureMode mode = EarthPressureMode::Hungr;
  double phi_internal = 0.0;       // rad
  double tan_phi_basal = 0.0;      // of the bed, before the modification
  double lambda = 0.333;           // Hungr (2008), empirical
  double passive_strain = 0.05;    // strain that takes k from k_a to k_p (Hungr mode)
  double constant = 1.0;           // k (Constant mode) and the initial k (Hungr mode)
  bool modify_basal_angle = true;  // tan(phi_b,mod) = tan(phi_b) - lambda k dh/dx
};

// The coefficient of a mass block after a strain increment d_strain (> 0
// stretching) with the current k and free-surface gradient dh_dx (along the
// path). Hungr mode: k -= (k_p - k_a) / passive_strain * d_strain, clamped to
// [k_a, k_p]. See docs/validation.md "Runout" for why this stiffness.
double update_earth_pressure(const EarthPressure& model, double k, double d_strain, double dh_dx);

// The initial coefficient of every block.
double initial_earth_pressure(const EarthPressure& model);

}  // namespace talus::runout
