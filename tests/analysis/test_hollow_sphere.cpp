// Götz 2024 eq. (33) as the spec corrects it (analysis/hollow_sphere.hpp):
// its limits, and the value of the bundled scenario's geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "talus/analysis/hollow_sphere.hpp"

namespace talus::analysis {
namespace {

TEST(HollowSphereContinuum, Limits) {
  // An incompressible shell on a rigid core passes nothing on (the exact
  // zero of 2 nu - 1), nor does a shell of no thickness (x = 1).
  EXPECT_NEAR(continuum_object_pressure(9e4, 0.04, 0.01, 0.5), 0.0, 1e-9);
  EXPECT_NEAR(continuum_object_pressure(9e4, 0.01, 0.01, 0.3), 0.0, 1e-9);
  // nu = 0, thick shell: 2 p_vac (3 p_vac at a rigid inclusion, less the
  // membrane's p_vac); at x = 1e9 the rest is 6 / x relative.
  EXPECT_NEAR(continuum_object_pressure(1.0, 1e3, 1.0, 0.0), 2.0, 1e-8);
}

TEST(HollowSphereContinuum, MatchesLameSolution) {
  // From u = A r + B / r^2, u(a) = 0, sigma_rr(b) = -p: the core carries
  // p (3K + 4G) / (3K + 4G a^3 / b^3); the membrane takes p back.
  const double E = 1e8, nu = 0.254, p = 9e4, a = 0.01, b = 0.04;
  const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  const double core = p * (3 * K + 4 * G) / (3 * K + 4 * G * std::pow(a / b, 3));
  EXPECT_NEAR(continuum_object_pressure(p, b, a, nu), core - p, 1e-9 * p);
  // The bundled scenario: x = 64, nu = 0.254: 0.763 p_vac = 68.7 kPa.
  EXPECT_NEAR(continuum_object_pressure(p, b, a, nu), 68676.5, 0.1);
}

}  // namespace
}  // namespace talus::analysis
