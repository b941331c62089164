// The plan-view bed of a 2D run ([run] plan_view: Coulomb friction mu g_n on
// every node against its trial velocity): an elastic block on the bed must
// move as a rigid Coulomb slider, since every node feels the same friction per
// unit mass. Checks: at rest below tan(theta) = mu, sliding at
// g (sin - mu cos) above it, and a block launched obliquely on a level bed
// stopping along its launch direction after v0^2 / (2 mu g_n).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>

#include "mpm_test_support.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::mpm {
namespace {

using V2 = Eigen::Vector2d;
constexpr double kMu = 0.4, kG = 9.81;

// Elastic block 0.1 x 0.08 m in plan view, h = 10 mm, GIMP, 2x2 points per
// cell, on a bed sloping by theta down +x (gravity along the bed g sin(theta),
// normal g cos(theta)).
MpmScenario block_on_bed(double theta, const V2& v0) {
  MpmScenario sc;
  sc.dimension = 2;
  sc.solver.shape = ShapeKind::Gimp;
  sc.solver.gravity = Vec3(kG * std::sin(theta), 0.0, 0.0);
  sc.solver.basal_friction = kMu;
  sc.solver.bed_normal_gravity = kG * std::cos(theta);
  sc.grid.lo = Vec3(0.0, 0.0, 0.0);
  sc.grid.hi = Vec3(1.0, 0.6, 0.0);
  sc.grid.cell_size = 0.01;
  sc.grid.faces.fill(BoundaryKind::Free);
  MaterialParams m;
  m.name = "block";
  m.model = LinearElastic::name;
  m.density = 2000.0;
  m.youngs_modulus = 2e6;
  m.poisson_ratio = 0.3;
  sc.materials = {m};
  BodyParams block;
  block.material = "block";
  block.min = Vec3(0.1, 0.1, 0.0);
  block.max = Vec3(0.2, 0.18, 0.0);
  block.velocity = Vec3(v0.x(), v0.y(), 0.0);
  sc.bodies = {block};
  return sc;
}

V2 centre(const Solver<2>& s) {
  V2 c = V2::Zero();
  double m = 0.0;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    c += s.particles.mass[i] * s.particles.x[i];
    m += s.particles.mass[i];
  }
  return c / m;
}

// Below the friction angle (tan 20 deg = 0.36 < 0.4) a block at rest stays:
// the node's trial velocity g sin(theta) dt is below mu g cos(theta) dt. The
// bound, 1e-9 m over 0.3 s, is round-off (no elastic waves: no stress at start
// and none induced).
TEST(MpmPlanView, BlockBelowFrictionAngleStaysAtRest) {
  const OneThread one;
  Solver<2> s = build_mpm<2>(block_on_bed(deg2rad(20.0), V2::Zero()));
  const V2 c0 = centre(s);
  while (s.time < 0.3) s.advance();
  EXPECT_LT((centre(s) - c0).norm(), 1e-9);
}

// Above it (30 deg) the block slides from rest at g (sin - mu cos) = 1.508
// m/s^2: after 0.3 s it has moved a t^2 / 2 along x and not across. The
// tolerance, 0.5 % of the distance, bounds the explicit stepping's error
// (first-order in dt, a few 1e-5 s against 0.3 s).
TEST(MpmPlanView, BlockAboveFrictionAngleSlidesAtCoulombAcceleration) {
  const OneThread one;
  const double theta = deg2rad(30.0);
  Solver<2> s = build_mpm<2>(block_on_bed(theta, V2::Zero()));
  const V2 c0 = centre(s);
  while (s.time < 0.3) s.advance();
  const double a = kG * (std::sin(theta) - kMu * std::cos(theta));
  const double expected = 0.5 * a * s.time * s.time;
  const V2 moved = centre(s) - c0;
  std::printf("slid %.6f m, expected %.6f (ratio %.5f)\n", moved.x(), expected,
              moved.x() / expected);
  EXPECT_NEAR(moved.x(), expected, 5e-3 * expected);
  EXPECT_NEAR(moved.y(), 0.0, 1e-9);
}

// Level bed, launched at 1 m/s at 30 deg to x: friction opposes the velocity,
// so the block decelerates at mu g along its launch direction and stops after
// v0^2 / (2 mu g) = 0.1274 m, then stays. Tolerance 0.5 % as above.
TEST(MpmPlanView, LaunchedBlockStopsAlongItsDirectionAfterCoulombDistance) {
  const OneThread one;
  const V2 dir(std::cos(deg2rad(30.0)), std::sin(deg2rad(30.0)));
  Solver<2> s = build_mpm<2>(block_on_bed(0.0, dir));
  const V2 c0 = centre(s);
  while (s.time < 0.4) s.advance();  // the stop is at 1 / (mu g) = 0.255 s
  const V2 moved = centre(s) - c0;
  const double expected = 1.0 / (2.0 * kMu * kG);
  std::printf("stopped after %.6f m, expected %.6f; direction off by %.2e\n", moved.norm(),
              expected, std::abs(moved.normalized().dot(V2(-dir.y(), dir.x()))));
  EXPECT_NEAR(moved.norm(), expected, 5e-3 * expected);
  EXPECT_NEAR(moved.normalized().dot(V2(-dir.y(), dir.x())), 0.0, 1e-9);
  EXPECT_LT(centre_of_mass_velocity(s.particles).norm(), 1e-9);
}

}  // namespace
}  // namespace talus::mpm
