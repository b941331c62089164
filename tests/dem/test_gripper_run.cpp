// The reduced granular gripper (scenarios/dem/granular_gripper_small.toml, Götz
// 2024 §4.2 at half size with a fast protocol) run up to 30 ms into the
// pull: about a minute on one thread. It checks what holds robustly there
// (measured values of the bundled case in the comments): the phases come
// in order, the object feels nothing until it reaches the membrane, the
// pre-tension lifts the filled membrane above its rest bottom, the push
// meets a growing resistance, and once the vacuum is on the lid carries
// the vacuum's whole load p_vac pi R^2 (the membrane's pressure force
// integrates to that over any shape spanning the rim).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "talus/analysis/gripper.hpp"
#include "talus/dem/builder.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::dem {
namespace {

using analysis::GripperPhase;

TEST(GripperRun, ReducedGripThroughAllPhases) {
  const auto sc = io::parse_dem_scenario(io::load_scenario_file(
      std::string(TALUS_SOURCE_DIR) + "/scenarios/dem/granular_gripper_small.toml", {}));
  ASSERT_TRUE(sc.gripper.has_value());
  const auto& g = *sc.gripper;
  auto run = build_dem<3>(sc, {});
  auto& s = run->system;
  ASSERT_EQ(s.objects.size(), 1u);
  const auto& o = s.objects[0];
  const auto& mb = s.membranes[0];
  const double r_rim = sc.membranes[0].radius;
  run->stepper->prime();

  int last_phase = 0;
  double lowest_at_push = 0.0, push_force = 0.0, lid_at_hold = 0.0;
  bool touched = false;
  const int every = 100;  // steps between samples
  while (s.time < g.pull_start + 0.03) {
    run->stepper->advance(every);
    const auto phase = static_cast<int>(analysis::gripper_phase(g, s.time));
    EXPECT_GE(phase, last_phase) << "t = " << s.time;
    last_phase = phase;
    double lowest = std::numeric_limits<double>::infinity();
    for (const Vec3& x : mb.body.x) lowest = std::min(lowest, x.z());
    // Before the object's top reaches the membrane there is no force at all.
    if (phase <= static_cast<int>(GripperPhase::Push)) {
      if (o.x.z() + o.radius < lowest - 1e-4) {
        EXPECT_EQ(o.contacts, 0) << "t = " << s.time;
        EXPECT_EQ(o.force, Vec3::Zero()) << "t = " << s.time;
        ASSERT_FALSE(touched) << "the object left the membrane during the push";
      } else if (phase == static_cast<int>(GripperPhase::Push)) {
        touched = true;
      }
    }
    if (phase < static_cast<int>(GripperPhase::Push)) lowest_at_push = lowest;
    if (phase == static_cast<int>(GripperPhase::Push))
      push_force = std::max(push_force, -o.force.z());
    if (phase == static_cast<int>(GripperPhase::Hold)) lid_at_hold = s.walls[0].force.z();
  }
  EXPECT_EQ(last_phase, static_cast<int>(GripperPhase::Pull));
  EXPECT_TRUE(touched);
  // Pre-tension: measured lowest point -18.79 mm at the push, above the
  // rest bottom -20 mm (grains and all).
  EXPECT_GT(lowest_at_push, -r_rim) << lowest_at_push;
  // The membrane resists the push: measured 12.53 N at most.
  EXPECT_GT(push_force, 5.0);
  // Measured 112.6 N at the end of the hold against p_vac pi R^2 = 113.1 N
  // (the object, the grains' weight and the rim's pins share the rest).
  const double load = g.vacuum * M_PI * r_rim * r_rim;
  EXPECT_NEAR(lid_at_hold, load, 0.05 * load);
  std::printf("lowest at push %.2f mm, push force %.2f N, lid %.1f N of %.1f N\n",
              1e3 * lowest_at_push, push_force, lid_at_hold, load);
}

}  // namespace
}  // namespace talus::dem
