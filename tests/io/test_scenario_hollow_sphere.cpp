// The hollow sphere's keys: [[particles]] shell, [[membranes]] stretch,
// core_radius, pressure_ramp, fixed = "all", and [hollow_sphere]. A valid
// scenario parses and survives the resolved-scenario round trip; bad values
// give an InputError naming file, line (the one marked "# <-") and key.
#include <gtest/gtest.h>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

const std::string kHollow = R"(method = "dem"
[run]
dimension = 3
duration = 0.03
gravity = [0, 0, 0]
[contact]
model = "viscoelastic_hertz"
[[materials]]
name = "grain"
density = 2000
youngs_modulus = 1e8
poisson_ratio = 0.254
friction = 0.25
[[materials]]
name = "rubber"
youngs_modulus = 1.25e6
friction = 1.2
[[particles]]
type = "grow"
material = "grain"
shell = { center = [0, 0, 0], inner_radius = 0.0102, outer_radius = 0.0247 }
radius_min = 0.0019
radius_max = 0.0021
packing_fraction = 0.27
count = 480
[[membranes]]
name = "object"
mesh = "geodesic_sphere"
radius = 0.01
frequency = 4
youngs_modulus = 1.25e6
thickness = 3e-4
density = 2000
core_radius = 0.01
pressure = 9e4
pressure_ramp = [0.01, 0.02]
material = "rubber"
[[membranes]]
name = "outer"
mesh = "geodesic_sphere"
radius = 0.02
frequency = 8
stretch = 1.25
youngs_modulus = 1.25e6
thickness = 3e-4
density = 2000
pressure = -9e4
pressure_ramp = [0.01, 0.02]
material = "rubber"
[hollow_sphere]
object = "object"
shell = "outer"
)";

using cases::BadCase;
using cases::edit;

void expect_same(const dem::DemScenario& s) {
  const auto& src = s.sources.at(0);
  EXPECT_DOUBLE_EQ(src.shell_inner_radius, 0.0102);
  EXPECT_DOUBLE_EQ(src.shell_outer_radius, 0.0247);
  EXPECT_DOUBLE_EQ(src.box_min.x(), -0.0247);  // the outer sphere's bounding box
  EXPECT_DOUBLE_EQ(src.box_max.z(), 0.0247);
  ASSERT_EQ(s.membranes.size(), 2u);
  EXPECT_DOUBLE_EQ(s.membranes[0].core_radius, 0.01);
  EXPECT_DOUBLE_EQ(s.membranes[0].pressure_ramp_start, 0.01);
  EXPECT_DOUBLE_EQ(s.membranes[0].pressure_ramp_end, 0.02);
  EXPECT_DOUBLE_EQ(s.membranes[1].stretch, 1.25);
  ASSERT_TRUE(s.hollow_sphere.has_value());
  EXPECT_EQ(s.hollow_sphere->object, "object");
  EXPECT_EQ(s.hollow_sphere->shell, "outer");
  EXPECT_DOUBLE_EQ(s.hollow_sphere->poisson_ratio, 0.254);  // the grains'
}

TEST(HollowSphereScenario, ParsesEveryKey) {
  expect_same(parse_dem_scenario(load_scenario_text(kHollow, "hs.toml")));
}

TEST(HollowSphereScenario, ResolvedScenarioKeepsTheKeys) {
  const auto a = parse_dem_scenario(load_scenario_text(kHollow, "a.toml"));
  expect_same(parse_dem_scenario(load_scenario_text(scenario_to_toml(a), "b.toml")));
}

TEST(HollowSphereScenario, BundledCasesParse) {
  for (const char* name : {"hollow_sphere.toml", "hollow_sphere_half.toml"}) {
    const auto s = parse_dem_scenario(
        load_scenario_file(std::string(TALUS_SOURCE_DIR) + "/scenarios/dem/" + name, {}));
    ASSERT_TRUE(s.hollow_sphere.has_value()) << name;
    EXPECT_DOUBLE_EQ(s.membranes[1].pressure, -9e4) << name;  // Götz: p_vac = 90 kPa
  }
}

class BadHollowSphere : public testing::TestWithParam<BadCase> {};

TEST_P(BadHollowSphere, InputErrorNamesFileLineAndKey) {
  cases::expect_input_error(GetParam(), "hollow_");
}

INSTANTIATE_TEST_SUITE_P(
    Scenario, BadHollowSphere,
    testing::Values(BadCase{"shell_inverted",
                            edit(kHollow, "inner_radius = 0.0102, outer_radius = 0.0247 }",
                                 "inner_radius = 0.03, outer_radius = 0.0247 } # <-"),
                            "outer_radius", "an outer radius above inner_radius"},
                    BadCase{"ramp_backwards",
                            edit(kHollow, "pressure_ramp = [0.01, 0.02]\nmaterial = \"rubber\"\n[[",
                                 "pressure_ramp = [0.02, 0.01] # <-\nmaterial = \"rubber\"\n[["),
                            "pressure_ramp", "0 <= start < end"},
                    BadCase{"core_too_big",
                            edit(kHollow, "core_radius = 0.01", "core_radius = 0.011 # <-"),
                            "core_radius", "no larger than the radius"},
                    BadCase{"stretch_on_hemisphere",
                            edit(edit(kHollow, "name = \"outer\"\nmesh = \"geodesic_sphere\"",
                                      "name = \"outer\"\nmesh = \"geodesic_hemisphere\""),
                                 "stretch = 1.25", "stretch = 1.25 # <-"),
                            "stretch", "not used by mesh = \"geodesic_hemisphere\""},
                    BadCase{"object_without_core",
                            edit(edit(kHollow, "core_radius = 0.01\n", ""), "object = \"object\"",
                                 "object = \"object\" # <-"),
                            "object", "core_radius > 0"},
                    BadCase{"vacuums_differ",
                            edit(edit(kHollow, "pressure = 9e4", "pressure = 8e4"),
                                 "object = \"object\"", "object = \"object\" # <-"),
                            "object", "the same vacuum acts on both"},
                    BadCase{"shell_inflated",
                            edit(edit(kHollow, "pressure = -9e4", "pressure = 9e4"),
                                 "shell = \"outer\"", "shell = \"outer\" # <-"),
                            "shell", "a vacuum pressure < 0"}),
    [](const testing::TestParamInfo<BadCase>& info) { return info.param.name; });

}  // namespace
}  // namespace talus::io
