// [beam] (io/scenario_beam.cpp): the bundled beams parse with the step count
// derived and survive the resolved-scenario round trip; bad values give an
// InputError naming file, line ("# <-") and key.
#include <gtest/gtest.h>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

using cases::BadCase;
using cases::bundled;
using cases::edit;

const std::string kSmall = bundled("dem/granular_beam_3pt_small.toml");

void expect_small(const dem::DemScenario& s) {
  ASSERT_TRUE(s.beam.has_value());
  const auto& b = *s.beam;
  EXPECT_EQ(b.membrane, "beam");
  EXPECT_EQ(b.load_steps, 4);  // 2 N in 0.5 N steps
  EXPECT_DOUBLE_EQ(b.load_ramp, 0.003);
  EXPECT_DOUBLE_EQ(b.beam_poisson_ratio, 0.3);
  EXPECT_NEAR(b.end(), 0.03 + 9 * 0.01, 1e-12);
}

TEST(BeamScenario, ParsesAndDerivesTheSteps) {
  expect_small(parse_dem_scenario(load_scenario_text(kSmall, "b.toml")));
}

TEST(BeamScenario, ResolvedScenarioKeepsTheKeys) {
  const auto a = parse_dem_scenario(load_scenario_text(kSmall, "a.toml"));
  expect_small(parse_dem_scenario(load_scenario_text(scenario_to_toml(a), "b.toml")));
}

TEST(BeamScenario, FullSizeCaseParses) {
  const auto s = parse_dem_scenario(load_scenario_file(
      std::string(TALUS_SOURCE_DIR) + "/scenarios/dem/granular_beam_3pt.toml", {}));
  ASSERT_TRUE(s.beam.has_value());
  // Götz 2024 §5.2: F = 0 -> 10 N -> 0 in 1 N steps on a 40 x 8 x 8 cm beam.
  EXPECT_EQ(s.beam->load_steps, 10);
  EXPECT_DOUBLE_EQ(s.beam->max_load, 10.0);
  EXPECT_DOUBLE_EQ(s.membranes[0].size_x, 0.4);
  EXPECT_LE(s.beam->end(), s.run.duration);
}

TEST(BeamScenario, LoadScheduleStepsUpAndDown) {
  const auto s = parse_dem_scenario(load_scenario_text(kSmall, "b.toml"));
  const auto& b = *s.beam;
  EXPECT_EQ(b.step_at(0.0299), -1);
  EXPECT_EQ(b.step_at(0.0301), 0);
  EXPECT_EQ(b.load_at(0.035), 0.0);
  // Step 1 from 0.04 s: the 0.5 N rise is ramped over 3 ms.
  EXPECT_NEAR(b.load_at(0.0415), 0.25, 1e-12);
  EXPECT_NEAR(b.load_at(0.045), 0.5, 1e-12);
  EXPECT_NEAR(b.load_at(0.075), 2.0, 1e-12);    // step 4, the top
  EXPECT_NEAR(b.load_at(0.0815), 1.75, 1e-12);  // step 5, halfway down its ramp
  EXPECT_NEAR(b.load_at(0.115), 0.0, 1e-12);    // step 8, back to 0
  EXPECT_EQ(b.step_at(0.125), 9);
  EXPECT_EQ(b.load_at(0.125), 0.0);
}

const std::string kFour = bundled("dem/granular_beam_4pt_small.toml");

TEST(BeamScenario, FourPointParsesAndDerivesTheRodsTravel) {
  for (const auto& text : {kFour, std::string()}) {
    const auto s = parse_dem_scenario(load_scenario_text(
        text.empty() ? scenario_to_toml(parse_dem_scenario(load_scenario_text(kFour, "a.toml")))
                     : text,
        "b.toml"));
    ASSERT_TRUE(s.beam.has_value());
    const auto& b = *s.beam;
    EXPECT_EQ(b.test, dem::BeamTest::FourPoint);
    ASSERT_TRUE(b.bending_friction.has_value());
    EXPECT_DOUBLE_EQ(*b.bending_friction, 0.3);
    // Source eq. 44 for ε = 0.08 on the 15 cm long, 3 cm high beam.
    EXPECT_NEAR(b.rod_travel, 0.08 * 23 * 0.15 * 0.15 / (108 * 0.03), 1e-15);
    EXPECT_DOUBLE_EQ(b.yield_smoothing, 0.002);             // max_strain / 40
    EXPECT_DOUBLE_EQ(s.sources.at(0).edge_radius, 0.0065);  // grains grown in the rounded box
    // 10 mm/s after a 20 ms ramp: half the ramp is lost.
    EXPECT_NEAR(b.end(), 0.06 + b.rod_travel / 0.01 + 0.01, 1e-12);
    EXPECT_LE(b.end(), s.run.duration);
  }
}

TEST(BeamScenario, RodsRampUpThenMoveSteadilyThenHold) {
  const auto s = parse_dem_scenario(load_scenario_text(kFour, "b.toml"));
  const auto& b = *s.beam;
  EXPECT_EQ(b.rod_travel_at(0.05), 0.0);
  EXPECT_NEAR(b.rod_travel_at(0.07), 0.5 * 0.01 * 0.01 * 0.01 / 0.02, 1e-15);  // in the ramp
  EXPECT_NEAR(b.rod_travel_at(0.12), 0.01 * (0.06 - 0.01), 1e-15);
  EXPECT_DOUBLE_EQ(b.rod_travel_at(b.end() + 0.1), b.rod_travel);
}

class BadBeam : public testing::TestWithParam<BadCase> {};

TEST_P(BadBeam, InputErrorNamesFileLineAndKey) { cases::expect_input_error(GetParam(), "beam_"); }

INSTANTIATE_TEST_SUITE_P(
    Scenario, BadBeam,
    testing::Values(
        BadCase{"unknown_key",
                edit(kSmall, "load_ramp = 0.003", "load_ramp = 0.003\nramp = 1 # <-"), "ramp", ""},
        BadCase{"membrane_missing", edit(kSmall, "membrane = \"beam\"", "membrane = \"bag\" # <-"),
                "membrane", "no membrane named 'bag'"},
        BadCase{"membrane_along_z",
                edit(edit(kSmall, "size = [0.06, 0.03, 0.03]", "size = [0.03, 0.03, 0.06]"),
                     "membrane = \"beam\"", "membrane = \"beam\" # <-"),
                "membrane", "longest along x"},
        BadCase{"membrane_without_vacuum",
                edit(edit(kSmall, "pressure = -9e4", "pressure = 9e4"), "membrane = \"beam\"",
                     "membrane = \"beam\" # <-"),
                "membrane", "a vacuum"},
        BadCase{"mould_before_vacuum", edit(kSmall, "mould_end = 0.02", "mould_end = 0.005 # <-"),
                "mould_end", "end of the membrane's pressure_ramp"},
        BadCase{"bending_in_mould",
                edit(kSmall, "bending_start = 0.03", "bending_start = 0.01 # <-"), "bending_start",
                "no earlier than 'mould_end'"},
        BadCase{"support_on_rounded_edge",
                edit(kSmall, "support_length = 0.012", "support_length = 0.005 # <-"),
                "support_length", "edge radius"},
        BadCase{"load_beyond_top", edit(kSmall, "load_length = 0.012", "load_length = 0.05 # <-"),
                "load_length", "within the flat top"},
        BadCase{"steps_not_whole", edit(kSmall, "load_step = 0.5", "load_step = 0.3 # <-"),
                "load_step", "a whole fraction of max_load"},
        BadCase{"ramp_longer_than_step", edit(kSmall, "load_ramp = 0.003", "load_ramp = 0.02 # <-"),
                "load_ramp", ""},
        BadCase{"poisson_out_of_range",
                edit(kSmall, "beam_poisson_ratio = 0.3", "beam_poisson_ratio = 0.7 # <-"),
                "beam_poisson_ratio", ""},
        BadCase{"no_time_for_steps",
                edit(edit(kSmall, "duration = 0.12", "duration = 0.1"), "step_time = 0.01",
                     "step_time = 0.01 # <-"),
                "step_time", "no time for the load steps"},
        BadCase{"checkpoints",
                edit(edit(kSmall, "snapshot_interval = 0.01",
                          "snapshot_interval = 0.01\ncheckpoint_interval = 0.05"),
                     "membrane = \"beam\"", "membrane = \"beam\" # <-"),
                "membrane", "checkpoints of [beam] runs are not supported"},
        BadCase{"edge_radius_beyond_half_side",
                edit(kFour, "edge_radius = 0.0065", "edge_radius = 0.015 # <-"), "edge_radius",
                "at most half the box's smallest side"},
        BadCase{"edge_radius_negative",
                edit(kFour, "edge_radius = 0.0065", "edge_radius = -0.001 # <-"), "edge_radius",
                "a positive number"},
        BadCase{"unknown_test", edit(kFour, "test = \"four_point\"", "test = \"five_point\" # <-"),
                "test", "four_point"},
        BadCase{"load_steps_in_four_point",
                edit(kFour, "max_strain = 0.08", "max_strain = 0.08\nmax_load = 2.0 # <-"),
                "max_load", "not used by test = \"four_point\""},
        BadCase{"rods_in_three_point",
                edit(kSmall, "load_ramp = 0.003", "load_ramp = 0.003\nrod_speed = 0.01 # <-"),
                "rod_speed", "not used by test = \"three_point\""},
        BadCase{"strain_too_large", edit(kFour, "max_strain = 0.08", "max_strain = 0.8 # <-"),
                "max_strain", ""},
        BadCase{"ramp_past_travel", edit(kFour, "rod_ramp = 0.02", "rod_ramp = 5.0 # <-"),
                "rod_ramp", "ends before the rods' travel"},
        BadCase{"negative_bending_friction",
                edit(kFour, "bending_friction = 0.3", "bending_friction = -0.1 # <-"),
                "bending_friction", ""},
        BadCase{"no_time_for_rods",
                edit(edit(kFour, "duration = 1.36", "duration = 0.5"), "rod_speed = 0.01",
                     "rod_speed = 0.01 # <-"),
                "rod_speed", "no time for the rods' travel"},
        BadCase{"damping_ends_before_it_starts",
                edit(kFour, "damping_end = 0.06", "damping_end = 0.02 # <-"), "damping_end",
                "after 'mould_end'"},
        BadCase{"smoothing_too_wide",
                edit(kFour, "max_strain = 0.08", "max_strain = 0.08\nyield_smoothing = 0.05 # <-"),
                "yield_smoothing", ""}),
    [](const testing::TestParamInfo<BadCase>& info) { return info.param.name; });

}  // namespace
}  // namespace talus::io
