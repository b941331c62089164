// Earth-pressure coefficients of the depth-averaged models (spec runout.md §1).
#include <gtest/gtest.h>

#include <cmath>

#include "talus/core/space.hpp"
#include "talus/runout/earth_pressure.hpp"

namespace talus::runout {
namespace {

TEST(EarthPressure, FlumeSandLimits) {
  // runout.md: phi_i = 30.9 deg, phi_b = 21.7 deg gives k_a = 0.674, k_p = 2.758
  // (three decimals: half a unit of the last place plus the rounding of the
  // inputs' tenth of a degree).
  const auto k = earth_pressure_limits(deg2rad(30.9), std::tan(deg2rad(21.7)));
  EXPECT_NEAR(k.active, 0.674, 1.5e-3);
  EXPECT_NEAR(k.passive, 2.758, 2.5e-3);
}

TEST(EarthPressure, RankineWithoutBasalFriction) {
  // tan(phi_b,mod) = 0: the formula reduces to Rankine (1 -/+ sin)/(1 +/- sin),
  // which runout.md quotes as 0.321 and 3.111.
  const double phi = deg2rad(30.9);
  const auto k = earth_pressure_limits(phi, 0.0);
  EXPECT_NEAR(k.active, (1 - std::sin(phi)) / (1 + std::sin(phi)), 1e-12);
  EXPECT_NEAR(k.passive, (1 + std::sin(phi)) / (1 - std::sin(phi)), 1e-12);
  EXPECT_NEAR(k.active, 0.321, 1e-3);
  EXPECT_NEAR(k.passive, 3.111, 1e-3);
}

TEST(EarthPressure, ClampedWhenBasalAngleExceedsInternal) {
  // phi_b,mod > phi_i: the root is clamped to zero, so k_a = k_p = 2/cos^2 - 1
  // (the value at phi_b,mod = phi_i), and no NaN comes out.
  const double phi = deg2rad(30.0);
  const auto k = earth_pressure_limits(phi, std::tan(deg2rad(40.0)));
  const double c2 = std::cos(phi) * std::cos(phi);
  EXPECT_DOUBLE_EQ(k.active, 2.0 / c2 - 1.0);
  EXPECT_DOUBLE_EQ(k.passive, 2.0 / c2 - 1.0);
  const auto at = earth_pressure_limits(phi, std::tan(phi));
  EXPECT_NEAR(at.active, k.active, 1e-7);
}

TEST(EarthPressure, HungrStrainLaw) {
  EarthPressure m;
  m.phi_internal = deg2rad(30.9);
  m.tan_phi_basal = std::tan(deg2rad(21.7));
  m.passive_strain = 0.05;
  const auto lim = earth_pressure_limits(m.phi_internal, m.tan_phi_basal);
  // Starts at rest (k = 1), inside [k_a, k_p].
  EXPECT_DOUBLE_EQ(initial_earth_pressure(m), 1.0);
  // A flat surface (dh/dx = 0): compression of 1 % raises k by (k_p - k_a)/5.
  const double k1 = update_earth_pressure(m, 1.0, -0.01, 0.0);
  EXPECT_NEAR(k1, 1.0 + (lim.passive - lim.active) * 0.2, 1e-12);
  // Large strains saturate at the limits.
  EXPECT_DOUBLE_EQ(update_earth_pressure(m, 1.0, -1.0, 0.0), lim.passive);
  EXPECT_DOUBLE_EQ(update_earth_pressure(m, 1.0, 1.0, 0.0), lim.active);
  // Savage-Hutter switching: active when stretching, passive when compressed.
  m.mode = EarthPressureMode::SavageHutter;
  EXPECT_DOUBLE_EQ(update_earth_pressure(m, 1.0, 1e-6, 0.0), lim.active);
  EXPECT_DOUBLE_EQ(update_earth_pressure(m, 1.0, -1e-6, 0.0), lim.passive);
  // The modified basal angle: a surface falling downstream (dh/dx < 0)
  // raises tan(phi_b,mod) = tan(phi_b) - lambda k dh/dx.
  const double dhdx = -0.2, k = 1.0;
  const auto mod = earth_pressure_limits(m.phi_internal, m.tan_phi_basal - 0.333 * k * dhdx);
  EXPECT_DOUBLE_EQ(update_earth_pressure(m, k, 1e-6, dhdx), mod.active);
}

}  // namespace
}  // namespace talus::runout
