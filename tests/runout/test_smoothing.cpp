// Momentum-conserving velocity smoothing (spec runout.md §1, Kuen eq. 2.40).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "talus/runout/smoothing.hpp"

namespace talus::runout {
namespace {

double momentum(const std::vector<double>& m, const std::vector<double>& v) {
  double p = 0;
  for (std::size_t i = 0; i < m.size(); ++i) p += m[i] * v[i];
  return p;
}

TEST(Smoothing, ConservesMomentumExactly) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t n = 5 + trial * 7;
    std::vector<double> x(n), m(n), v(n), scratch;
    double pos = 0;
    for (std::size_t i = 0; i < n; ++i) {
      pos += 1e-4 + u(rng) * 0.05;  // some blocks nearly squeezed together
      x[i] = pos;
      m[i] = 0.1 + 10 * u(rng);
      v[i] = 4 * u(rng) - 1;
    }
    const double p0 = momentum(m, v);
    const double vmin = *std::min_element(v.begin(), v.end());
    const double vmax = *std::max_element(v.begin(), v.end());
    SmoothingParams sp;
    smooth_velocities(sp, x, m, 1e-3, v, scratch);
    // Every exchange leaves one block and enters its neighbour: only
    // round-off (a few ulps of the sum of |m v|) may change the total.
    double scale = 0;
    for (std::size_t i = 0; i < n; ++i) scale += std::abs(m[i] * v[i]);
    EXPECT_NEAR(momentum(m, v), p0, 1e-14 * scale * n);
    // Convex combinations: no new extremes.
    for (double vi : v) {
      EXPECT_GE(vi, vmin - 1e-12);
      EXPECT_LE(vi, vmax + 1e-12);
    }
  }
}

TEST(Smoothing, EqualMassesReduceToDanFormula) {
  // Equal masses and uniform spacing: interior blocks follow eq. 2.40 exactly,
  // v' = (w v_{i-1} + v_i + w v_{i+1}) / (2w + 1) with w = c_s (dx_avg = dx),
  // for the blocks whose both neighbours are interior too.
  const std::size_t n = 8;
  std::vector<double> x(n), m(n, 2.0), v(n), scratch;
  for (std::size_t i = 0; i < n; ++i) x[i] = 0.1 * i, v[i] = (i * i) % 5;
  const std::vector<double> v0 = v;
  SmoothingParams sp;
  sp.c_inner = 0.3;  // strong, so a wrong formula shows
  smooth_velocities(sp, x, m, sp.reference_time_step, v, scratch);
  const double w = 0.3;
  for (std::size_t i = 2; i + 2 < n; ++i)
    EXPECT_NEAR(v[i], (w * v0[i - 1] + v0[i] + w * v0[i + 1]) / (2 * w + 1), 1e-14) << i;
}

TEST(Smoothing, ScalesWithTimeStep) {
  // The weights are a rate: half the step, half the (small) change.
  const std::size_t n = 6;
  std::vector<double> x(n), m(n, 1.0), a(n), b(n), scratch;
  for (std::size_t i = 0; i < n; ++i) x[i] = 0.1 * i, a[i] = b[i] = (i % 2) ? 1.0 : 0.0;
  SmoothingParams sp;
  smooth_velocities(sp, x, m, 1e-3, a, scratch);
  smooth_velocities(sp, x, m, 0.5e-3, b, scratch);
  const double da = a[2] - 0.0, db = b[2] - 0.0;
  EXPECT_GT(da, 0.0);
  EXPECT_NEAR(db / da, 0.5, 0.02);  // 2 % from the denominators 1 + 2w
}

}  // namespace
}  // namespace talus::runout
