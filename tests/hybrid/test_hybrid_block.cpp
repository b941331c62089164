// The hybrid method's particles as blocks (issue 31's checks): a stiff block
// slides on an incline at a = g (sin - cos tan phi_b) and stops where the
// energy line says; a block at rest stays at rest, without the tensile
// instability's clumping; the particle forces conserve momentum; the result
// does not depend on the number of threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "hybrid/hybrid_test_support.hpp"
#include "talus/core/error.hpp"

namespace talus::hybrid {
namespace {

using namespace testing;

struct Block {
  runout::Terrain terrain;
  Seeded seeded;
};

// The seed's clay block, 0.3 x 0.25 m and 0.2 m deep, on 2.5 cm cells (12 x
// 10 of them) with 4 particles per cell, its corner at cell (i0, j0).
constexpr double kCell = 0.025;
Block clay_block(std::size_t nx, std::size_t ny, double theta, std::size_t i0, std::size_t j0,
                 double u0 = 0.0, double v0 = 0.0) {
  runout::Terrain terrain = plane(nx, ny, kCell, theta);
  const auto depth = block_depth(terrain.shape(), i0, i0 + 12, j0, j0 + 10, 0.2);
  Seeded seeded = seed_particles(terrain.shape(), depth, 0.2 * kCell * kCell / 4, 2400.0, u0, v0);
  return {std::move(terrain), std::move(seeded)};
}

HybridParams stiff_params(double tan_friction) {
  HybridParams params;
  params.smoothing_length = kCell;
  params.material = clay(1e9);  // never yields: a rigid-like elastic block
  params.tan_basal_friction = tan_friction;
  return params;
}

double centre_x(const Particles& p) {
  double mx = 0.0, m = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) mx += p.mass[k] * p.x[k], m += p.mass[k];
  return mx / m;
}

// Horizontal coordinates: on a plane at theta the along-bed acceleration
// g (sin - cos tan phi_b) has the horizontal component
// g cos (sin - cos tan phi_b). A uniform, unstressed block moves as one body,
// so the rate holds to round-off; 1e-9 relative is asserted.
TEST(HybridBlock, StiffBlockSlidesAtCoulombsRate) {
  const double theta = deg(30.0), mu = std::tan(deg(20.0));
  Block b = clay_block(40, 20, theta, 4, 5);
  HybridSolver solver(b.terrain, stiff_params(mu), b.seeded.particles, b.seeded.spacing);
  run_to(solver, 0.3);
  const double g = 9.81;
  const double a = g * std::cos(theta) * (std::sin(theta) - std::cos(theta) * mu);
  const HybridTotals t = solver.totals();
  EXPECT_NEAR(t.momentum_x / t.mass, a * 0.3, 1e-9 * a * 0.3);
  EXPECT_NEAR(t.momentum_y / t.mass, 0.0, 1e-12);
  // Every particle moves with the block.
  for (std::size_t k = 0; k < solver.particles().size(); ++k)
    EXPECT_NEAR(solver.particles().u[k], a * 0.3, 1e-9) << k;
}

// Frictionless, a stiff block released on a 30 deg slope runs through a
// circular arc of radius 0.5 m onto the flat: on the flat its kinetic energy
// is the potential energy its particles lost. With the bed's centripetal
// load in the pull (g + u^T Hess(b) u) this holds to 0.34 % here (and 0.15 %
// with R = 2 m); without it 24 % was lost (both measured while building the
// term). 1 % is asserted: the curvature is a second difference on 2.5 cm
// cells and the block is 0.3 m long.
TEST(HybridBlock, FrictionlessBlockKeepsItsEnergyThroughACurve) {
  const double cell = kCell, theta = deg(30.0), radius = 0.5, flat = 2.0;
  const double arc = flat - radius * std::sin(theta);
  auto bed = [&](double x) {
    if (x >= flat) return 0.0;
    if (x >= arc) return radius - std::sqrt(radius * radius - (flat - x) * (flat - x));
    return radius * (1 - std::cos(theta)) + (arc - x) * std::tan(theta);
  };
  runout::GridShape g{120, 20, cell, cell};
  std::vector<double> b(g.cells());
  for (std::size_t j = 0; j < g.ny; ++j)
    for (std::size_t i = 0; i < g.nx; ++i) b[g.index(i, j)] = bed((i + 0.5) * cell);
  runout::Terrain terrain(g, b);
  Seeded seeded = seed_particles(g, block_depth(g, 4, 16, 5, 15, 0.2), 0.2 * cell * cell / 4, 2400);
  HybridSolver solver(terrain, stiff_params(0.0), seeded.particles, seeded.spacing);
  auto potential = [&] {
    double e = 0.0;
    for (std::size_t k = 0; k < solver.particles().size(); ++k)
      e += solver.particles().mass[k] * 9.81 * bed(solver.particles().x[k]);
    return e;
  };
  const double e0 = potential();
  auto on_flat = [&] {
    for (double x : solver.particles().x)
      if (x < flat + 0.05) return false;
    return true;
  };
  while (!on_flat() && solver.time() < 2.0) solver.step(solver.stable_time_step());
  ASSERT_TRUE(on_flat());
  EXPECT_NEAR(solver.totals().kinetic_energy / (e0 - potential()), 1.0, 0.01);
}

// Launched down a 10 deg plane with tan phi_b = tan 20 deg > tan theta, the
// block decelerates and stops where its energy line (slope tan phi_b from
// the head z + v^2 / 2g) meets the bed: horizontal distance
// u0^2 / (2 g cos^2 (tan phi_b - tan theta)) for a horizontal speed u0.
// Symplectic Euler's error is O(u0 dt) ~ 1e-5 m here; 1e-3 m is asserted.
// Stopped, it stays (friction holds what gravity pulls).
TEST(HybridBlock, StiffBlockStopsWhereTheEnergyLineSays) {
  const double theta = deg(10.0), mu = std::tan(deg(20.0)), u0 = 1.0;
  Block b = clay_block(40, 20, theta, 4, 5, u0);
  HybridSolver solver(b.terrain, stiff_params(mu), b.seeded.particles, b.seeded.spacing);
  const double x0 = centre_x(solver.particles());
  const double cos2 = std::pow(std::cos(theta), 2);
  const double expected = u0 * u0 / (2 * 9.81 * cos2 * (mu - std::tan(theta)));
  run_to(solver, 0.7);  // stops after u0 / (g cos^2 (mu - tan)) = 0.56 s
  EXPECT_NEAR(centre_x(solver.particles()) - x0, expected, 1e-3);
  EXPECT_EQ(solver.totals().max_speed, 0.0);
}

// A weakly cohesive block (c = 0.5 kPa) at rest on a flat frictionless bed
// under gravity: the earth pressure of its weight (K_a gamma z beyond Bell's
// tension zone: with K_a = 0.3755 for 27 deg, 75.5 N/m over the 0.2 m depth)
// pushes its edges out and its elastic stress holds it in tension, ~380 Pa,
// below the cone (k_c = 0.43 kPa). The elastic stretch is P / (h E) ~ 2e-5:
// edges move ~3 microns. Asserted: after 0.3 s
// no particle has moved 0.5 mm, the closest pair is no closer than half the
// initial closest (no clumping) and the block has calmed (speed < 1 mm/s).
TEST(HybridBlock, WeakBlockAtRestStaysAtRestWithoutClumping) {
  Block b = clay_block(30, 25, 0.0, 9, 8);
  HybridParams params = stiff_params(0.0);
  params.material = clay(500.0);
  HybridSolver solver(b.terrain, params, b.seeded.particles, b.seeded.spacing);
  EXPECT_NEAR(solver.lateral_force(0.2, 500.0, 9.81), 75.5, 0.1);  // by hand above
  const Particles start = solver.particles();
  const double closest0 = closest_pair(start);
  run_to(solver, 0.3);
  const Particles& p = solver.particles();
  double moved = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k)
    moved = std::max(moved, std::hypot(p.x[k] - start.x[k], p.y[k] - start.y[k]));
  EXPECT_LT(moved, 5e-4);
  EXPECT_GT(closest_pair(p), 0.5 * closest0);
  EXPECT_LT(solver.totals().max_speed, 1e-3);
  for (std::size_t k = 0; k < p.size(); ++k) ASSERT_FALSE(p.state[k].yielding) << k;
}

// Stress forces are pairwise equal and opposite (symmetric in i and j with an
// antisymmetric kernel gradient): an elastic block stretched by an initial
// velocity field on a frictionless flat bed, away from the walls, keeps its
// momentum to round-off (1e-12 of the momentum scale m |v|), and with the
// artificial stress its particles do not clump while it rings in tension.
TEST(HybridBlock, StretchedBlockKeepsMomentumAndDoesNotClump) {
  Block b = clay_block(40, 35, 0.0, 14, 12);
  Particles& p0 = b.seeded.particles;
  for (std::size_t k = 0; k < p0.size(); ++k) {
    p0.u[k] = 0.5 * (p0.x[k] - 0.5) + 0.1;  // stretching along x, drifting
    p0.v[k] = 0.2 * (p0.y[k] - 0.425);
  }
  HybridParams params = stiff_params(0.0);
  params.gravity = 0.0;
  HybridSolver solver(b.terrain, params, p0, b.seeded.spacing);
  const HybridTotals t0 = solver.totals();
  const double closest0 = closest_pair(solver.particles());
  run_to(solver, 0.05);
  const HybridTotals t = solver.totals();
  const double scale = t0.mass * 0.2;
  EXPECT_NEAR(t.momentum_x, t0.momentum_x, 1e-12 * scale);
  EXPECT_NEAR(t.momentum_y, t0.momentum_y, 1e-12 * scale);
  EXPECT_LE(t.kinetic_energy, t0.kinetic_energy * 1.001);  // dissipative at most
  EXPECT_GT(closest_pair(solver.particles()), 0.5 * closest0);
}

// A weak block (c = 2 kPa, cohesion loss averaged over 5 cm) stretched apart
// on a slope: it yields and loses cohesion, through every path of the step,
// with the same bits on one and two threads.
TEST(HybridBlock, SameBitsOnOneAndTwoThreads) {
  auto run = [](int threads) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    Block b = clay_block(40, 20, deg(25.0), 4, 5);
    for (std::size_t k = 0; k < b.seeded.particles.size(); ++k)
      b.seeded.particles.u[k] = 2.0 * (b.seeded.particles.x[k] - 0.25);
    HybridParams params = stiff_params(std::tan(deg(20.0)));
    params.material = clay(2e3);
    params.material.critical_volume_strain = 0.01;
    params.material.nonlocal_length = 0.05;
    HybridSolver solver(b.terrain, params, b.seeded.particles, b.seeded.spacing);
    run_to(solver, 0.02);
    omp_set_num_threads(before);
    double lowest = 1.0;
    for (std::size_t k = 0; k < solver.particles().size(); ++k)
      lowest = std::min(lowest, solver.strength_fraction(k));
    return std::make_pair(solver.particles(), lowest);
  };
  const auto [one, lowest] = run(1);
  const auto [two, lowest2] = run(2);
  EXPECT_LT(lowest, 0.5);  // the loss ran
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    ASSERT_EQ(one.x[k], two.x[k]) << k;
    ASSERT_EQ(one.u[k], two.u[k]) << k;
    ASSERT_EQ(one.state[k].cohesion, two.state[k].cohesion) << k;
  }
}

// A stiff block sliding at 1 m/s into a wall of no-data cells across its
// path (flat bed, tan phi_b = 0.3; on its own it would stop after
// 1 / (2 g 0.3) = 0.17 m, the wall is 0.1 m ahead): its front reaches the
// wall, no particle ever enters the wall's cells, and the rebound dies out
// (kinetic energy < 1 % of the start after 0.6 s).
TEST(HybridBlock, ObstacleCellsAreWalls) {
  runout::Terrain flat = plane(30, 20, kCell, 0.0);
  std::vector<unsigned char> inside(flat.shape().cells(), 1);
  for (std::size_t j = 0; j < 20; ++j)
    for (std::size_t i = 20; i < 30; ++i) inside[flat.shape().index(i, j)] = 0;
  runout::Terrain terrain(flat.shape(), flat.elevation(), inside);
  const auto depth = block_depth(terrain.shape(), 4, 16, 5, 15, 0.2);
  Seeded seeded = seed_particles(terrain.shape(), depth, 0.2 * kCell * kCell / 4, 2400.0, 1.0);
  HybridSolver solver(terrain, stiff_params(0.3), seeded.particles, seeded.spacing);
  const double wall = 20 * kCell, energy0 = solver.totals().kinetic_energy;
  double reached = 0.0;
  while (solver.time() < 0.6) {
    solver.step(solver.stable_time_step());
    for (double x : solver.particles().x) {
      ASSERT_LE(x, wall) << "t = " << solver.time();
      reached = std::max(reached, x);
    }
  }
  EXPECT_GT(reached, wall - 0.5 * kCell);
  EXPECT_LT(solver.totals().kinetic_energy, 0.01 * energy0);
  // Particles may not start inside a wall.
  Particles in_wall = seeded.particles;
  in_wall.x[0] = wall + 0.01;
  EXPECT_THROW(HybridSolver(terrain, stiff_params(0.3), in_wall, seeded.spacing), InputError);
}

TEST(HybridBlock, RefusesBadInput) {
  Block b = clay_block(30, 25, 0.0, 9, 8);
  HybridParams params = stiff_params(0.3);
  params.material.model = "linear_elastic";
  EXPECT_THROW(HybridSolver(b.terrain, params, b.seeded.particles, b.seeded.spacing), InputError);
  params = stiff_params(0.3);
  params.smoothing_length = 0.0;
  EXPECT_THROW(HybridSolver(b.terrain, params, b.seeded.particles, b.seeded.spacing), InputError);
  Particles outside = b.seeded.particles;
  outside.x[3] = 7.0;
  EXPECT_THROW(HybridSolver(b.terrain, stiff_params(0.3), outside, b.seeded.spacing), InputError);
  EXPECT_THROW(seed_particles(b.terrain.shape(), std::vector<double>(3, 0.1), 1e-5, 2400.0),
               InputError);
}

}  // namespace
}  // namespace talus::hybrid
