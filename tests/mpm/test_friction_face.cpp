// Frictional grid faces (BoundaryKind::Friction, `boundaries = { y_min = {
// friction = mu } }`): Bardenhagen et al.'s (2000) Coulomb contact against a
// wall at rest, applied at the nodes of the face (mpm.md "Boundaries and
// contact"). The rule on single nodes; a block sliding on a frictional floor
// decelerates at mu g until it stops (2D and 3D); on a tilted floor it stays
// at rest when tan(theta) < mu and slides at g (sin(theta) - mu cos(theta))
// when tan(theta) > mu; mu = 0 gives the roller's run bit for bit.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>

#include "mpm_test_support.hpp"
#include "talus/mpm/health.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::mpm {
namespace {

using V2 = Eigen::Vector2d;

TEST(MpmFrictionFace, CoulombRuleOnTheFaceNodes) {
  // One cell of 1 m; the floor (y_min) has mu = 0.5, x_min is a roller.
  std::array<BoundaryKind, 4> faces{BoundaryKind::Roller, BoundaryKind::Free,
                                    BoundaryKind::Friction, BoundaryKind::Free};
  Grid<2> g(V2(0.0, 0.0), V2(4.0, 2.0), 1.0, faces, {0.0, 0.0, 0.5, 0.0});
  const int w = Grid<2>::kPad;
  const auto floor = [&](int i) { return g.index({w + i, w}); };
  ASSERT_EQ(g.friction_nodes.size(), 9u);  // y = 0, x = -2 .. 6 (ghost columns too)
  std::vector<V2> v(g.nodes(), V2(9.0, 9.0));
  v[floor(1)] = V2(2.0, -1.0);   // slides: loses 0.5 * 1 of its 2 m/s
  v[floor(2)] = V2(-0.4, -1.0);  // 0.4 <= 0.5 * 1: sticks
  v[floor(3)] = V2(2.0, 0.5);    // moves away from the wall: free
  v[floor(0)] = V2(3.0, -1.0);   // corner: the roller takes x first, nothing to slide
  v[g.index({w + 3, w + 1})] = V2(0.7, 0.2);
  g.constrain_velocity(v);
  EXPECT_EQ(v[floor(1)], V2(1.5, 0.0));
  EXPECT_EQ(v[floor(2)], V2(0.0, 0.0));
  EXPECT_EQ(v[floor(3)], V2(2.0, 0.5));
  EXPECT_EQ(v[floor(0)], V2(0.0, 0.0));
  // The ghost below the floor mirrors the node above it as a roller's would:
  // the normal component odd, the tangential one even.
  EXPECT_EQ(v[g.index({w + 3, w - 1})], V2(0.7, -0.2));
  // velocity_old: roller-like (normal zeroed) where the last velocity update
  // touched the wall, untouched where it left it.
  std::vector<V2> old(g.nodes(), V2(1.0, -0.25));
  g.constrain(old);
  EXPECT_EQ(old[floor(1)], V2(1.0, 0.0));
  EXPECT_EQ(old[floor(3)], V2(1.0, -0.25));
}

// An elastic block 0.12 m long and 0.06 m high (2D; 3D: 0.12 x 0.12 x 0.06)
// on a frictional floor, in its geostatic state, E = 2.5e5 Pa, nu = 0.3,
// rho = 1000 kg/m^3, g = 10 m/s^2, 2 points per cell and axis, GIMP. The
// other faces are free.
constexpr double kG = 10.0, kMu = 0.3;

template <int D>
MpmScenario block_on_floor(double h, double mu, double v0,
                           BoundaryKind floor = BoundaryKind::Friction,
                           ShapeKind shape = ShapeKind::Gimp) {
  MpmScenario sc;
  sc.dimension = D;
  sc.solver.shape = shape;
  const int up = D - 1;
  sc.solver.gravity = Vec3::Zero();
  sc.solver.gravity[up] = -kG;
  sc.grid.lo = Vec3::Zero();
  sc.grid.hi = D == 2 ? Vec3(0.5, 0.12, 0.0) : Vec3(0.5, 0.2, 0.12);
  sc.grid.cell_size = h;
  sc.grid.faces.fill(BoundaryKind::Free);
  sc.grid.faces[2 * up] = floor;
  sc.grid.friction[2 * up] = mu;
  sc.materials = {elastic_material("block", 1000.0, 2.5e5, 0.3)};
  BodyParams block;
  block.material = "block";
  block.min = D == 2 ? Vec3(0.04, 0.0, 0.0) : Vec3(0.04, 0.04, 0.0);
  block.max = D == 2 ? Vec3(0.16, 0.06, 0.0) : Vec3(0.16, 0.16, 0.06);
  block.velocity = Vec3(v0, 0.0, 0.0);
  block.geostatic = true;
  sc.bodies = {block};
  return sc;
}

template <int D>
double centre_x(const Solver<D>& s) {
  return centre_of_mass(s.particles, 0);
}

struct Slide {
  double deceleration;  // fitted, m/s^2
  double distance;      // of the centre of mass until 1.5 stopping times, m
  double final_speed;   // of the centre of mass then, m/s
};

// v0 = 1 m/s: it stops after t_s = v0 / (mu g) = 0.333 s, v0^2 / (2 mu g) =
// 0.1667 m further. The slope is fitted between 20 % and 80 % of t_s.
template <int D>
Slide slide(double h, ShapeKind shape = ShapeKind::Gimp) {
  const double v0 = 1.0, t_stop = v0 / (kMu * kG);
  Solver<D> s = build_mpm<D>(block_on_floor<D>(h, kMu, v0, BoundaryKind::Friction, shape));
  const double x0 = centre_x(s);
  Fit fit;
  while (s.time < 1.5 * t_stop) {
    s.advance();
    if (s.time >= 0.2 * t_stop && s.time <= 0.8 * t_stop)
      fit.add(s.time, centre_of_mass_velocity(s.particles)[0]);
  }
  const Slide r{-fit.slope(), centre_x(s) - x0, centre_of_mass_velocity(s.particles).norm()};
  std::printf(
      "%dD h = %g m: deceleration %.4f m/s^2 (/ mu g = %.4f), distance %.4f m "
      "(/ (v0^2 / (2 mu g)) = %.4f), final speed %.2e m/s\n",
      D, h, r.deceleration, r.deceleration / (kMu * kG), r.distance,
      r.distance * 2 * kMu * kG / (v0 * v0), r.final_speed);
  return r;
}

// Measured (GIMP, deceleration / mu g; distance / (v0^2 / (2 mu g))):
//   2D h = 10 mm: 0.9992, 0.9988;  2D h = 5 mm:  1.0015, 1.0002;
//   3D h = 20 mm: 0.9997, 0.9990;  3D h = 10 mm: 0.9972, 1.0077.
// The two grids differ by 0.3 % (deceleration) and 0.9 % (distance); the
// tolerance, 2 %, leaves room for the elastic waves of the start (the final
// speed, 2e-3 to 1.3e-2 m/s, is their wobble about rest). The test runs the
// coarser grid of each. (The cubic B-spline, which the scenario reader
// refuses with a friction face, gives 0.8332 at 10 mm and 1.6407 at 5 mm.)
TEST(MpmFrictionFace, BlockSlidingOnFloorDeceleratesAtMuG2D) {
  const OneThread one;
  const Slide r = slide<2>(0.01);
  EXPECT_NEAR(r.deceleration / (kMu * kG), 1.0, 0.02);
  EXPECT_NEAR(r.distance / (1.0 / (2 * kMu * kG)), 1.0, 0.02);
  EXPECT_LT(r.final_speed, 0.02);
}

TEST(MpmFrictionFace, BlockSlidingOnFloorDeceleratesAtMuG3D) {
  const OneThread one;
  const Slide r = slide<3>(0.02);
  EXPECT_NEAR(r.deceleration / (kMu * kG), 1.0, 0.02);
  EXPECT_NEAR(r.distance / (1.0 / (2 * kMu * kG)), 1.0, 0.02);
  EXPECT_LT(r.final_speed, 0.02);
}

// The same block on a floor tilted by theta: gravity g (sin, -cos) in the
// floor's frame. It starts at rest in the geostatic state of the normal
// component (the shear stress builds up in the first milliseconds).
Solver<2> block_on_tilted_floor(double theta) {
  MpmScenario sc = block_on_floor<2>(0.01, kMu, 0.0);
  sc.solver.gravity = Vec3(0.0, -kG * std::cos(theta), 0.0);
  Solver<2> s = build_mpm<2>(sc);
  s.params.gravity = Vec3(kG * std::sin(theta), -kG * std::cos(theta), 0.0);
  return s;
}

// tan(theta) = mu / 2: after 0.3 s the block has moved less than 0.1 mm
// (sliding freely it would have moved g sin(theta) t^2 / 2 = 67 mm; the
// Coulomb law allows no creep where it sticks).
TEST(MpmFrictionFace, BlockStaysAtRestOnFloorFlatterThanAtanMu) {
  const OneThread one;
  Solver<2> s = block_on_tilted_floor(std::atan(0.5 * kMu));
  const double x0 = centre_x(s);
  while (s.time < 0.3) s.advance();
  std::printf("tan(theta) = mu/2: moved %.3e m in 0.3 s\n", centre_x(s) - x0);
  EXPECT_LT(std::abs(centre_x(s) - x0), 1e-4);
}

// theta = atan(mu) + 10 deg: acceleration g (sin - mu cos) = 1.8129 m/s^2,
// fitted over 0.1 to 0.3 s; measured 1.8142 (h = 10 mm). Tolerance 2 %, as
// on the level floor.
TEST(MpmFrictionFace, BlockSlidesDownFloorSteeperThanAtanMu) {
  const OneThread one;
  const double theta = std::atan(kMu) + deg2rad(10.0);
  Solver<2> s = block_on_tilted_floor(theta);
  Fit fit;
  while (s.time < 0.3) {
    s.advance();
    if (s.time >= 0.1) fit.add(s.time, centre_of_mass_velocity(s.particles)[0]);
  }
  const double expected = kG * (std::sin(theta) - kMu * std::cos(theta));
  std::printf("theta = %.2f deg: acceleration %.4f m/s^2, expected %.4f (ratio %.4f)\n",
              rad2deg(theta), fit.slope(), expected, fit.slope() / expected);
  EXPECT_NEAR(fit.slope() / expected, 1.0, 0.02);
}

// mu = 0 is the roller wherever the material presses on the wall: every
// particle's state equal bit for bit after 0.1 s of sliding, with GIMP and
// with the cubic B-spline (ghost nodes; the scenario reader refuses friction
// faces with it, the code path is the same), FLIP and APIC. Where a node
// moves away from the wall the two differ (the roller holds it): with
// nu = 0 the geostatic block (sigma_xx = 0) is in equilibrium, sends no
// waves, and no floor node leaves the wall.
template <int D>
void expect_same_as_roller(ShapeKind shape, Transfer transfer) {
  MpmScenario friction = block_on_floor<D>(0.02, 0.0, 1.0, BoundaryKind::Friction, shape);
  MpmScenario roller = block_on_floor<D>(0.02, 0.0, 1.0, BoundaryKind::Roller, shape);
  friction.solver.transfer = roller.solver.transfer = transfer;
  friction.materials[0].poisson_ratio = roller.materials[0].poisson_ratio = 0.0;
  Solver<D> a = build_mpm<D>(friction), b = build_mpm<D>(roller);
  while (a.time < 0.1) {
    a.advance();
    b.advance();
  }
  ASSERT_EQ(a.steps, b.steps);
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    ASSERT_EQ(a.particles.x[i], b.particles.x[i]) << i;
    ASSERT_EQ(a.particles.v[i], b.particles.v[i]) << i;
    ASSERT_EQ(a.particles.state[i].stress, b.particles.state[i].stress) << i;
  }
}

TEST(MpmFrictionFace, ZeroFrictionIsTheRollerBitForBit) {
  const OneThread one;
  expect_same_as_roller<2>(ShapeKind::Gimp, Transfer::FlipPic);
  expect_same_as_roller<2>(ShapeKind::CubicBSpline, Transfer::FlipPic);
  expect_same_as_roller<2>(ShapeKind::CubicBSpline, Transfer::Apic);
  expect_same_as_roller<3>(ShapeKind::Gimp, Transfer::FlipPic);
}

}  // namespace
}  // namespace talus::mpm
