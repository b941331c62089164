// The two-phase model's coupling (issue 30): its closures against their
// closed forms, the relaxation of the phases' relative velocity under drag
// alone against the drag law's ODE, the slip at which the drag balances a
// constant force difference, and each phase's mass to round-off.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "talus/core/space.hpp"
#include "talus/runout/two_phase_closures.hpp"
#include "two_phase_helpers.hpp"

namespace talus::runout {
namespace {

using testing::run_to;
using testing::sample;
namespace tp = two_phase;

constexpr double kG = 9.81;

TEST(TwoPhaseClosures, ZankeSettlingVelocityMatchesItsClosedFormAndLimits) {
  // Seed eq. 73 as printed, U_T = 10 eta / (d rho_f) (sqrt(1 + 0.01 (rho_s -
  // rho_f) rho_f g d^3 / eta^2) - 1), for quartz in water at 1e-3 Pa s.
  const double rs = 2650.0, rf = 1000.0, eta = 1e-3;
  for (double d : {1e-4, 2e-4, 1e-3, 5e-3}) {
    const double x = 0.01 * (rs - rf) * rf * kG * d * d * d / (eta * eta);
    const double printed = 10.0 * eta / (d * rf) * (std::sqrt(1.0 + x) - 1.0);
    EXPECT_NEAR(tp::zanke_settling_velocity(d, rs, rf, eta, kG), printed, 1e-12 * printed);
  }
  // 0.2 mm sand: 2.57 cm/s (by hand from eq. 73: x = 1.2949, 0.05 (sqrt(2.2949) - 1)).
  EXPECT_NEAR(tp::zanke_settling_velocity(2e-4, rs, rf, eta, kG), 0.025745, 5e-6);
  // Small grains: 0.9 of Stokes' velocity (rho_s - rho_f) g d^2 / (18 eta)
  // (the series of eq. 73: 0.05 (s - 1) g d^2 / nu against 1/18).
  const double d = 1e-6, stokes = (rs - rf) * kG * d * d / (18.0 * eta);
  EXPECT_NEAR(tp::zanke_settling_velocity(d, rs, rf, eta, kG) / stokes, 0.9, 1e-6);
  // Large grains: sqrt((s - 1) g d) (eq. 73's leading term), to 1e-2 at 1 m.
  const double big = 1.0, newton = std::sqrt((rs - rf) / rf * kG * big);
  EXPECT_NEAR(tp::zanke_settling_velocity(big, rs, rf, eta, kG) / newton, 1.0, 1e-2);
  // No settling for a grain no denser than the fluid.
  EXPECT_EQ(tp::zanke_settling_velocity(1e-3, 1000.0, 1000.0, eta, kG), 0.0);
}

TEST(TwoPhaseClosures, DragAndVirtualMassAsTheSeedWritesThem) {
  // Julien & O'Brien: eta = alpha e^(beta alpha_s).
  EXPECT_DOUBLE_EQ(tp::julien_obrien_viscosity(0.01, 20.0, 0.3), 0.01 * std::exp(6.0));
  // Richardson-Zaki between 2.4 and 4.65.
  for (double re : {1e-3, 0.5, 10.0, 1e4}) {
    EXPECT_GE(tp::richardson_zaki_exponent(re), 2.4);
    EXPECT_LE(tp::richardson_zaki_exponent(re), 4.65);
  }
  // The drag coefficient, eqs. 31-34 and 64 by hand for alpha_s = 0.6:
  // U_T (Zanke, d = 1 mm, eta = 1e-3), Re_p = rho_f d U_T / (alpha_f eta),
  // P = 0.6, F, G = 0.4^(M - 1), S_p = (P / 0.6 + 0.4 / 0.4) 10 m/s.
  tp::DragParams p;
  const double as = 0.6, af = 0.4, eta = 1e-3;
  const double ut = tp::zanke_settling_velocity(1e-3, 2700.0, 1000.0, eta, kG);
  const double re = 1000.0 * 1e-3 * ut / (af * eta);
  const double f = (1000.0 / 2700.0) / 180.0 * std::pow(af / as, 3) * re;
  const double g = std::pow(af, tp::richardson_zaki_exponent(re) - 1.0);
  const double denominator = ut * (0.6 * f + 0.4 * g) + (0.6 / 0.6 + 0.4 / 0.4) * 10.0;
  const double by_hand = as * af * 1700.0 * kG / denominator;
  EXPECT_NEAR(tp::drag_coefficient(p, as, af, eta), by_hand, 1e-12 * by_hand);
  p.exponent = 2;
  EXPECT_NEAR(tp::drag_coefficient(p, as, af, eta), by_hand / denominator, 1e-12 * by_hand);
  // No interface, no drag.
  EXPECT_EQ(tp::drag_coefficient(p, 0.0, 1.0, eta), 0.0);
  EXPECT_EQ(tp::drag_coefficient(p, 1.0, 0.0, eta), 0.0);
  // Virtual mass: r = 1 / (1 + C_VM (gamma + alpha_s / alpha_f)), C_VM = (1 + 2 alpha_s) / (2
  // alpha_f).
  const double gam = 1000.0 / 2700.0;
  const double cvm = tp::virtual_mass_coefficient(as, af);
  EXPECT_DOUBLE_EQ(cvm, 2.2 / 0.8);
  EXPECT_NEAR(tp::virtual_mass_relative_factor(as, af, gam), 1.0 / (1.0 + cvm * (gam + as / af)),
              1e-15);
  // The guard: where C_VM diverges (alpha_f -> 0) the factor goes to 0, finite.
  EXPECT_LT(tp::virtual_mass_relative_factor(0.999999, 1e-6, gam), 1e-11);
  EXPECT_EQ(tp::virtual_mass_relative_factor(1.0, 0.0, gam), 0.0);
  EXPECT_EQ(tp::virtual_mass_relative_factor(0.0, 1.0, gam), 1.0);
}

// One cell with open edges over a flat bed: every flux is the same on both
// sides, so only the sources act (no friction, no resistance: drag, and
// virtual mass when asked).
struct Relaxation {
  double rate;                  // a = H C (1 / m_s + 1 / m_f), 1/s or 1/m
  double r;                     // the virtual-mass factor
  double rel0, rel_end, t_end;  // relative speed at the start and at t_end
  double momentum0, momentum_end;
};

Relaxation relax(int exponent, bool virtual_mass, double steps_per_time) {
  GridShape g{1, 1, 1000.0, 1000.0};
  auto p = testing::two_phase_frictionless();
  p.boundary = GridBoundary::Open;
  p.viscosity_alpha = 1e-3;  // for the settling velocity in C only (shear factor 0)
  p.drag.exponent = exponent;
  p.virtual_mass = virtual_mass;
  const double hs = 0.5, hf = 0.5, h = 1.0, as = 0.5;
  TwoPhaseSolver s(Terrain(g, {0.0}), p, {hs}, {hf});
  TwoPhaseState st = s.state();
  st.hfu[0] = hf * 1.0;  // fluid at 1 m/s through a still solid
  s.set_state(st);
  const double c = tp::drag_coefficient(p.drag, as, 1.0 - as, 1e-3);
  Relaxation out{};
  out.rate = h * c * (1.0 / (p.drag.solid_density * hs) + 1.0 / (p.drag.fluid_density * hf));
  out.r = virtual_mass
              ? tp::virtual_mass_relative_factor(
                    as, 1.0 - as, s.params().drag.fluid_density / s.params().drag.solid_density)
              : 1.0;
  out.rel0 = 1.0;
  out.momentum0 = s.momentum_x();
  out.t_end = 3.0 / (out.r * out.rate);  // e^-3 left (linear), a quarter (quadratic)
  run_to(s, out.t_end, {}, 1.0 / (steps_per_time * out.r * out.rate));
  const auto& e = s.state();
  out.rel_end = e.hfu[0] / e.hf[0] - e.hsu[0] / e.hs[0];
  out.momentum_end = s.momentum_x();
  return out;
}

double exact_relaxation(const Relaxation& r, int exponent) {
  const double k = r.r * r.rate * r.t_end;  // 3
  return exponent == 1 ? r.rel0 * std::exp(-k) : r.rel0 / (1.0 + k * r.rel0);
}

TEST(TwoPhaseCoupling, RelativeVelocityRelaxesAsTheDragLawPredicts) {
  // d(dU)/dt = -r a dU |dU|^(J-1): dU0 e^(-r a t) (J = 1) or
  // dU0 / (1 + r a dU0 t) (J = 2), r = 1 without virtual mass, run to
  // r a t = 3. The drag is implicit within each of the two stages of a step
  // (first order in time). For J = 1 with x = a dt a step multiplies dU by
  // (1 + (1 - r x / (1 + x))^2) / 2 = 1 - r x + r x^2 + r^2 x^2 / 2 + O(x^3)
  // against e^(-r x) = 1 - r x + r^2 x^2 / 2: a relative excess of r x^2 per
  // step, 3 x over the 3 / (r x) steps. So the error is asserted within 10 %
  // of 3 x at 100 steps per relaxation time (x = 0.01 / r), and to halve
  // when the step halves. J = 2 relaxes more slowly as dU falls, so its
  // error stays below that of the linear law at the same starting rate.
  for (int exponent : {1, 2})
    for (bool vm : {false, true}) {
      const Relaxation coarse = relax(exponent, vm, 50.0), fine = relax(exponent, vm, 100.0);
      const double exact = exact_relaxation(fine, exponent);
      const double e_coarse = std::abs(coarse.rel_end - exact) / exact;
      const double e_fine = std::abs(fine.rel_end - exact) / exact;
      const double x = 0.01 / fine.r;  // a dt (times dU0 = 1 m/s for J = 2)
      std::printf(
          "relaxation J=%d vm=%d: r %.4f, a %.4f, dU %.6f (exact %.6f), errors %.2e %.2e "
          "(3 a dt = %.2e)\n",
          exponent, vm, fine.r, fine.rate, fine.rel_end, exact, e_coarse, e_fine, 3.0 * x);
      if (exponent == 1)
        EXPECT_NEAR(e_fine, 3.0 * x, 0.1 * 3.0 * x);
      else
        EXPECT_LT(e_fine, 3.0 * x);
      EXPECT_NEAR(e_coarse / e_fine, 2.0, 0.2);  // first order in time
      // The drag is internal: the mixture's momentum is kept to round-off.
      EXPECT_NEAR(fine.momentum_end, fine.momentum0, 1e-12 * std::abs(fine.momentum0));
    }
}

TEST(TwoPhaseCoupling, DragBalancesAConstantForceDifference) {
  // A uniform mixture on a plane of slope tan(theta) = 0.1, open edges: the
  // fluid is pushed by g tan(theta), the solid by (gamma g + (1 - gamma) g
  // cos^2) tan(theta) less its Coulomb friction tan(delta) (1 - gamma) g
  // cos^2 (the model's horizontal equations). Both keep accelerating, but
  // their slip dU = u_f - u_s settles where the linear drag balances the
  // difference: H C dU (1 / m_s + 1 / m_f) = g tan(theta) - (gamma g + (1 -
  // gamma) g cos^2) tan(theta) + tan(delta) (1 - gamma) g cos^2. Virtual mass
  // slows the approach, not the end.
  const double tan_theta = 0.1, tan_delta = 0.05, hs = 0.5, hf = 0.5, h = 1.0;
  GridShape g{401, 1, 1.0, 1.0};
  auto bed = sample(g, [&](double x, double) { return -tan_theta * x; });
  auto p = testing::two_phase_frictionless();
  p.boundary = GridBoundary::Open;
  p.tan_basal_friction = tan_delta;
  p.viscosity_alpha = 1e-3;
  p.drag.smoothing_speed = 1.0;  // a stronger drag: relaxes within seconds
  p.virtual_mass = true;         // (the default) it must not move the end
  TwoPhaseSolver s(Terrain(g, bed), p, std::vector<double>(g.cells(), hs),
                   std::vector<double>(g.cells(), hf));
  const double gam = p.drag.fluid_density / p.drag.solid_density;
  const double c2 = 1.0 / (1.0 + tan_theta * tan_theta);
  const double force = kG * tan_theta - (gam * kG + (1.0 - gam) * kG * c2) * tan_theta +
                       tan_delta * (1.0 - gam) * kG * c2;
  const double c = tp::drag_coefficient(p.drag, 0.5, 0.5, 1e-3);
  const double rate =
      h * c * (1.0 / (p.drag.solid_density * hs) + 1.0 / (p.drag.fluid_density * hf));
  const double r = tp::virtual_mass_relative_factor(0.5, 0.5, gam);
  // 20 / (r a) leaves less than e^-17 of the start's slip (the implicit
  // stages relax at r a / (1 + a dt), a dt < 0.2 here); the disturbances
  // from the edges (at most u + c ~ 10 + 3.3 m/s at the end) stay > 80 m
  // from the middle cell (200 m from either edge) until then.
  const double t_end = 20.0 / (r * rate);
  ASSERT_LT(t_end, 20.0);
  run_to(s, t_end);
  const std::size_t k = 200;
  const auto& e = s.state();
  const double slip = e.hfu[k] / e.hf[k] - e.hsu[k] / e.hs[k];
  const double exact = force / rate;
  std::printf("terminal slip %.8f m/s (exact %.8f), solid at %.3f m/s, t %.2f s\n", slip, exact,
              e.hsu[k] / e.hs[k], t_end);
  EXPECT_NEAR(slip, exact, 1e-6 * exact);  // e^-17 of the start (~4e-8) plus round-off
}

// A solid-fluid release on a bumpy slope between walls: the solid a lumpy
// disc, the fluid a disc overlapping it.
struct BumpyRelease {
  GridShape g{48, 40, 1.0, 1.0};
  std::vector<double> bed = sample(g, [](double x, double y) {
    return -0.4 * x + 1.5 * std::sin(0.3 * x) * std::cos(0.25 * y) + 0.02 * y * y;
  });
  std::vector<double> solid = sample(g, [](double x, double y) {
    const double r2 = (x - 12) * (x - 12) + (y - 20) * (y - 20);
    return r2 < 64 ? 1.2 + 0.3 * std::sin(x * y) : 0.0;
  });
  std::vector<double> fluid = sample(g, [](double x, double y) {
    const double r2 = (x - 14) * (x - 14) + (y - 18) * (y - 18);
    return r2 < 49 ? 0.8 : 0.0;
  });
  TwoPhaseSolver solver() const {
    TwoPhaseParams p;
    p.tan_basal_friction = std::tan(deg2rad(18.0));
    p.pressure.phi_internal = deg2rad(32.0);
    p.pressure.tan_phi_basal = p.tan_basal_friction;
    p.manning = 0.05, p.viscosity_alpha = 0.01, p.viscosity_beta = 10.0;
    return TwoPhaseSolver(Terrain(g, bed), p, solid, fluid);
  }
};

TEST(TwoPhaseCoupling, EachPhaseKeepsItsMassAndNothingOutrunsFreeFall) {
  // With no rain or infiltration, each phase's volume is constant to
  // round-off while the two separate, and depths stay non-negative.
  const BumpyRelease release;
  const GridShape& g = release.g;
  const std::vector<double>&bed = release.bed, &solid = release.solid, &fluid = release.fluid;
  TwoPhaseSolver s = release.solver();
  const double vs = s.solid_volume(), vf = s.fluid_volume();
  // No part of the flow may outrun free fall from the highest surface to the
  // lowest bed, sqrt(2 g dz) (friction only slows it). Thin layers that the
  // reconstruction's steps at faces between wet cells trapped did (33 m/s
  // against the 31 m/s bound, with virtual mass on), before those steps
  // acted as walls.
  double top = -1e9, bottom = 1e9;
  for (std::size_t c = 0; c < g.cells(); ++c)
    top = std::max(top, bed[c] + solid[c] + fluid[c]), bottom = std::min(bottom, bed[c]);
  const double free_fall = std::sqrt(2.0 * 9.81 * (top - bottom));
  double min_depth = 0.0, fastest = 0.0;
  run_to(s, 6.0, [&](const TwoPhaseSolver& f) {
    for (std::size_t c = 0; c < g.cells(); ++c)
      min_depth = std::min({min_depth, f.state().hs[c], f.state().hf[c]});
    fastest = std::max(fastest, f.max_speed());
  });
  std::printf("fastest %.2f m/s, free-fall bound %.2f m/s\n", fastest, free_fall);
  EXPECT_LT(fastest, free_fall);
  std::printf("mass: solid %.3e, fluid %.3e relative change; max speed %.2f m/s\n",
              s.solid_volume() / vs - 1.0, s.fluid_volume() / vf - 1.0, s.max_speed());
  EXPECT_GT(s.max_speed(), 1.0);  // it did flow
  EXPECT_NEAR(s.solid_volume(), vs, 1e-12 * vs);
  EXPECT_NEAR(s.fluid_volume(), vf, 1e-12 * vf);
  EXPECT_GE(min_depth, 0.0);
}

TEST(TwoPhaseCoupling, TwoThreadsGiveTheSameBits) {
  // Every loop of the solver is per cell or per face (or a max), and sums
  // run in cell order, so the release above on two threads gives the same
  // state, bit for bit, as on one.
  const BumpyRelease release;
  TwoPhaseState state[2];
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    TwoPhaseSolver s = release.solver();
    run_to(s, 2.0);
    state[threads - 1] = s.state();
  }
  omp_set_num_threads(1);
  EXPECT_EQ(state[0].time, state[1].time);
  EXPECT_EQ(state[0].hs, state[1].hs);
  EXPECT_EQ(state[0].hsu, state[1].hsu);
  EXPECT_EQ(state[0].hsv, state[1].hsv);
  EXPECT_EQ(state[0].hf, state[1].hf);
  EXPECT_EQ(state[0].hfu, state[1].hfu);
  EXPECT_EQ(state[0].hfv, state[1].hfv);
}

// A debris-flow release on a 25 deg plane (solid fraction 0.6, bed friction
// 20 deg, Manning 0.03, drag, virtual mass, viscosity) on three grids.
struct DebrisRun {
  std::size_t nx, ny;
  std::vector<double> hs, hf;
  double centre_s, centre_f;  // x of each phase's centre of mass, m
};

// beta: of Julien & O'Brien's viscosity; lateral: the fluid's lateral
// viscous stress (two_phase_viscous.hpp).
DebrisRun debris_on_plane(double dx, double beta = 10.0, bool lateral = false) {
  const std::size_t nx = static_cast<std::size_t>(std::lround(20.0 / dx));
  const std::size_t ny = static_cast<std::size_t>(std::lround(10.0 / dx));
  GridShape g{nx, ny, dx, dx};
  auto bed = sample(g, [](double x, double) { return -std::tan(deg2rad(25.0)) * x; });
  auto mixture = sample(g, [](double x, double y) {
    const double r2 = (x - 4.0) * (x - 4.0) + (y - 5.0) * (y - 5.0);
    return std::max(0.0, 0.8 * (1.0 - r2 / 4.0));
  });
  std::vector<double> solid(g.cells()), fluid(g.cells());
  for (std::size_t c = 0; c < g.cells(); ++c)
    solid[c] = 0.6 * mixture[c], fluid[c] = 0.4 * mixture[c];
  TwoPhaseParams p;
  p.tan_basal_friction = std::tan(deg2rad(20.0));
  // k = 1 (a liquefied mass): with Savage-Hutter's k_a / k_p the passive
  // pressure holds the pile's upslope part by friction, and the edge of that
  // held zone wears away faster the finer the grid -- fv2d alike (centre of
  // mass 5.146 m at 0.125 m cells, 5.788 m at 0.0625 m for the dry pile);
  // that is not what this test is about.
  p.pressure.mode = EarthPressureMode::Constant;
  p.pressure.constant = 1.0;
  p.manning = 0.03, p.viscosity_alpha = 0.01, p.viscosity_beta = beta;
  p.lateral_viscosity = lateral;
  p.boundary = GridBoundary::Open;
  TwoPhaseSolver s(Terrain(g, bed), p, solid, fluid);
  run_to(s, 1.5);
  DebrisRun r{nx, ny, s.state().hs, s.state().hf, 0.0, 0.0};
  double ms = 0.0, mf = 0.0;
  for (std::size_t c = 0; c < g.cells(); ++c) {
    const double x = (c % nx + 0.5) * dx;
    ms += r.hs[c], mf += r.hf[c], r.centre_s += r.hs[c] * x, r.centre_f += r.hf[c] * x;
  }
  r.centre_s /= ms, r.centre_f /= mf;
  return r;
}

// L1 distance (m^3) between a run and the next finer one averaged onto its
// cells (2 x 2 blocks), both phases.
double distance_to_finer(const DebrisRun& coarse, const DebrisRun& fine, double dx) {
  double sum = 0.0;
  for (std::size_t j = 0; j < coarse.ny; ++j)
    for (std::size_t i = 0; i < coarse.nx; ++i) {
      double s = 0.0, f = 0.0;
      for (std::size_t dj = 0; dj < 2; ++dj)
        for (std::size_t di = 0; di < 2; ++di) {
          const std::size_t k = (2 * j + dj) * fine.nx + 2 * i + di;
          s += 0.25 * fine.hs[k], f += 0.25 * fine.hf[k];
        }
      const std::size_t c = j * coarse.nx + i;
      sum += (std::abs(coarse.hs[c] - s) + std::abs(coarse.hf[c] - f)) * dx * dx;
    }
  return sum;
}

TEST(TwoPhaseConvergence, DebrisReleaseOnAPlaneConvergesWithTheGrid) {
  // No closed form: the runs on 0.5, 0.25 and 0.125 m cells are compared
  // each with the next finer (self-convergence, L1 of both phases' depths).
  // The distance must shrink with the cell size; the observed order is
  // printed and asserted above 0.5 (fronts and friction's stop-or-move
  // switch allow at most first order).
  const DebrisRun r1 = debris_on_plane(0.5), r2 = debris_on_plane(0.25),
                  r3 = debris_on_plane(0.125);
  const double e1 = distance_to_finer(r1, r2, 0.5), e2 = distance_to_finer(r2, r3, 0.25);
  const double released = 0.8 * M_PI * 4.0 / 2.0;  // paraboloid: pi R^2 h / 2
  std::printf(
      "debris on a plane: distances %.4f %.4f m^3 (of %.3f released), order %.2f; "
      "centres solid %.4f %.4f %.4f, fluid %.4f %.4f %.4f m\n",
      e1, e2, released, std::log2(e1 / e2), r1.centre_s, r2.centre_s, r3.centre_s, r1.centre_f,
      r2.centre_f, r3.centre_f);
  EXPECT_GT(std::log2(e1 / e2), 0.5);
}

TEST(TwoPhaseConvergence, WithTheLateralViscousStressToo) {
  // The same with the fluid's lateral viscous stress, at beta = 5. At the
  // first test's beta = 10 the order falls to 0.22 (distances 0.2722,
  // 0.2344 m^3): in the flow's thin edges, where alpha_s -> 1, Julien &
  // O'Brien's eta = alpha e^(beta alpha_s) reaches 220 Pa s, and that
  // explicit stress sets the finest grid's steps -- why the stress is off by
  // default (docs/validation/two-phase.md).
  const DebrisRun r1 = debris_on_plane(0.5, 5.0, true), r2 = debris_on_plane(0.25, 5.0, true),
                  r3 = debris_on_plane(0.125, 5.0, true);
  const double e1 = distance_to_finer(r1, r2, 0.5), e2 = distance_to_finer(r2, r3, 0.25);
  std::printf("debris on a plane, lateral stress, beta 5: distances %.4f %.4f m^3, order %.2f\n",
              e1, e2, std::log2(e1 / e2));
  EXPECT_GT(std::log2(e1 / e2), 0.5);
}

TEST(TwoPhaseSources, RainAndInfiltrationBalanceTheFluidsVolume) {
  // Continuity with R - I (seed eqs. 47, 49): on a closed bumpy basin the
  // fluid's volume is the start's plus R A t less what infiltrated, to
  // round-off; rain alone adds exactly R A t; infiltration faster than rain
  // empties cells but never below 0. The solid is untouched.
  GridShape g{30, 20, 1.0, 1.0};
  auto bed =
      sample(g, [](double x, double y) { return 0.3 * std::sin(0.4 * x) * std::cos(0.3 * y); });
  auto solid =
      sample(g, [](double x, double y) { return std::hypot(x - 10, y - 10) < 4 ? 0.3 : 0.0; });
  auto fluid = sample(g, [](double x, double) { return x > 20 ? 0.2 : 0.0; });
  const double area = 30.0 * 20.0, t = 20.0;
  for (double infiltration : {0.0, 2e-3}) {
    TwoPhaseParams p;
    p.tan_basal_friction = 0.4, p.manning = 0.05, p.viscosity_alpha = 0.01;
    p.rainfall = 1e-3, p.infiltration = infiltration;
    TwoPhaseSolver s(Terrain(g, bed), p, solid, fluid);
    const double vs = s.solid_volume(), vf = s.fluid_volume();
    double lowest = 0.0;
    run_to(s, t, [&](const TwoPhaseSolver& f) {
      lowest = std::min(lowest, *std::min_element(f.state().hf.begin(), f.state().hf.end()));
    });
    std::printf(
        "rain %g, infiltration %g: fluid %.6f m^3 (start %.6f, rained %.6f, infiltrated "
        "%.6f)\n",
        p.rainfall, infiltration, s.fluid_volume(), vf, s.rained_volume(), s.infiltrated_volume());
    EXPECT_NEAR(s.rained_volume(), p.rainfall * area * t, 1e-9 * p.rainfall * area * t);
    EXPECT_NEAR(s.fluid_volume(), vf + s.rained_volume() - s.infiltrated_volume(), 1e-12 * vf);
    if (infiltration == 0.0) {
      EXPECT_EQ(s.infiltrated_volume(), 0.0);
    } else {  // faster than the rain, but some cells ran dry: less than I A t
      EXPECT_GT(s.infiltrated_volume(), s.rained_volume());
      EXPECT_LT(s.infiltrated_volume(), infiltration * area * t);
    }
    EXPECT_GE(lowest, 0.0);
    EXPECT_NEAR(s.solid_volume(), vs, 1e-12 * vs);
  }
}

}  // namespace
}  // namespace talus::runout
