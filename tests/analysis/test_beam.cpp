// The 3-point beam fit (analysis/beam.hpp): Timoshenko's deflection
// Δz = F L³/(48 E I) + 3 F L (1 + ν)/(5 E A) (spec/membranes-and-jamming.md,
// Götz 2024 eq. 36) generated for a known modulus must give that modulus back.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "talus/analysis/beam.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {
namespace {

double timoshenko(double f, double e, double l, double b, double h, double nu) {
  const double i = b * h * h * h / 12.0, a = b * h;
  return f * l * l * l / (48.0 * e * i) + 3.0 * f * l * (1.0 + nu) / (5.0 * e * a);
}

TEST(BeamFit, RecoversTheModulusOfTimoshenkosDeflection) {
  // The source's example: E_b,eff 11.4 MPa on the 40 x 8 x 8 cm beam; with
  // ν_b = 0 the formula gives Δz(10 N) = 0.376 mm, the spec's "≈ 0.38 mm".
  const double l = 0.4, b = 0.08, h = 0.08, e = 11.4e6;
  EXPECT_NEAR(timoshenko(10.0, e, l, b, h, 0.0), 3.76e-4, 0.005e-3);
  for (double nu : {0.0, 0.3}) {
    std::vector<double> f, dz;
    for (int k = 0; k <= 10; ++k) {
      f.push_back(k);
      dz.push_back(2e-6 + timoshenko(k, e, l, b, h, nu));  // an offset does not matter
    }
    const BeamFit fit = fit_three_point(f, dz, l, b, h, nu);
    EXPECT_NEAR(fit.youngs_modulus, e, 1e-9 * e) << nu;
    EXPECT_NEAR(fit.effective_modulus, e / (1 - nu * nu), 1e-9 * e) << nu;
    EXPECT_NEAR(fit.intercept, 2e-6, 1e-15);
    EXPECT_NEAR(fit.r2, 1.0, 1e-12);
  }
}

TEST(BeamFit, ScatterLowersTheFitQuality) {
  const std::vector<double> f = {0, 1, 2, 3}, dz = {0, 1.2e-5, 1.8e-5, 3.1e-5};
  const BeamFit fit = fit_three_point(f, dz, 0.4, 0.08, 0.08, 0.3);
  EXPECT_LT(fit.r2, 0.99);
  EXPECT_GT(fit.r2, 0.9);
  // Least squares by hand: slope = S_fd / S_ff = 4.95e-5 / 5 m/N.
  EXPECT_NEAR(fit.slope, 9.9e-6, 1e-15);
}

TEST(BeamFit, RefusesWhatIsNoBendingCurve) {
  const std::vector<double> one = {1.0}, two = {1.0, 1.0}, up = {0.0, 1.0};
  EXPECT_THROW(fit_three_point(one, one, 0.4, 0.08, 0.08, 0.3), InputError);
  EXPECT_THROW(fit_three_point(two, up, 0.4, 0.08, 0.08, 0.3), InputError);
  const std::vector<double> down = {0.0, -1e-5};
  EXPECT_THROW(fit_three_point(up, down, 0.4, 0.08, 0.08, 0.3), InputError);
}

}  // namespace
}  // namespace talus::analysis
