// [gripper] (io/scenario_gripper.cpp): the bundled reduced gripper parses
// with its phase times derived and survives the resolved-scenario round
// trip; bad values give an InputError naming file, line ("# <-") and key.
#include <gtest/gtest.h>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

using cases::BadCase;
using cases::bundled;
using cases::edit;

const std::string kSmall = bundled("dem/granular_gripper_small.toml");

// The small case: the object's top starts at -22 mm and ends the push 14 mm
// above the rest bottom (-20 mm), 16 mm at 0.1 m/s from 0.17 s.
void expect_times(const dem::DemScenario& s) {
  ASSERT_TRUE(s.gripper.has_value());
  const auto& g = *s.gripper;
  EXPECT_EQ(g.membrane, "gripper");
  EXPECT_EQ(g.object_material, "object");
  EXPECT_DOUBLE_EQ(g.hold_stretch, 1.25);
  EXPECT_DOUBLE_EQ(g.pretension, 0.125);
  EXPECT_NEAR(g.push_end, 0.17 + 0.016 / 0.1, 1e-12);
  EXPECT_NEAR(g.vacuum_start, g.push_end + 0.03, 1e-12);
  EXPECT_NEAR(g.vacuum_end, g.vacuum_start + 3 * 0.02, 1e-12);
  EXPECT_NEAR(g.pull_start, g.vacuum_end + 0.02, 1e-12);
  EXPECT_EQ(g.vacuum_steps, 3);
  EXPECT_DOUBLE_EQ(g.vacuum, 9e4);
}

TEST(GripperScenario, ParsesAndDerivesThePhaseTimes) {
  expect_times(parse_dem_scenario(load_scenario_text(kSmall, "g.toml")));
}

TEST(GripperScenario, ResolvedScenarioKeepsTheKeys) {
  const auto a = parse_dem_scenario(load_scenario_text(kSmall, "a.toml"));
  expect_times(parse_dem_scenario(load_scenario_text(scenario_to_toml(a), "b.toml")));
}

TEST(GripperScenario, FullSizeCaseParses) {
  const auto s = parse_dem_scenario(load_scenario_file(
      std::string(TALUS_SOURCE_DIR) + "/scenarios/dem/granular_gripper.toml", {}));
  ASSERT_TRUE(s.gripper.has_value());
  // Götz 2024 §4.2: R = 40 mm, 10 mm/s to 28 mm depth, 90 kPa, 2.5 mm/s.
  EXPECT_DOUBLE_EQ(s.membranes[0].radius, 0.04);
  EXPECT_EQ(s.membranes[0].frequency, 16);
  EXPECT_DOUBLE_EQ(s.gripper->push_speed, 0.01);
  EXPECT_DOUBLE_EQ(s.gripper->depth, 0.028);
  EXPECT_DOUBLE_EQ(s.gripper->vacuum, 9e4);
  EXPECT_DOUBLE_EQ(s.gripper->pull_speed, 0.0025);
}

class BadGripper : public testing::TestWithParam<BadCase> {};

TEST_P(BadGripper, InputErrorNamesFileLineAndKey) {
  cases::expect_input_error(GetParam(), "gripper_");
}

INSTANTIATE_TEST_SUITE_P(
    Scenario, BadGripper,
    testing::Values(
        BadCase{"unknown_key", edit(kSmall, "hold = 0.02", "hold = 0.02\nholdd = 1 # <-"), "holdd",
                ""},
        BadCase{"rim_free",
                edit(edit(kSmall, "fixed = \"edge\"", "fixed = \"none\""), "membrane = \"gripper\"",
                     "membrane = \"gripper\" # <-"),
                "membrane", "with fixed = \"edge\""},
        BadCase{"own_pressure",
                edit(edit(kSmall, "fixed = \"edge\"", "fixed = \"edge\"\npressure = -1e3"),
                     "membrane = \"gripper\"", "membrane = \"gripper\" # <-"),
                "membrane", "no pressure"},
        BadCase{"membrane_missing",
                edit(kSmall, "membrane = \"gripper\"", "membrane = \"bag\" # <-"), "membrane",
                "no membrane named 'bag'"},
        BadCase{"object_material_missing",
                edit(kSmall, "object_material = \"object\"", "object_material = \"steel\" # <-"),
                "object_material", ""},
        BadCase{"object_off_axis",
                edit(kSmall, "object_center = [0, 0, -0.027]",
                     "object_center = [0.001, 0, -0.027] # <-"),
                "object_center", "on the membrane's axis"},
        BadCase{
            "object_inside",
            edit(kSmall, "object_center = [0, 0, -0.027]", "object_center = [0, 0, -0.02] # <-"),
            "object_center", "below the membrane's lowest rest point"},
        BadCase{"too_deep", edit(kSmall, "depth = 0.014", "depth = 0.02 # <-"), "depth",
                "below the membrane's rim"},
        BadCase{"push_before_release", edit(kSmall, "push_start = 0.17", "push_start = 0.1 # <-"),
                "push_start", "no earlier than 'release'"},
        BadCase{"no_time_to_pull",
                edit(edit(kSmall, "duration = 0.6", "duration = 0.4"), "pull_speed = 0.05",
                     "pull_speed = 0.05 # <-"),
                "pull_speed", "no time left to pull"},
        BadCase{"zero_steps", edit(kSmall, "vacuum_steps = 3", "vacuum_steps = 0 # <-"),
                "vacuum_steps", "an integer in [1, 100]"},
        BadCase{"pretension_negative", edit(kSmall, "pretension = 0.125", "pretension = -0.1 # <-"),
                "pretension", ""},
        BadCase{"checkpoints",
                edit(edit(kSmall, "snapshot_interval = 0.05",
                          "snapshot_interval = 0.05\ncheckpoint_interval = 0.1"),
                     "membrane = \"gripper\"", "membrane = \"gripper\" # <-"),
                "membrane", "checkpoints of [gripper] runs are not supported"}),
    [](const testing::TestParamInfo<BadCase>& info) { return info.param.name; });

}  // namespace
}  // namespace talus::io
