// DAN against analytic solutions (spec runout.md "Verification"): the sliding
// block, the Savage-Hutter parabolic cap, the Ritter dam break, and mass
// conservation.
#include <gtest/gtest.h>

#include <cmath>

#include "point_mass.hpp"
#include "talus/core/space.hpp"
#include "talus/runout/dan.hpp"
#include "talus/runout/release.hpp"

namespace talus::runout {
namespace {

constexpr double g = 9.81;

DanParams frictional(double phi_b_deg, double k) {
  DanParams p;
  p.density = 1600;
  p.gravity = g;
  p.rheology.law = RheologyLaws::index_of(FrictionalRheology::name);
  p.rheology.tan_friction = std::tan(deg2rad(phi_b_deg));
  p.pressure.mode = EarthPressureMode::Constant;
  p.pressure.constant = k;
  p.smoothing.enabled = false;  // a numerical device; the analytic cases need none
  return p;
}

// An incline of angle theta from (0, height) down to y = 0, then a flat to x_end.
RunoutPath incline_then_flat(double theta, double height, double x_end, double smoothing) {
  const double x_foot = height / std::tan(theta);
  return path_from_profile({{0, height}, {x_foot, 0}, {x_end, 0}}, {1, 1, 1}, smoothing, 1e-3);
}

TEST(DanVerification, SlidingBlockAcceleratesAsPointMass) {
  // k = 0: every boundary block is a point mass with a = g (sin - cos tan phi_b).
  const double theta = deg2rad(35), phi = 20;
  DanModel model(incline_then_flat(theta, 2.0, 8.0, 0.2), frictional(phi, 0.0),
                 blocks_from_depth(incline_then_flat(theta, 2.0, 8.0, 0.2), 0.1, 0.3, 11,
                                   [](double) { return 0.05; }));
  const double a = g * (std::sin(theta) - std::cos(theta) * std::tan(deg2rad(phi)));
  const double dt = 1e-3;
  for (int k = 0; k < 400; ++k) model.step(dt);  // 0.4 s, still on the incline
  ASSERT_LT(model.blocks().s.back(), 2.0 / std::sin(theta) - 0.2);
  for (std::size_t i = 0; i < model.size(); ++i) {
    // v = a t exactly for constant acceleration (round-off only); the
    // semi-implicit position update sums dt * v_k = a dt^2 k over the steps:
    // s = s0 + a t^2 / 2 + a t dt / 2, also exact.
    EXPECT_NEAR(model.blocks().v[i], a * 0.4, 1e-9);
    EXPECT_NEAR(model.blocks().s[i], 0.1 + 0.02 * i + 0.5 * a * (0.16 + 0.4 * dt), 1e-9);
  }
}

TEST(DanVerification, SlidingBlockStopsOnEnergyLine) {
  const double theta = deg2rad(30), phi = 20, height = 1.0;
  const auto path = incline_then_flat(theta, height, 10.0, 0.3);
  for (bool centripetal : {false, true}) {
    auto params = frictional(phi, 1.0);
    params.centripetal = centripetal;
    // A short pile (5 cm long, 1 cm deep, hydrostatic k = 1): with k = 0 the
    // boundary blocks would be independent point masses and the rear one,
    // starting higher, would overtake the front one on the run-out. Its
    // centre of mass follows the point mass up to the pile's own spreading,
    // so the tolerance is half the pile's length.
    const double length = 0.05, tol = 0.5 * length;
    DanModel model(path, params,
                   blocks_from_depth(path, 0.0, length, 11, [](double) { return 0.01; }));
    auto centre = [&] {
      double ms = 0, m = 0;
      for (std::size_t i = 0; i < model.size(); ++i)
        ms += model.node_mass(i) * model.blocks().s[i], m += model.node_mass(i);
      return ms / m;
    };
    const double s0 = centre();
    for (int k = 0; k < 20000 && (k == 0 || !model.at_rest()); ++k) model.step(1e-3);
    ASSERT_TRUE(model.at_rest());
    const double s_stop = centre();
    // Reference: a point mass from the same start integrated with RK4.
    EXPECT_NEAR(s_stop,
                reference::point_mass_stop(path, s0, std::tan(deg2rad(phi)), g, centripetal), tol);
    if (!centripetal) {
      // Without the curvature term friction works mu g dx: the block stops
      // where the energy line from its start meets the bed.
      const Vec2 p = path.point(s_stop), start = path.point(s0);
      EXPECT_NEAR(p.x() - start.x(), (start.y() - p.y()) / std::tan(deg2rad(phi)), tol);
    }
  }
}

TEST(DanVerification, SavageHutterParabolicCap) {
  // Savage & Hutter (1989): on a plane of inclination zeta with bed friction
  // delta and constant K, a parabolic pile stays parabolic with
  //   x_c'' = g (sin zeta - tan delta cos zeta),
  //   lambda'' = 2 K g cos zeta h0 / (L0^2 lambda^2), lambda(0) = 1, lambda'(0) = 0,
  // and material points at xi0 move to x_c + lambda xi0. The initial 1 m/s
  // keeps the whole pile moving downslope (friction of one sign) for 1.5 s,
  // which the loop checks at the rear block.
  const double zeta = deg2rad(35), delta = 25, h0 = 0.1, L0 = 1.0, u0 = 1.0;
  const double K = earth_pressure_limits(deg2rad(35), std::tan(deg2rad(delta))).active;
  const auto path = path_from_profile({{0, 20}, {20 / std::tan(zeta), 0}}, {1, 1}, 0, 1e-2);
  const double xc0 = 3.0;
  const std::size_t n = 201;
  DanModel model(
      path, frictional(delta, K),
      blocks_from_depth(
          path, xc0 - L0, xc0 + L0, n,
          [&](double s) { return h0 * std::max(0.0, 1 - (s - xc0) * (s - xc0) / (L0 * L0)); },
          [&](double) { return u0; }));
  const double T = 1.5, dt = 5e-4;
  for (int k = 0; k < static_cast<int>(T / dt + 0.5); ++k) {
    model.step(dt);
    ASSERT_GT(model.blocks().v.front(), 0.0) << "solution invalid from t = " << model.blocks().time;
  }
  // lambda(T) from the ODE with RK4 (fine step).
  const double lam =
      reference::savage_hutter_lambda(2 * K * g * std::cos(zeta) * h0 / (L0 * L0), T);
  ASSERT_GT(lam, 1.2);  // the pile has spread noticeably: the test can tell
  const double a = g * (std::sin(zeta) - std::tan(deg2rad(delta)) * std::cos(zeta));
  const double xc = xc0 + u0 * T + 0.5 * a * T * T;
  // Positions: the interior boundary blocks (not the two end ones, whose
  // triangular blocks are DAN's own approximation of the pile's edge). The
  // pressure gradient of eq. 2.35 is second-order in the block spacing
  // (1 cm here), so a few mm over a 2.5 m spread is the expected accuracy.
  double worst_pos = 0, worst_depth = 0;
  for (std::size_t i = 2; i + 2 < n; ++i) {
    const double xi0 = -L0 + 2 * L0 * i / (n - 1.0);
    worst_pos = std::max(worst_pos, std::abs(model.blocks().s[i] - (xc + lam * xi0)));
    const double depth = h0 / lam * (1 - xi0 * xi0 / (L0 * L0));
    worst_depth = std::max(worst_depth, std::abs(model.boundary_depth(i) - depth));
  }
  EXPECT_LT(worst_pos, 5e-3 * L0);
  EXPECT_LT(worst_depth, 2e-2 * h0);  // the shape stays parabolic
}

// Frictionless horizontal bed, k = 1, released column of depth h0 and length
// 4 m (long enough that the rarefaction from its back end stays out of the
// window). Returns the mean |depth error| over -c0 t <= x <= 1.5 c0 t against
// Ritter's h = (2 c0 - x/t)^2 / (9 g), and how far the front trails 2 c0 t.
struct RitterError {
  double mean_depth_error, front_lag;
};
RitterError ritter_run(std::size_t n) {
  const double h0 = 0.1, c0 = std::sqrt(g * h0), T = 0.8;
  const auto path = path_from_profile({{-10, 0}, {10, 0}}, {1, 1}, 0, 1e-2);
  auto params = frictional(0, 1.0);
  DanModel model(path, params, blocks_from_depth(path, 10 - 4, 10, n, [&](double) { return h0; }));
  const int steps = static_cast<int>(std::ceil(T / (0.1 * 4.0 / (n - 1) / c0)));
  for (int k = 0; k < steps; ++k) model.step(T / steps);
  double sum_err = 0;
  int count = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double x = model.blocks().s[i] - 10;
    if (x < -c0 * T || x > 1.5 * c0 * T) continue;
    sum_err += std::abs(model.boundary_depth(i) - std::pow(2 * c0 - x / T, 2) / (9 * g));
    ++count;
  }
  EXPECT_GT(count, 20);
  return {sum_err / count, 2 * c0 * T - (model.blocks().s.back() - 10)};
}

TEST(DanVerification, RitterDamBreak) {
  const double h0 = 0.1;
  const RitterError coarse = ritter_run(201), mid = ritter_run(401), fine = ritter_run(801);
  // Depth over the fan: the kinks at its ends are smeared over a few blocks;
  // 1 % of h0 on average.
  EXPECT_LT(fine.mean_depth_error, 1e-2 * h0);
  EXPECT_LT(fine.mean_depth_error, mid.mean_depth_error);
  // Front: Ritter's 2 c0 t is where the depth goes to zero, but the last DAN
  // block carries half a block of mass, which the exact solution holds only
  // in a tip of length delta ~ (13.5 g t^2 h0 ds)^(1/3) (mass of the tip
  // t (delta/t)^3 / (27 g) = h0 ds / 2). So the front trails by less than
  // delta and converges at least like ds^(1/3): each halving of the block
  // size must shrink the lag by 2^(-1/3) = 0.794 or more.
  EXPECT_GT(coarse.front_lag, 0.0);
  EXPECT_LT(mid.front_lag, 0.794 * coarse.front_lag);
  EXPECT_LT(fine.front_lag, 0.794 * mid.front_lag);
  const double ds = 4.0 / 800, delta = std::cbrt(13.5 * g * 0.64 * h0 * ds);
  EXPECT_LT(fine.front_lag, delta);
}

TEST(DanVerification, MassConservedToRoundOff) {
  // Constant-volume blocks: the deformed depths times lengths times widths
  // add up to the released volume after any amount of deformation, on a
  // path whose width varies.
  const auto path = path_from_profile({{0, 2}, {3, 0}, {6, 0.5}}, {1.0, 0.5, 2.0}, 0.3, 1e-3);
  auto params = frictional(20, 1.0);
  params.pressure.mode = EarthPressureMode::Hungr;
  params.pressure.phi_internal = deg2rad(35);
  params.pressure.tan_phi_basal = std::tan(deg2rad(20));
  params.smoothing.enabled = true;
  DanModel model(path, params,
                 blocks_from_depth(path, 0.2, 1.2, 60, [](double s) { return 0.1 + 0.05 * s; }));
  double v0 = 0;
  for (double V : model.blocks().volume) v0 += V;
  for (int k = 0; k < 2000; ++k) model.step(1e-3);
  EXPECT_GT(model.blocks().s.back(), 3.0);  // it reached the flat: real deformation
  EXPECT_NEAR(model.deformed_volume(), v0, 1e-13 * v0);
  EXPECT_DOUBLE_EQ(model.total_mass(), 1600 * v0);
}

}  // namespace
}  // namespace talus::runout
