// A run that goes unstable stops with a diagnosis instead of writing garbage.
#include <gtest/gtest.h>

#include "peer_case.hpp"
#include "support/dem_loop.hpp"
#include "talus/core/error.hpp"
#include "talus/dem/builder.hpp"

using namespace talus;
using namespace talus::dem;

// The builder refuses such a step; forcing one past it (8x the critical step
// of the peer column) makes the contacts blow up, and the driver must notice.
TEST(Health, UnstableTimeStepStopsTheRunWithADiagnosis) {
  auto run = build_dem<3>(cases::peer_column(6, 4, 12), {});
  run->system.dt = 8.0 * run->system.critical_time_step;
  run::DemControl c;
  c.duration = 4000 * run->system.dt;
  try {
    test::run_dem<3>(*run, c);
    FAIL() << "the unstable run was not stopped";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("time step"), std::string::npos) << what;
    std::printf("[health] %s\n", what.c_str());
  }
}

// The same with the floor vibrating gently (2 pi f A = 6 mm/s): a moving wall
// does not switch the energy check off; its work joins the budget, and the
// blow-up exceeds that by far. The particles fly out of the domain within the
// first check interval: the energy they carried out still counts.
TEST(Health, UnstableTimeStepStopsTheRunWhileAWallMoves) {
  auto sc = cases::peer_column(6, 4, 12);
  sc.walls[0].motion.amplitude = 1e-4;
  sc.walls[0].motion.frequency = 10;
  sc.walls[0].motion.direction = Vec3::UnitZ();
  auto run = build_dem<3>(sc, {});
  run->system.dt = 8.0 * run->system.critical_time_step;
  run::DemControl c;
  c.duration = 4000 * run->system.dt;
  try {
    test::run_dem<3>(*run, c);
    FAIL() << "the unstable run was not stopped";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("time step"), std::string::npos) << what;
    // The energy check (not a NaN) stopped it, with the wall's work counted.
    EXPECT_NE(what.find("the work the moving walls have done"), std::string::npos) << what;
    std::printf("[health] %s\n", what.c_str());
  }
}
