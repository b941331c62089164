// The GPU backend against the CPU stepper on the peer column (the peer
// benchmark's collapse, ../shared/peers/README.md §1), and its refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem/peer_case.hpp"
#include "dem_gpu/test_backend.hpp"
#include "talus/core/error.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem/gpu_support.hpp"

using namespace talus;
using namespace talus::dem;

namespace {

// 4 000 steps (20 ms) of the 8 000-grain column on both steppers: the lattice
// gaps close after ~9 ms, so the last half has ~12 000 contacts. The GPU
// backend sums each particle's contact forces in another order than the CPU
// stepper (its own pair list; on the GPU, atomics in no fixed order): a
// round-off difference, which test_peer_column's thread comparison bounds by
// 1e-9 relative in kinetic energy (one and two CPU threads, 600 steps; at
// 4 000 steps they agree to 11 digits: bench_gpu_peer 20 10 40 0 4000 cpu 1|2).
TEST(GpuBackend, PeerColumnAgreesWithTheCpuStepper) {
  const DemScenario sc = cases::peer_column(20, 10, 40);
  auto cpu = build_dem<3>(sc, {});
  auto gpu = build_dem<3>(sc, {});
  gpu->stepper = test::backend_stepper<3>(gpu->system);
  for (auto* run : {cpu.get(), gpu.get()}) {
    run->stepper->prime();
    for (int k = 0; k < 8; ++k) run->stepper->advance(500);
  }
  const auto& a = cpu->system.particles;
  const auto& b = gpu->system.particles;
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(cpu->system.step, gpu->system.step);
  EXPECT_DOUBLE_EQ(cpu->system.time, gpu->system.time);
  const double ke_cpu = kinetic_energy(a), ke_gpu = kinetic_energy(b);
  std::printf("[gpu] peer column 4000 steps: KE cpu %.15e gpu %.15e, contacts %lld / %lld\n",
              ke_cpu, ke_gpu, static_cast<long long>(cpu->system.pair_contacts),
              static_cast<long long>(gpu->system.pair_contacts));
  EXPECT_NEAR(ke_gpu, ke_cpu, 1e-9 * ke_cpu);
  EXPECT_NEAR(front_x(b), front_x(a), 1e-9 * front_x(a));
  EXPECT_GT(cpu->system.pair_contacts, 10000);
  EXPECT_EQ(gpu->system.pair_contacts, cpu->system.pair_contacts);
  EXPECT_EQ(gpu->system.wall_contacts, cpu->system.wall_contacts);
  // The floor carries the column's weight on both.
  EXPECT_NEAR(gpu->system.walls[0].force.z(), cpu->system.walls[0].force.z(),
              1e-6 * std::abs(cpu->system.walls[0].force.z()));
}

// Particles that leave the domain are removed at a rebuild, as on the CPU.
TEST(GpuBackend, ParticlesLeavingTheDomainAreRemoved) {
  DemScenario sc = cases::peer_column(4, 4, 4);
  sc.walls.erase(sc.walls.begin());  // no floor: the grains fall out at z = 0
  sc.run.domain_min = Vec3(0, 0, 0);
  auto run = build_dem<3>(sc, {});
  run->stepper = test::backend_stepper<3>(run->system);
  run->stepper->prime();
  run->stepper->advance(20000);  // 0.1 s: every grain has fallen over 5 cm
  EXPECT_EQ(run->system.particles.size(), 0u);
  EXPECT_EQ(run->system.removed, 64);
}

TEST(GpuBackend, ScenariosWithMissingFeaturesAreRefusedWithTheList) {
  DemScenario sc = cases::peer_column(2, 2, 2);
  EXPECT_TRUE(gpu_missing_features(sc).empty());
  sc.contact.model = "viscoelastic_hertz";
  sc.contact.rolling = RollingModel::Kuen;
  sc.walls[0].kind = WallKind::Mesh;
  sc.walls[1].motion.servo_pressure = 1e3;
  const auto missing = gpu_missing_features(sc);
  ASSERT_EQ(missing.size(), 4u);
  const std::string msg = gpu_refusal(sc, missing);
  EXPECT_NE(msg.find("viscoelastic_hertz"), std::string::npos) << msg;
  EXPECT_NE(msg.find("kuen"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'floor'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("servo"), std::string::npos) << msg;
  // The stepper itself refuses what slipped past (a system built otherwise).
  DemScenario ok = cases::peer_column(2, 2, 2);
  auto run = build_dem<3>(ok, {});
  run->system.contact.model = "viscoelastic_hertz";
  EXPECT_THROW(test::backend_stepper<3>(run->system), InputError);
}

}  // namespace
