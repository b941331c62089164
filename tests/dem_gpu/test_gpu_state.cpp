// The GPU backend's state across the run loop's seams: checkpoints (the CPU
// stepper's format, in both directions) and walls with prescribed motion.
// Tolerances: the backend sums forces in another order than the CPU stepper,
// and a resumed run rebuilds its list at once; both are round-off differences,
// bounded by 1e-9 relative as in test_gpu_collapse.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "dem/peer_case.hpp"
#include "dem_gpu/test_backend.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem/checkpoint.hpp"

using namespace talus;
using namespace talus::dem;

namespace {

// 3 000 steps on the backend, a checkpoint, 1 000 more; the checkpoint resumed
// on the backend and on the CPU stepper gives the same state 1 000 steps on.
TEST(GpuBackendState, CheckpointsResumeOnEitherBackend) {
  DemScenario sc = cases::peer_column(10, 5, 20);
  sc.contact.rolling = RollingModel::Epsd;  // rolling history through the file too
  for (auto& m : sc.materials) m.rolling_friction = 0.1;
  const auto path = std::filesystem::temp_directory_path() / "talus_gpu_checkpoint.bin";
  auto a = build_dem<3>(sc, {});
  a->stepper = test::backend_stepper<3>(a->system);
  a->stepper->prime();
  a->stepper->advance(3000);
  a->stepper->sync_lists();
  save_checkpoint(a->system, path);
  a->stepper->advance(1000);
  const double ke = kinetic_energy(a->system.particles);
  ASSERT_GT(a->system.pair_contacts, 500);  // the column has closed its gaps

  for (const bool on_backend : {true, false}) {
    auto b = build_dem<3>(sc, {1, false, false});
    load_checkpoint(b->system, path);
    if (on_backend) b->stepper = test::backend_stepper<3>(b->system);
    b->stepper->resume();
    b->stepper->advance(1000);
    EXPECT_EQ(b->system.step, a->system.step);
    EXPECT_EQ(b->system.particles.size(), a->system.particles.size());
    EXPECT_NEAR(kinetic_energy(b->system.particles), ke, 1e-9 * ke)
        << (on_backend ? "backend" : "CPU stepper");
    EXPECT_NEAR(b->system.walls[0].impulse.z(), a->system.walls[0].impulse.z(),
                1e-9 * std::abs(a->system.walls[0].impulse.z()));
  }
  std::filesystem::remove(path);
}

// The back wall pushes the column at 5 cm/s: particle-wall kinematics with the
// wall's velocity, and rebuilds when the wall has moved half the skin.
TEST(GpuBackendState, MovingWallAgreesWithTheCpuStepper) {
  DemScenario sc = cases::peer_column(10, 5, 20);
  ASSERT_EQ(sc.walls[1].name, "back");
  sc.walls[1].motion.velocity = Vec3(0.05, 0, 0);
  auto cpu = build_dem<3>(sc, {});
  auto gpu = build_dem<3>(sc, {});
  gpu->stepper = test::backend_stepper<3>(gpu->system);
  for (auto* run : {cpu.get(), gpu.get()}) {
    run->stepper->prime();
    run->stepper->advance(4000);  // 20 ms: the wall moves 1 mm, five skins
  }
  const double ke = kinetic_energy(cpu->system.particles);
  EXPECT_NEAR(kinetic_energy(gpu->system.particles), ke, 1e-9 * ke);
  const double push = cpu->system.walls[1].impulse.x();
  EXPECT_LT(push, 0.0);  // the grains push back on it
  EXPECT_NEAR(gpu->system.walls[1].impulse.x(), push, 1e-9 * std::abs(push));
  EXPECT_EQ(gpu->system.neighbours.builds, cpu->system.neighbours.builds);
}

}  // namespace
