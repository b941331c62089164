// The triaxial test's keys: [walls.motion.servo], [[particles]] cylinder,
// [[membranes]] bottom_ring_wall / top_ring_wall and [triaxial]. A valid
// scenario parses and survives the resolved-scenario round trip; bad keys give
// an InputError naming file, line (the one marked "# <-") and key.
#include <gtest/gtest.h>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

const std::string kTriaxial = R"(method = "dem"
[run]
dimension = 3
duration = 0.1
gravity = [0, 0, 0]
[contact]
model = "viscoelastic_hertz"
[[materials]]
name = "glass"
density = 2000
youngs_modulus = 4.6e10
friction = 0.25
dissipation = 7e-9
[[materials]]
name = "rubber"
youngs_modulus = 1.25e6
friction = 1.2
[[walls]]
name = "bottom"
type = "plane"
material = "glass"
point = [0, 0, 0]
normal = [0, 0, 1]
[walls.motion]
velocity = [0, 0, 0.025]
start = 0.03
servo = { pressure = 1e5, area = 2e-3, speed = 0.05, stop = 0.03 }
[[walls]]
name = "top"
type = "plane"
material = "glass"
point = [0, 0, 0.1]
normal = [0, 0, -1]
[walls.motion]
velocity = [0, 0, -0.025]
start = 0.04
servo = { pressure = 1e5, area = 2e-3, speed = 0.05, stop = 0.03 }
[[particles]]
type = "grow"
material = "glass"
cylinder = { center = [0, 0, 0], radius = 0.0249, height = 0.1 }
radius_min = 0.0023
radius_max = 0.0027
packing_fraction = 0.58
count = 1716
[[membranes]]
name = "sleeve"
mesh = "cylinder"
radius = 0.025
height = 0.1
spacing = 0.004
youngs_modulus = 1.25e6
thickness = 3e-4
density = 1000
pressure = -1e5
fixed = "both_rings"
bottom_ring_wall = "bottom"
top_ring_wall = "top"
material = "rubber"
[triaxial]
bottom_plate = "bottom"
top_plate = "top"
membrane = "sleeve"
)";

using cases::BadCase;
using cases::edit;

void expect_same(const dem::DemScenario& s) {
  ASSERT_EQ(s.walls.size(), 2u);
  const auto& m = s.walls[1].motion;
  EXPECT_DOUBLE_EQ(m.servo_pressure, 1e5);
  EXPECT_DOUBLE_EQ(m.servo_area, 2e-3);
  EXPECT_DOUBLE_EQ(m.servo_speed, 0.05);
  EXPECT_DOUBLE_EQ(m.servo_stop, 0.03);
  EXPECT_DOUBLE_EQ(m.move_start, 0.04);
  ASSERT_EQ(s.sources.size(), 1u);
  const auto& src = s.sources[0];
  EXPECT_DOUBLE_EQ(src.cylinder_radius, 0.0249);
  // The cylinder is kept as its bounding box: base centre (0, 0, 0), height 0.1.
  EXPECT_DOUBLE_EQ(src.box_min.x(), -0.0249);
  EXPECT_DOUBLE_EQ(src.box_max.y(), 0.0249);
  EXPECT_DOUBLE_EQ(src.box_min.z(), 0.0);
  EXPECT_DOUBLE_EQ(src.box_max.z(), 0.1);
  ASSERT_EQ(s.membranes.size(), 1u);
  EXPECT_EQ(s.membranes[0].bottom_ring_wall, "bottom");
  EXPECT_EQ(s.membranes[0].top_ring_wall, "top");
  ASSERT_TRUE(s.triaxial.has_value());
  EXPECT_EQ(s.triaxial->bottom_plate, "bottom");
  EXPECT_EQ(s.triaxial->top_plate, "top");
  EXPECT_EQ(s.triaxial->membrane, "sleeve");
}

TEST(TriaxialScenario, ParsesEveryKey) {
  expect_same(parse_dem_scenario(load_scenario_text(kTriaxial, "tri.toml")));
}

TEST(TriaxialScenario, ResolvedScenarioKeepsTheKeys) {
  const auto a = parse_dem_scenario(load_scenario_text(kTriaxial, "a.toml"));
  expect_same(parse_dem_scenario(load_scenario_text(scenario_to_toml(a), "b.toml")));
}

// Servo walls and membranes are checkpointed since checkpoint version 4
// (dem/checkpoint.cpp); tests/app/test_resume_membrane.sh resumes such a run.
TEST(TriaxialScenario, CheckpointsAreAccepted) {
  const auto s = parse_dem_scenario(
      load_scenario_text(kTriaxial + "[output]\ncheckpoint_interval = 0.01\n", "tri.toml"));
  EXPECT_DOUBLE_EQ(s.output.checkpoint_interval, 0.01);
}

TEST(TriaxialScenario, BundledCaseParses) {
  const auto s = parse_dem_scenario(
      load_scenario_file(std::string(TALUS_SOURCE_DIR) + "/scenarios/dem/triaxial_case1.toml", {}));
  ASSERT_TRUE(s.triaxial.has_value());
  EXPECT_DOUBLE_EQ(s.membranes[0].pressure, -1e5);  // Götz: p_c = 100 kPa
}

class BadTriaxial : public testing::TestWithParam<BadCase> {};

TEST_P(BadTriaxial, InputErrorNamesFileLineAndKey) {
  cases::expect_input_error(GetParam(), "triaxial_");
}

INSTANTIATE_TEST_SUITE_P(
    Scenario, BadTriaxial,
    testing::Values(
        BadCase{
            "servo_negative_pressure",
            edit(kTriaxial,
                 "servo = { pressure = 1e5, area = 2e-3, speed = 0.05, stop = 0.03 }\n[[walls]]",
                 "servo = { pressure = -1e5, area = 2e-3, speed = 0.05, stop = 0.03 } # "
                 "<-\n[[walls]]"),
            "pressure", "expected a positive number"},
        BadCase{
            "servo_missing_area",
            edit(
                kTriaxial,
                "servo = { pressure = 1e5, area = 2e-3, speed = 0.05, stop = 0.03 }\n[[particles]]",
                "servo = { pressure = 1e5, speed = 0.05, stop = 0.03 } # <-\n[[particles]]"),
            "area", "missing"},
        BadCase{
            "servo_unknown_key",
            edit(
                kTriaxial,
                "servo = { pressure = 1e5, area = 2e-3, speed = 0.05, stop = 0.03 }\n[[particles]]",
                "servo = { pressure = 1e5, area = 2e-3, speed = 0.05, stop = 0.03, gain = 1 } # "
                "<-\n[[particles]]"),
            "gain", "unknown"},
        BadCase{"velocity_before_servo_stop", edit(kTriaxial, "start = 0.04", "start = 0.02 # <-"),
                "start", "at or after servo.stop"},
        BadCase{"cylinder_and_box",
                edit(edit(kTriaxial, "count = 1716",
                          "count = 1716\nbox = { min = [0, 0, 0], max = [1, 1, 1] }"),
                     "height = 0.1 }", "height = 0.1 } # <-"),
                "cylinder", "exactly one of"},
        BadCase{"cylinder_without_height",
                edit(kTriaxial, "cylinder = { center = [0, 0, 0], radius = 0.0249, height = 0.1 }",
                     "cylinder = { center = [0, 0, 0], radius = 0.0249 } # <-"),
                "height", "missing"},
        BadCase{"ring_wall_unknown",
                edit(kTriaxial, "top_ring_wall = \"top\"", "top_ring_wall = \"lid\" # <-"),
                "top_ring_wall", "no wall named 'lid'"},
        BadCase{"ring_wall_not_pinned",
                edit(edit(kTriaxial, "fixed = \"both_rings\"", "fixed = \"bottom_ring\""),
                     "top_ring_wall = \"top\"", "top_ring_wall = \"top\" # <-"),
                "top_ring_wall", "needs fixed = \"top_ring\""},
        BadCase{"plate_unknown", edit(kTriaxial, "top_plate = \"top\"", "top_plate = \"lid\" # <-"),
                "top_plate", "no wall named 'lid'"},
        BadCase{"membrane_unknown",
                edit(kTriaxial, "membrane = \"sleeve\"", "membrane = \"jacket\" # <-"), "membrane",
                "no membrane named 'jacket'"},
        BadCase{"membrane_not_confining",
                edit(edit(kTriaxial, "pressure = -1e5", "pressure = 1e5"), "membrane = \"sleeve\"",
                     "membrane = \"sleeve\" # <-"),
                "membrane", "confining pressure < 0"}),
    [](const testing::TestParamInfo<BadCase>& info) { return info.param.name; });

}  // namespace
}  // namespace talus::io
