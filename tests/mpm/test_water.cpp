// Still water in MPM ([run.water], mpm/water.hpp): buoyancy and added mass on
// the submerged points, drag on the membranes' faces moving into the water.
//  - A block released under water accelerates at g (rho_s - rho_w) /
//    (rho_s + C_a rho_w) (a uniform body force: every point alike); a block
//    as dense as the water stays at rest; above the level it falls at g.
//  - A bag (a closed membrane around a block) sinks to the terminal velocity
//    where drag on its bottom face balances its submerged weight:
//    v_t = sqrt(2 (rho_s - rho_w) g V / (rho_w C_d W)).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>

#include "mpm_scenario_cases.hpp"
#include "mpm_test_support.hpp"
#include "talus/mpm/health.hpp"
#include "talus/mpm/scenario.hpp"
#include "talus/scenario/scenario_mpm.hpp"

namespace talus::mpm {
namespace {

constexpr double kG = 9.81;

// An elastic block 0.2 x 0.1 m (E = 1 MPa, nu = 0.3, 2 x 2 points per cell,
// h = 20 mm) at rest in a tall free grid, water of 1000 kg/m^3 up to `level`.
MpmScenario block_in_water(double density, double level, double added_mass) {
  MpmScenario sc;
  sc.dimension = 2;
  sc.solver.gravity = Vec3(0.0, -kG, 0.0);
  sc.solver.water.level = level;
  sc.solver.water.density = 1000.0;
  sc.solver.water.drag_coefficient = 1.0;
  sc.solver.water.added_mass_coefficient = added_mass;
  sc.grid.lo = Vec3::Zero();
  sc.grid.hi = Vec3(0.4, 2.6, 0.0);
  sc.grid.cell_size = 0.02;
  sc.grid.faces.fill(BoundaryKind::Free);
  sc.materials = {elastic_material("block", density, 1e6, 0.3)};
  BodyParams block;
  block.material = "block";
  block.min = Vec3(0.1, 2.3, 0.0);
  block.max = Vec3(0.3, 2.4, 0.0);
  sc.bodies = {block};
  return sc;
}

double fall_speed_after(MpmScenario sc, double t) {
  Solver<2> s = build_mpm<2>(sc);
  while (s.time < t) s.step(std::min(s.time_step(), t - s.time));
  return -centre_of_mass_velocity(s.particles).y();
}

TEST(MpmWater, SubmergedBlockAcceleratesAtTheReducedRate) {
  const OneThread one;
  const double t = 0.1;
  for (double ca : {0.0, 1.0}) {
    const double expected = kG * (2000.0 - 1000.0) / (2000.0 + ca * 1000.0) * t;
    const double v = fall_speed_after(block_in_water(2000.0, 2.5, ca), t);
    std::printf("C_a = %g: speed %.9f m/s after %g s, expected %.9f\n", ca, v, t, expected);
    // Exact but for round-off: the same body force on every point.
    EXPECT_NEAR(v / expected, 1.0, 1e-9);
  }
  EXPECT_NEAR(fall_speed_after(block_in_water(1000.0, 2.5, 1.0), t), 0.0, 1e-12);
  // Above the water (level below the block): free fall.
  EXPECT_NEAR(fall_speed_after(block_in_water(2000.0, 1.0, 1.0), t) / (kG * t), 1.0, 1e-9);
}

// The block inside a closed FE membrane (J = 1e4 N/m, 0.1 kg/m^2, nodes 10 mm
// apart) drawn 5 mm outside it, C_d = 1, C_a = 1: v_t = sqrt(2 * 1000 * 9.81
// * 0.02 / (1000 * 1 * 0.21)) = 1.3669 m/s (W = 0.21 m, the membrane's bottom
// width; the membrane's own 0.06 kg/m adds 0.1 %; the corner nodes, whose
// normals lie at 45 degrees, take 1.4 % less drag than their bottom share:
// v_t 0.7 % higher). Sinking from rest it reaches 99 % of v_t after about
// 1.4 s; the speed is read at 1.8 s. Tolerance 3 %, fixed before the first
// run. Measured 1.3934 m/s (1.019); the drag taken from the membrane nodes'
// own FLIP velocities gave 1.4405 (1.054), with PIC throughout 1.3855.
TEST(MpmWater, BagSinksAtItsTerminalVelocity) {
  const OneThread one;
  MpmScenario sc = block_in_water(2000.0, 2.55, 1.0);
  MembraneParams bag;
  bag.name = "bag";
  bag.points = {Vec3(0.095, 2.295, 0.0), Vec3(0.305, 2.295, 0.0), Vec3(0.305, 2.405, 0.0),
                Vec3(0.095, 2.405, 0.0)};
  bag.closed = true;
  bag.spacing = 0.01;
  bag.stiffness = 1e4;
  bag.areal_mass = 0.1;
  sc.membranes = {bag};
  const double vt = std::sqrt(2.0 * 1000.0 * kG * 0.02 / (1000.0 * 1.0 * 0.21));
  const double v = fall_speed_after(sc, 1.8);
  std::printf("bag: speed %.4f m/s at 1.8 s, terminal %.4f (ratio %.4f)\n", v, vt, v / vt);
  EXPECT_NEAR(v / vt, 1.0, 0.03);
}

// The block resting on a rough floor, half under water (level 0.05 m above
// its base), with a geostatic start and nu = 0 (K0 = 0: its free sides carry
// no lateral stress): the skeleton carries (rho - rho_w) g below the level,
// so it starts in equilibrium and stays at rest. Measured after 0.1 s: the
// fastest point 2.1e-17 m/s; with rho g throughout (no buoyancy in the
// initial stress), 4.5e-3 m/s.
TEST(MpmWater, GeostaticStartUnderWaterIsInEquilibrium) {
  const OneThread one;
  MpmScenario sc = block_in_water(2000.0, 0.05, 1.0);
  sc.materials[0].poisson_ratio = 0.0;
  sc.grid.faces[2] = BoundaryKind::Fixed;
  sc.bodies[0].min = Vec3(0.1, 0.0, 0.0);
  sc.bodies[0].max = Vec3(0.3, 0.1, 0.0);
  sc.bodies[0].geostatic = true;
  Solver<2> s = build_mpm<2>(sc);
  while (s.time < 0.1) s.advance();
  double fastest = 0.0;
  for (const auto& v : s.particles.v) fastest = std::max(fastest, v.norm());
  std::printf("half-submerged geostatic block: fastest point %.3e m/s after 0.1 s\n", fastest);
  EXPECT_LT(fastest, 1e-9);
}

TEST(MpmWater, ScenarioTableParsesAndRoundTrips) {
  const std::string base = R"(method = "mpm"
[run]
dimension = 2
duration = 0.5
[run.water]
level = 1.5
drag_coefficient = 1.2
added_mass_coefficient = 2
[grid]
min = [0, 0]
max = [2, 2]
cell_size = 0.1
[[materials]]
name = "sand"
model = "linear_elastic"
density = 2000
youngs_modulus = 1e6
poisson_ratio = 0.3
[[bodies]]
material = "sand"
box = { min = [0.5, 0.5], max = [1.0, 1.0] }
)";
  const auto sc = io::parse_mpm_scenario(io::load_scenario_text(base, "w.toml"));
  EXPECT_EQ(sc.solver.water.level, 1.5);
  EXPECT_EQ(sc.solver.water.density, 1000.0);
  EXPECT_EQ(sc.solver.water.drag_coefficient, 1.2);
  EXPECT_EQ(sc.solver.water.added_mass_coefficient, 2.0);
  const auto again =
      io::parse_mpm_scenario(io::load_scenario_text(io::mpm_scenario_to_toml(sc), "r.toml"));
  EXPECT_EQ(io::mpm_scenario_to_json(again).dump(), io::mpm_scenario_to_json(sc).dump());
  using io::mpm_cases::edit;
  using io::mpm_cases::expect_error;
  expect_error(edit(base, "drag_coefficient = 1.2\n", ""), "[run.water] 'drag_coefficient'");
  expect_error(edit(base, "level = 1.5", "level = 1.5\ndensity = -1"), "'density'");
  expect_error(edit(base, "level = 1.5", "levle = 1.5"), "did you mean 'level'");
}

}  // namespace
}  // namespace talus::mpm
