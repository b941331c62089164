// A run that goes unstable stops with a diagnosis instead of writing garbage.
#include <gtest/gtest.h>

#include "peer_case.hpp"
#include "support/dem_loop.hpp"
#include "talus/core/error.hpp"
#include "talus/dem/builder.hpp"

using namespace talus;
using namespace talus::dem;

namespace {

// Runs the scenario at 8x its critical step (the builder refuses such a step;
// it is forced past it) for 4000 steps; the contacts blow up and the run must
// be stopped. Returns the diagnosis ("" when the run was not stopped).
std::string unstable_run_diagnosis(const DemScenario& sc) {
  auto run = build_dem<3>(sc, {});
  run->system.dt = 8.0 * run->system.critical_time_step;
  run::DemControl c;
  c.duration = 4000 * run->system.dt;
  try {
    test::run_dem<3>(*run, c);
  } catch (const RunError& e) {
    std::printf("[health] %s\n", e.what());
    return e.what();
  }
  return "";
}

}  // namespace

// The peer column at 8x its critical step.
TEST(Health, UnstableTimeStepStopsTheRunWithADiagnosis) {
  const std::string what = unstable_run_diagnosis(cases::peer_column(6, 4, 12));
  ASSERT_FALSE(what.empty()) << "the unstable run was not stopped";
  EXPECT_NE(what.find("time step"), std::string::npos) << what;
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
  const std::string what = unstable_run_diagnosis(sc);
  ASSERT_FALSE(what.empty()) << "the unstable run was not stopped";
  EXPECT_NE(what.find("time step"), std::string::npos) << what;
  // The energy check (not a NaN) stopped it, with the wall's work counted.
  EXPECT_NE(what.find("the work the moving walls have done"), std::string::npos) << what;
}
