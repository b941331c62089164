// MPM checkpoints (mpm/checkpoint.hpp): a run saved, restored into a solver
// built afresh from the same scenario and continued ends bit for bit where
// the uninterrupted run ends, with cohesion loss and a turning rigid body in
// play; a checkpoint that does not fit the scenario is refused.
#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <filesystem>

#include "talus/core/error.hpp"
#include "talus/mpm/checkpoint.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::mpm {
namespace {

// A cohesive Drucker-Prager block with cohesion loss thrown onto a rigid plate
// that turns about a hinge (as tests/data/scenarios/mpm_resume.toml).
MpmScenario block_on_turning_plate() {
  MpmScenario sc;
  sc.dimension = 2;
  sc.solver.gravity = Vec3(0.0, -10.0, 0.0);
  sc.grid.lo = Vec3(0.0, 0.0, 0.0);
  sc.grid.hi = Vec3(0.4, 0.3, 0.0);
  sc.grid.cell_size = 0.01;
  sc.grid.faces.fill(BoundaryKind::Free);
  MaterialParams m;
  m.name = "clay";
  m.model = MaterialModel::DruckerPrager;
  m.density = 2000.0;
  m.youngs_modulus = 1e6;
  m.poisson_ratio = 0.3;
  m.friction_angle = deg2rad(25.0);
  m.cohesion = 2000.0;
  m.critical_volume_strain = 0.01;
  sc.materials = {m};
  BodyParams b;
  b.material = "clay";
  b.min = Vec3(0.15, 0.12, 0.0);
  b.max = Vec3(0.25, 0.17, 0.0);
  b.velocity = Vec3(0.0, -1.0, 0.0);
  sc.bodies = {b};
  RigidBodyParams plate;
  plate.min = Vec3(0.05, 0.07, 0.0);
  plate.max = Vec3(0.35, 0.1, 0.0);
  plate.friction = 0.3;
  plate.motion.hinge = Vec3(0.2, 0.1, 0.0);
  plate.motion.angular_velocity = Vec3(0.0, 0.0, deg2rad(20.0));
  sc.rigid_bodies = {plate};
  return sc;
}

TEST(MpmCheckpoint, ResumedRunEndsBitForBitLikeTheUninterruptedOne) {
  const auto sc = block_on_turning_plate();
  const auto path = std::filesystem::temp_directory_path() /
                    ("talus_mpm_checkpoint_test_" + std::to_string(::getpid()) + ".bin");
  Solver<2> full = build_mpm<2>(sc);
  for (int k = 0; k < 300; ++k) full.advance();
  save_checkpoint(full, path);
  for (int k = 0; k < 300; ++k) full.advance();

  Solver<2> resumed = build_mpm<2>(sc);
  load_checkpoint(resumed, path);
  EXPECT_EQ(resumed.steps, 300);
  for (int k = 0; k < 300; ++k) resumed.advance();
  std::filesystem::remove(path);

  // The run exercised the state: cohesion was lost, the plate turned.
  int cracked = 0;
  for (const auto& st : full.particles.state) cracked += st.cohesion < 2000.0;
  EXPECT_GT(cracked, 0);
  EXPECT_GT(full.rigid_bodies[0].angle, 0.0);
  EXPECT_EQ(resumed.time, full.time);
  for (std::size_t i = 0; i < full.particles.size(); ++i) {
    ASSERT_EQ(resumed.particles.x[i], full.particles.x[i]) << i;
    ASSERT_EQ(resumed.particles.v[i], full.particles.v[i]) << i;
    ASSERT_EQ(resumed.particles.volume[i], full.particles.volume[i]) << i;
    ASSERT_EQ(resumed.particles.state[i].stress, full.particles.state[i].stress) << i;
    ASSERT_EQ(resumed.particles.state[i].cohesion, full.particles.state[i].cohesion) << i;
  }
  EXPECT_EQ(resumed.rigid_bodies[0].x, full.rigid_bodies[0].x);
  EXPECT_EQ(resumed.rigid_bodies[0].angle, full.rigid_bodies[0].angle);
}

TEST(MpmCheckpoint, CheckpointOfAnotherScenarioIsRefused) {
  auto sc = block_on_turning_plate();
  const auto path = std::filesystem::temp_directory_path() /
                    ("talus_mpm_checkpoint_other_" + std::to_string(::getpid()) + ".bin");
  save_checkpoint(build_mpm<2>(sc), path);
  sc.bodies[0].max = Vec3(0.3, 0.17, 0.0);  // more points
  Solver<2> other = build_mpm<2>(sc);
  EXPECT_THROW(load_checkpoint(other, path), InputError);
  sc = block_on_turning_plate();
  sc.rigid_bodies.clear();
  Solver<2> no_plate = build_mpm<2>(sc);
  EXPECT_THROW(load_checkpoint(no_plate, path), InputError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace talus::mpm
