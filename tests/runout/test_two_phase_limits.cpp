// The two-phase solver's limits (issue 30, spec runout.md §3): without solid
// it is the shallow-water equations with Manning friction (Ritter's and
// Stoker's dam breaks, a lake at rest over a bumpy bed, uniform flow at the
// Manning depth); without fluid (and with no fluid density, so no buoyancy)
// it is fv2d's granular model (the Savage-Hutter cap, the sliding block, a
// pile held by friction).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dam_break.hpp"
#include "parabolic_cap.hpp"
#include "talus/core/space.hpp"
#include "two_phase_helpers.hpp"

namespace talus::runout {
namespace {

using testing::run_to;
using testing::sample;

constexpr double kG = 9.81;

// A channel one cell wide along x, dam at its middle, flat bed, fluid only.
TwoPhaseSolver water_dam_break(double dx, double length, double h_left, double h_right) {
  const std::size_t cells = static_cast<std::size_t>(std::lround(length / dx));
  GridShape g{cells, 1, dx, dx};
  auto fluid = sample(g, [&](double x, double) { return x < 0.5 * length ? h_left : h_right; });
  return TwoPhaseSolver(Terrain(g, std::vector<double>(g.cells(), 0.0)),
                        testing::two_phase_frictionless(), std::vector<double>(g.cells(), 0.0),
                        fluid);
}

double ritter(double x, double t, double h0) { return reference::ritter_depth(x, t, h0, kG); }

double ritter_l1(double dx, double t) {
  const double length = 100.0, h0 = 1.0;
  TwoPhaseSolver s = water_dam_break(dx, length, h0, 0.0);
  double min_depth = 1.0;
  run_to(s, t, [&](const TwoPhaseSolver& f) {
    min_depth = std::min(min_depth, *std::min_element(f.state().hf.begin(), f.state().hf.end()));
  });
  EXPECT_GE(min_depth, 0.0);
  double err = 0.0;
  const auto& h = s.state().hf;
  for (std::size_t k = 0; k < h.size(); ++k)
    err += std::abs(h[k] - ritter((k + 0.5) * dx - 0.5 * length, t, h0)) * dx;
  return err / (0.5 * length * h0);
}

TEST(TwoPhaseLimits, WithoutSolidRitterDryDamBreak) {
  // fv2d's own test and tolerance (test_fv2d_verification.cpp): L1 within
  // 1 % of the released volume at 800 cells, and a clear gain on refinement.
  const double fine = ritter_l1(0.125, 4.0), coarse = ritter_l1(0.25, 4.0);
  std::printf("two-phase Ritter L1: %.4f (dx 0.25), %.4f (dx 0.125)\n", coarse, fine);
  EXPECT_LT(fine, 0.01);
  EXPECT_LT(fine, coarse / 1.5);
}

// Stoker (1957): the wet dam break. The middle state h_m joins the left
// rarefaction, u_m = 2 (sqrt(g h_l) - sqrt(g h_m)), to the shock into still
// water of depth h_r, u_m = (h_m - h_r) sqrt(g (h_m + h_r) / (2 h_m h_r));
// the shock moves at h_m u_m / (h_m - h_r).
struct Stoker {
  double h_m, u_m, shock_speed;
};

Stoker stoker(double h_l, double h_r) {
  auto mismatch = [&](double h) {
    return 2.0 * (std::sqrt(kG * h_l) - std::sqrt(kG * h)) -
           (h - h_r) * std::sqrt(kG * (h + h_r) / (2.0 * h * h_r));
  };
  double lo = h_r, hi = h_l;  // mismatch > 0 at h_r, < 0 at h_l
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (mismatch(mid) > 0.0 ? lo : hi) = mid;
  }
  const double h_m = 0.5 * (lo + hi), u_m = 2.0 * (std::sqrt(kG * h_l) - std::sqrt(kG * h_m));
  return {h_m, u_m, h_m * u_m / (h_m - h_r)};
}

TEST(TwoPhaseLimits, WithoutSolidStokerWetDamBreak) {
  const double length = 100.0, dx = 0.125, t = 5.0, h_l = 1.0, h_r = 0.1;
  TwoPhaseSolver s = water_dam_break(dx, length, h_l, h_r);
  run_to(s, t);
  const Stoker exact = stoker(h_l, h_r);
  const auto& h = s.state().hf;
  auto x_of = [&](std::size_t k) { return (k + 0.5) * dx - 0.5 * length; };
  // The plateau: between the rarefaction's tail, at (u_m - c_m) t, and the
  // shock, less a margin of 2 m on each side for the smeared edges.
  const double tail = (exact.u_m - std::sqrt(kG * exact.h_m)) * t, shock = exact.shock_speed * t;
  double worst = 0.0, u_err = 0.0;
  for (std::size_t k = 0; k < h.size(); ++k)
    if (x_of(k) > tail + 2.0 && x_of(k) < shock - 2.0) {
      worst = std::max(worst, std::abs(h[k] - exact.h_m));
      u_err = std::max(u_err, std::abs(s.state().hfu[k] / h[k] - exact.u_m));
    }
  // The shock: where the depth falls through the mean of h_m and h_r.
  double x_shock = 0.0;
  for (std::size_t k = h.size() - 1; k-- > 0;)
    if (h[k] > 0.5 * (exact.h_m + h_r)) {
      x_shock = x_of(k) + dx * (h[k] - 0.5 * (exact.h_m + h_r)) / (h[k] - h[k + 1]);
      break;
    }
  std::printf(
      "Stoker: h_m %.5f (exact %.5f, worst %.2e), u_m err %.2e, shock at %.3f (exact %.3f)\n",
      exact.h_m, exact.h_m, worst, u_err, x_shock, shock);
  // A second-order shock-capturing scheme holds the plateau to a fraction of
  // a percent and places the shock within a cell or two (800 cells).
  EXPECT_LT(worst, 0.005 * exact.h_m);
  EXPECT_LT(u_err, 0.01 * exact.u_m);
  EXPECT_NEAR(x_shock, shock, 2.0 * dx);
}

TEST(TwoPhaseLimits, LakeAtRestOverABumpyBedStaysAtRest) {
  // Well-balanced: hydrostatic reconstruction keeps a flat surface over any
  // bed, including bumps that rise above it (dry islands), to round-off.
  // Both reconstruction orders; walls.
  for (int order : {1, 2}) {
    GridShape g{40, 30, 0.5, 0.5};
    auto bed = sample(g, [](double x, double y) {
      return 0.6 * std::sin(0.7 * x) * std::cos(0.5 * y) +
             0.3 * std::exp(-((x - 8) * (x - 8) + (y - 7) * (y - 7)));
    });
    std::vector<double> fluid(g.cells());
    for (std::size_t c = 0; c < fluid.size(); ++c) fluid[c] = std::max(0.0, 0.5 - bed[c]);
    ASSERT_TRUE(std::any_of(fluid.begin(), fluid.end(), [](double h) { return h == 0.0; }));
    auto p = testing::two_phase_frictionless();
    p.order = order;
    TwoPhaseSolver s(Terrain(g, bed), p, std::vector<double>(g.cells(), 0.0), fluid);
    run_to(s, 5.0);
    double dh = 0.0;
    for (std::size_t c = 0; c < fluid.size(); ++c)
      dh = std::max(dh, std::abs(s.state().hf[c] - fluid[c]));
    std::printf("lake at rest, order %d: max speed %.2e m/s, max depth change %.2e m\n", order,
                s.max_speed(), dh);
    // Round-off of sums of O(1) terms, accumulated over the steps.
    EXPECT_LT(s.max_speed(), 1e-12);
    EXPECT_LT(dh, 1e-13);
    // The same lake with 1 cm more water in one quarter must move (a solver
    // whose fluid exchanged nothing would pass the rest test too: order 1
    // once did), at the speed of that step, ~ sqrt(g h) 0.01 / h > 1 cm/s.
    for (std::size_t c = 0; c < fluid.size(); ++c)
      if (c % g.nx < g.nx / 2 && c / g.nx < g.ny / 2 && fluid[c] > 0.0) fluid[c] += 0.01;
    TwoPhaseSolver disturbed(Terrain(g, bed), p, std::vector<double>(g.cells(), 0.0), fluid);
    run_to(disturbed, 0.5);
    EXPECT_GT(disturbed.max_speed(), 0.01);
  }
}

TEST(TwoPhaseLimits, WithoutSolidUniformFlowReachesTheManningDepth) {
  // A uniform sheet on a plane of slope S (b = -S x), open edges: where the
  // draw-down from the upstream edge has not arrived, it stays uniform and
  // accelerates until gravity balances Manning's friction,
  // g H S = g n^2 U^2 / H^(1/3): U = H^(2/3) sqrt(S) / n (this model's
  // friction and bed term are of the vertical depth and horizontal speed).
  const double slope = 0.05, n = 0.03, depth = 1.0, dx = 10.0;
  GridShape g{300, 1, dx, dx};
  auto bed = sample(g, [&](double x, double) { return -slope * x; });
  auto p = testing::two_phase_frictionless();
  p.manning = n;
  p.boundary = GridBoundary::Open;
  TwoPhaseSolver s(Terrain(g, bed), p, std::vector<double>(g.cells(), 0.0),
                   std::vector<double>(g.cells(), depth));
  // Relaxation time U / (g S) = 15 s; the draw-down moves at U + c < 11 m/s,
  // so at 150 s it has reached 1.7 km of the 3 km: cell 250 (2.5 km) is clear.
  run_to(s, 150.0);
  const double u_exact = std::pow(depth, 2.0 / 3.0) * std::sqrt(slope) / n;
  const std::size_t k = 250;
  const double u = s.state().hfu[k] / s.state().hf[k];
  std::printf("Manning: U %.6f (exact %.6f), H %.6f\n", u, u_exact, s.state().hf[k]);
  // exp(-2 * 150 / 15) of the start's deficit is left: far below 1e-6.
  EXPECT_NEAR(s.state().hf[k], depth, 1e-9);
  EXPECT_NEAR(u, u_exact, 1e-6 * u_exact);
}

// The Savage-Hutter cap of test_fv2d_analytic.cpp (parabolic_cap.hpp), as
// solid alone.
TEST(TwoPhaseLimits, WithoutFluidSavageHutterParabolicCap) {
  const reference::ParabolicCap cap;
  const double dx = 0.005, T = 1.5;
  const GridShape g = cap.grid(dx);
  const auto solid = cap.depth(g);
  auto p = testing::two_phase_granular(25.0, 35.0);
  p.pressure.mode = EarthPressureMode::Constant;
  p.pressure.constant = cap.k();
  TwoPhaseSolver s(Terrain(g, cap.bed(g)), p, solid, std::vector<double>(g.cells(), 0.0));
  TwoPhaseState start = s.state();
  for (std::size_t k = 0; k < g.cells(); ++k) start.hsu[k] = solid[k] * cap.u0 * cap.cos_zeta();
  s.set_state(start);
  double v0 = 0.0;
  for (double h : solid) v0 += h * dx;
  run_to(s, T);
  const auto computed = cap.moments(s.state().hs, dx, v0);
  std::printf("two-phase cap: centre %.5f (exact %.5f), lambda %.6f (ODE %.6f)\n", computed.centre,
              cap.centre(T), computed.lambda, cap.lambda(T));
  // fv2d's tolerances at the same cell size (test_fv2d_analytic.cpp): the
  // centre within a cell, lambda within 1e-3.
  EXPECT_NEAR(computed.centre, cap.centre(T), dx);
  EXPECT_NEAR(computed.lambda, cap.lambda(T), 1e-3);
}

TEST(TwoPhaseLimits, WithoutFluidSlidingBlockAcceleratesWithFriction) {
  // fv2d's sliding block (test_fv2d_verification.cpp): a stiff pile (k = 0)
  // on a 35 deg incline with 20 deg bed friction; the centre of mass
  // accelerates along the slope at g (sin 35 - cos 35 tan 20), within 0.1 %.
  const double theta = deg2rad(35.0), phi = deg2rad(20.0);
  GridShape g{600, 1, 0.1, 0.1};
  auto bed = sample(g, [&](double x, double) { return -std::tan(theta) * x; });
  auto solid = sample(g, [](double x, double) { return x > 5 && x < 9 ? 0.5 : 0.0; });
  auto p = testing::two_phase_granular(20.0, 30.0);
  p.pressure.mode = EarthPressureMode::Constant;
  p.pressure.constant = 0.0;
  TwoPhaseSolver s(Terrain(g, bed), p, solid, std::vector<double>(g.cells(), 0.0));
  const double t = 1.5;
  run_to(s, t);
  const double a = kG * (std::sin(theta) - std::cos(theta) * std::tan(phi));
  const double u_com = s.momentum_x() / (p.drag.solid_density * s.solid_volume());
  std::printf("two-phase sliding block: relative deficit %.2e\n",
              1.0 - u_com / (a * std::cos(theta) * t));
  EXPECT_NEAR(u_com, a * std::cos(theta) * t, 1e-3 * a * std::cos(theta) * t);
}

TEST(TwoPhaseLimits, WithoutFluidPileBelowFrictionAngleStaysExactlyAtRest) {
  // fv2d's cone on a 20 deg slope with 30 deg friction: nothing may move.
  GridShape g{80, 80, 0.25, 0.25};
  auto bed = sample(g, [](double x, double) { return -std::tan(deg2rad(20.0)) * x; });
  auto solid = sample(g, [](double x, double y) {
    return std::max(0.0, 0.3 * (1.0 - std::hypot(x - 10, y - 10) / 6.0));
  });
  TwoPhaseSolver s(Terrain(g, bed), testing::two_phase_granular(30.0, 35.0), solid,
                   std::vector<double>(g.cells(), 0.0));
  run_to(s, 2.0);
  EXPECT_EQ(s.max_speed(), 0.0);
  for (std::size_t c = 0; c < solid.size(); ++c) ASSERT_EQ(s.state().hs[c], solid[c]);
}

TEST(TwoPhaseLimits, WithoutFluidEachOrderIsFv2ds) {
  // A dry pile (no fluid, no fluid density) spreading and sliding on a 25 deg
  // plane with 20 deg friction and Savage-Hutter's k: the solid's terms are
  // fv2d's, so at either reconstruction order the two solvers' depths agree
  // to round-off (1e-9 m allows for operations done in another order).
  for (int order : {1, 2}) {
    GridShape g{40, 20, 0.5, 0.5};
    auto bed = testing::sample(g, [](double x, double) { return -std::tan(deg2rad(25.0)) * x; });
    auto pile = testing::sample(g, [](double x, double y) {
      return std::max(0.0, 0.8 * (1.0 - ((x - 4) * (x - 4) + (y - 5) * (y - 5)) / 4.0));
    });
    auto p = testing::two_phase_granular(20.0, 35.0);
    p.order = order;
    p.boundary = GridBoundary::Open;
    TwoPhaseSolver two(Terrain(g, bed), p, pile, std::vector<double>(g.cells(), 0.0));
    auto q = testing::frictional(20.0, 35.0);
    q.order = order;
    q.boundary = GridBoundary::Open;
    Fv2dSolver one(Terrain(g, bed), q, pile);
    while (one.state().time < 1.5 - 1e-12) {
      const double dt = std::min(one.stable_time_step(), 1.5 - one.state().time);
      one.step(dt), two.step(dt);
    }
    double worst = 0.0;
    for (std::size_t c = 0; c < g.cells(); ++c)
      worst = std::max(worst, std::abs(one.state().h[c] - two.state().hs[c]));
    std::printf("order %d: largest depth difference to fv2d %.2e m\n", order, worst);
    EXPECT_LT(worst, 1e-9);
  }
}

}  // namespace
}  // namespace talus::runout
