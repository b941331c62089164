// The 4-point beam's analysis (analysis/beam_four_point.hpp, Götz 2024 §5.3
// and appendix B): stress and strain agree with an elastic Euler–Bernoulli
// beam, E_b is the slope of the small-strain part, and Y_b lies where the
// curvature of σ(ε) turns from negative to positive.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "talus/analysis/beam_four_point.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {
namespace {

TEST(FourPointBeam, StressAndStrainOfAnElasticBeamGiveItsModulus) {
  // The textbook midspan deflection of a simply supported beam under two
  // symmetric loads P at a from the supports, P a (3L² - 4a²) / (24 E I),
  // with a = L/3 and P = F/2: for the source's 40 x 4 x 8 cm beam, E = 20 MPa,
  // F = 30 N, σ/ε must be E. (The source's eq. 63 reads twice this Δz for
  // the total F; its eqs. 64-65, which talus uses, agree with the textbook.)
  const double L = 0.4, t = 0.04, h = 0.08, E = 2e7, F = 30.0;
  const double I = t * h * h * h / 12.0, P = 0.5 * F, a = L / 3.0;
  const double dz = P * a * (3 * L * L - 4 * a * a) / (24.0 * E * I);
  const double sigma = four_point_stress(F, L, h, t);
  const double eps = four_point_strain(dz, L, h);
  EXPECT_NEAR(sigma / eps, E, 1e-9 * E);
  // σ is the bending moment between the rods, P a, over the section modulus t h² / 6.
  EXPECT_NEAR(sigma, P * a / (t * h * h / 6.0), 1e-9 * sigma);
}

TEST(FourPointBeam, SmallStrainFitIsTheSlopeBelowTheLimit) {
  std::vector<double> eps, sig;
  for (int i = 0; i <= 100; ++i) {
    eps.push_back(1e-4 * i);
    // Linear at 15 MPa up to 0.002, then much softer: only the first part counts.
    const double e = eps.back();
    sig.push_back(e <= 0.002 ? 1.5e7 * e : 3e4 + 1e6 * (e - 0.002));
  }
  const SmallStrainFit fit = fit_small_strain(eps, sig, 0.002);
  EXPECT_NEAR(fit.modulus, 1.5e7, 1e-6 * 1.5e7);
  EXPECT_EQ(fit.points, 20);  // 1e-4 .. 2e-3 (ε = 0 carries no slope)
  EXPECT_NEAR(fit.r2, 1.0, 1e-12);
  EXPECT_THROW(fit_small_strain(std::vector<double>{0.001, 0.01}, std::vector<double>{1, 2}, 0.002),
               InputError);
}

// σ = E ε - B ε² + C ε³: concave below ε* = B / (3C), convex above.
std::vector<double> cubic(const std::vector<double>& eps, double e_star) {
  const double E = 1e7, C = 2e8, B = 3 * C * e_star;
  std::vector<double> s;
  for (double e : eps) s.push_back(E * e - B * e * e + C * e * e * e);
  return s;
}

TEST(FourPointBeam, YieldIsWhereTheCurvatureTurnsPositive) {
  std::vector<double> eps;
  for (int i = 0; i <= 4000; ++i) eps.push_back(0.08 * i / 4000.0);
  const auto sig = cubic(eps, 0.02);
  const YieldPoint y = yield_from_curvature(eps, sig, 0.002);
  ASSERT_TRUE(y.found);
  // A Gaussian keeps a linear second derivative, and central differences of
  // a quadratic are exact: the crossing is exact but for the kernel's cutoff
  // at 4 widths, on which samples of this even spacing fall (measured 1.7e-6
  // off); the smoothed σ there is σ, since it differs by width² σ'' / 2
  // (measured 9e-5 relative off).
  EXPECT_NEAR(y.strain, 0.02, 1e-5);
  EXPECT_NEAR(y.stress, cubic({0.02}, 0.02)[0], 2e-4 * y.stress);
}

TEST(FourPointBeam, YieldSurvivesNoise) {
  std::vector<double> eps;
  for (int i = 0; i <= 8000; ++i) eps.push_back(0.08 * i / 8000.0);
  auto sig = cubic(eps, 0.03);
  // Deterministic noise of ±2 % of the curve's top (a beam's force jitters).
  const double top = sig.back();
  for (std::size_t i = 0; i < sig.size(); ++i)
    sig[i] += 0.02 * top * std::sin(12.9898 * static_cast<double>(i) * 78.233);
  const YieldPoint y = yield_from_curvature(eps, sig, 0.004);
  ASSERT_TRUE(y.found);
  EXPECT_NEAR(y.strain, 0.03, 0.001);  // a quarter of the smoothing width
}

TEST(FourPointBeam, NoYieldOnACurveThatOnlyBends) {
  std::vector<double> eps, sig;
  for (int i = 0; i <= 2000; ++i) {
    eps.push_back(0.08 * i / 2000.0);
    sig.push_back(5e4 * (1.0 - std::exp(-eps.back() / 0.01)));  // concave everywhere
  }
  EXPECT_FALSE(yield_from_curvature(eps, sig, 0.002).found);
}

}  // namespace
}  // namespace talus::analysis
