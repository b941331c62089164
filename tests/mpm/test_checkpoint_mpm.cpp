// MPM checkpoints (mpm/checkpoint.hpp): a run saved, restored into a solver
// built afresh from the same scenario and continued ends bit for bit where
// the uninterrupted run ends, with cohesion loss and a turning rigid body in
// play, and with membranes (2D FE cables and a York line, 3D triangles); a
// checkpoint that does not fit the scenario, or of an older format, is
// refused.
#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <filesystem>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"
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
  m.model = DruckerPrager::name;
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
  EXPECT_NE(full.rigid_bodies[0].work, 0.0);
  EXPECT_EQ(resumed.rigid_bodies[0].work, full.rigid_bodies[0].work);
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

// Runs `steps`, saves, runs `steps` more; a solver built afresh, restored and
// run `steps` must end with the same membranes, bit for bit.
template <int D>
void check_membranes_resume(const MpmScenario& sc, int steps, const std::string& tag) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("talus_mpm_checkpoint_" + tag + std::to_string(::getpid()) + ".bin");
  Solver<D> full = build_mpm<D>(sc);
  for (int k = 0; k < steps; ++k) full.advance();
  save_checkpoint(full, path);
  for (int k = 0; k < steps; ++k) full.advance();
  Solver<D> resumed = build_mpm<D>(sc);
  load_checkpoint(resumed, path);
  for (int k = 0; k < steps; ++k) resumed.advance();
  std::filesystem::remove(path);
  EXPECT_EQ(resumed.time, full.time);
  for (std::size_t i = 0; i < full.particles.size(); ++i)
    ASSERT_EQ(resumed.particles.x[i], full.particles.x[i]) << i;
  for (std::size_t b = 0; b < full.membranes.size(); ++b) {
    const auto &m = full.membranes[b], &r = resumed.membranes[b];
    // The membrane was loaded: its state mattered.
    EXPECT_GT(m.max_tension(), 0.0) << tag << " " << m.name;
    EXPECT_EQ(r.x, m.x) << m.name;
    EXPECT_EQ(r.v, m.v) << m.name;
    EXPECT_EQ(r.stretch, m.stretch) << m.name;
    EXPECT_EQ(r.tangent, m.tangent) << m.name;
  }
}

// An FE bag (closed, cables) around the block of the test above, falling at
// 1 m/s.
MembraneParams falling_bag() {
  MembraneParams bag;
  bag.name = "bag";
  bag.points = {Vec3(0.145, 0.115, 0.0), Vec3(0.255, 0.115, 0.0), Vec3(0.255, 0.175, 0.0),
                Vec3(0.145, 0.175, 0.0)};
  bag.closed = true;
  bag.spacing = 0.005;
  bag.stiffness = 2e4;
  bag.areal_mass = 0.5;
  bag.velocity = Vec3(0.0, -1.0, 0.0);
  return bag;
}

// The block falls in the bag, which hangs on nothing, onto a York line held
// at both ends.
TEST(MpmCheckpoint, RunWithMembranesResumesBitForBit) {
  auto sc = block_on_turning_plate();
  sc.rigid_bodies.clear();
  MembraneParams bag = falling_bag();
  MembraneParams line = bag;
  line.name = "line";
  line.model = MembraneModel::York;
  line.points = {Vec3(0.03, 0.11, 0.0), Vec3(0.37, 0.11, 0.0)};
  line.closed = false;
  line.fixed = MembraneFixed::Both;
  line.velocity = Vec3::Zero();
  sc.membranes = {bag, line};
  check_membranes_resume<2>(sc, 300, "2d");
}

// The same fall into a bag whose sand slips on it (its own velocity field,
// field_contact.hpp), onto an FE line held at both ends in the soil's field:
// nothing of the bag's field is carried between steps, so the membranes'
// checkpointed state is all a resume needs.
TEST(MpmCheckpoint, RunWithSlippingMembraneResumesBitForBit) {
  auto sc = block_on_turning_plate();
  sc.rigid_bodies.clear();
  MembraneParams bag = falling_bag();
  MembraneParams line = bag;
  line.name = "line";
  line.points = {Vec3(0.03, 0.11, 0.0), Vec3(0.37, 0.11, 0.0)};
  line.closed = false;
  line.fixed = MembraneFixed::Both;
  line.velocity = Vec3::Zero();
  bag.soil_friction = 0.4;
  sc.membranes = {bag, line};
  check_membranes_resume<2>(sc, 300, "2d_slip");
}

// 3D: a block falls onto a sheet of triangles held by its edges.
TEST(MpmCheckpoint, RunWithTriangleMembraneResumesBitForBit) {
  MpmScenario sc;
  sc.dimension = 3;
  sc.solver.gravity = Vec3(0.0, 0.0, -10.0);
  sc.grid.lo = Vec3::Zero();
  sc.grid.hi = Vec3::Constant(0.3);
  sc.grid.cell_size = 0.02;
  sc.grid.faces.fill(BoundaryKind::Free);
  MaterialParams m;
  m.name = "block";
  m.model = LinearElastic::name;
  m.density = 2000.0;
  m.youngs_modulus = 1e6;
  m.poisson_ratio = 0.3;
  sc.materials = {m};
  BodyParams b;
  b.material = "block";
  b.min = Vec3(0.12, 0.12, 0.16);
  b.max = Vec3(0.18, 0.18, 0.2);
  b.velocity = Vec3(0.0, 0.0, -1.0);
  sc.bodies = {b};
  MembraneParams p;
  p.name = "sheet";
  p.shape = MembraneShape::Sheet;
  p.points = {Vec3(0.05, 0.05, 0.14), Vec3(0.25, 0.05, 0.14), Vec3(0.25, 0.25, 0.14),
              Vec3(0.05, 0.25, 0.14)};
  p.fixed = MembraneFixed::Edges;
  p.spacing = 0.01;
  p.stiffness = 2e4;
  p.areal_mass = 0.5;
  p.poisson_ratio = 0.3;
  sc.membranes = {p};
  check_membranes_resume<3>(sc, 150, "3d");
}

// A checkpoint of format version 1 (before membranes were stored) is refused
// with its version named.
TEST(MpmCheckpoint, OlderFormatIsRefusedWithItsVersion) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("talus_mpm_checkpoint_v1_" + std::to_string(::getpid()) + ".bin");
  io::ArchiveWriter w;
  w.put("talus-mpm-checkpoint");
  w.put(int32_t{1});
  w.save(path);
  Solver<2> s = build_mpm<2>(block_on_turning_plate());
  try {
    load_checkpoint(s, path);
    ADD_FAILURE() << "version 1 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("version 1"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace talus::mpm
