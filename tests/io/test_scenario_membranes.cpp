// [[membranes]]: a valid table parses into MembraneSpec and survives the
// resolved-scenario round trip; bad keys give an InputError naming file,
// line (the one marked "# <-") and key.
#include <gtest/gtest.h>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

const std::string kHead = R"(method = "dem"
[run]
dimension = 3
duration = 0.1
[contact]
model = "viscoelastic_hertz"
[[materials]]
name = "grain"
density = 2500
youngs_modulus = 1e7
friction = 0.3
dissipation = 1e-4
[[materials]]
name = "rubber"
youngs_modulus = 1e7
friction = 1.2
[[particles]]
type = "list"
material = "grain"
[[particles.list]]
position = [0.02, 0.02, 0.01]
radius = 0.002
)";

const std::string kSheet = R"([[membranes]]
name = "sheet"
mesh = "flat_sheet"
origin = [0, 0, 0]
size = [0.04, 0.04]
spacing = 0.004
youngs_modulus = 1.25e6
thickness = 3e-4
density = 1000
spring_damping = 0.15
bending_stiffness = 1e-3
bending_damping = 1e-4
pressure = -9e4
fixed = "edge"
material = "rubber"
)";

using cases::BadCase;
using cases::edit;

TEST(MembraneScenario, SheetParsesWithEveryKey) {
  const auto s = parse_dem_scenario(load_scenario_text(kHead + kSheet, "sheet.toml"));
  ASSERT_EQ(s.membranes.size(), 1u);
  const auto& m = s.membranes[0];
  EXPECT_EQ(m.name, "sheet");
  EXPECT_EQ(m.mesh, dem::MembraneMeshKind::FlatSheet);
  EXPECT_DOUBLE_EQ(m.size_x, 0.04);
  EXPECT_DOUBLE_EQ(m.spacing, 0.004);
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 1.25e6);
  EXPECT_DOUBLE_EQ(m.bending_damping, 1e-4);
  EXPECT_DOUBLE_EQ(m.pressure, -9e4);
  EXPECT_EQ(m.fixed, dem::MembraneFixed::Edge);
  EXPECT_EQ(m.material, "rubber");
}

// The granular beam's membrane (Götz §5.2): a closed rounded box, vacuum
// ramped in.
const std::string kBoxMesh =
    "mesh = \"box\"\ncenter = [0, 0, 0.2]\nsize = [0.08, 0.08, 0.4]\nedge_radius = 0.01\n"
    "spacing = 0.0089";
const std::string kSheetMesh =
    "mesh = \"flat_sheet\"\norigin = [0, 0, 0]\nsize = [0.04, 0.04]\nspacing = 0.004";

TEST(MembraneScenario, BoxParsesAndSurvivesTheRoundTrip) {
  std::string text = edit(edit(kHead + kSheet, kSheetMesh, kBoxMesh), "fixed = \"edge\"",
                          "pressure_ramp = [0.0, 0.01]");
  const auto s = parse_dem_scenario(load_scenario_text(text, "box.toml"));
  ASSERT_EQ(s.membranes.size(), 1u);
  const auto& m = s.membranes[0];
  EXPECT_EQ(m.mesh, dem::MembraneMeshKind::Box);
  EXPECT_EQ(m.origin, Vec3(0, 0, 0.2));
  EXPECT_DOUBLE_EQ(m.size_x, 0.08);
  EXPECT_DOUBLE_EQ(m.size_z, 0.4);
  EXPECT_DOUBLE_EQ(m.edge_radius, 0.01);
  EXPECT_DOUBLE_EQ(m.spacing, 0.0089);
  EXPECT_DOUBLE_EQ(m.pressure_ramp_end, 0.01);
  const auto again = parse_dem_scenario(load_scenario_text(scenario_to_toml(s), "again.toml"));
  EXPECT_EQ(again.membranes[0].mesh, dem::MembraneMeshKind::Box);
  EXPECT_DOUBLE_EQ(again.membranes[0].size_y, 0.08);
  EXPECT_DOUBLE_EQ(again.membranes[0].edge_radius, 0.01);
  EXPECT_DOUBLE_EQ(again.membranes[0].pressure_ramp_end, 0.01);
}

TEST(MembraneScenario, ResolvedScenarioKeepsMembranes) {
  const std::string cyl = R"([[membranes]]
name = "jacket"
mesh = "cylinder"
center = [0, 0, 0.01]
radius = 0.025
height = 0.1
spacing = 0.004
caps = false
youngs_modulus = 1.25e6
thickness = 3e-4
density = 1000
pressure = 1e5
fixed = "both_rings"
material = "rubber"
)";
  const auto a = parse_dem_scenario(load_scenario_text(kHead + kSheet + cyl, "a.toml"));
  const auto b = parse_dem_scenario(load_scenario_text(scenario_to_toml(a), "b.toml"));
  ASSERT_EQ(b.membranes.size(), 2u);
  EXPECT_EQ(b.membranes[1].mesh, dem::MembraneMeshKind::Cylinder);
  EXPECT_EQ(b.membranes[1].fixed, dem::MembraneFixed::BothRings);
  EXPECT_DOUBLE_EQ(b.membranes[1].origin.z(), 0.01);
  EXPECT_DOUBLE_EQ(b.membranes[1].height, 0.1);
  EXPECT_DOUBLE_EQ(b.membranes[0].size_y, 0.04);
  EXPECT_DOUBLE_EQ(b.membranes[0].pressure, -9e4);
  EXPECT_FALSE(b.membranes[0].self_contact);
}

TEST(MembraneScenario, SelfContactIsOptInAndSurvivesTheRoundTrip) {
  const std::string text =
      edit(kHead + kSheet, "fixed = \"edge\"", "fixed = \"edge\"\nself_contact = true");
  const auto a = parse_dem_scenario(load_scenario_text(text, "a.toml"));
  ASSERT_EQ(a.membranes.size(), 1u);
  EXPECT_TRUE(a.membranes[0].self_contact);
  const auto b = parse_dem_scenario(load_scenario_text(scenario_to_toml(a), "b.toml"));
  EXPECT_TRUE(b.membranes[0].self_contact);
}

class BadMembrane : public testing::TestWithParam<BadCase> {};

TEST_P(BadMembrane, InputErrorNamesFileLineAndKey) {
  cases::expect_input_error(GetParam(), "membrane_");
}

const std::string kGood = kHead + kSheet;

INSTANTIATE_TEST_SUITE_P(
    Scenario, BadMembrane,
    testing::Values(
        BadCase{"unknown_mesh", edit(kGood, "mesh = \"flat_sheet\"", "mesh = \"sheet\" # <-"),
                "mesh", "expected one of \"flat_sheet\", \"cylinder\""},
        BadCase{"negative_modulus",
                edit(kGood, "youngs_modulus = 1.25e6", "youngs_modulus = -1 # <-"),
                "youngs_modulus", "expected a positive number, got -1"},
        BadCase{"zero_thickness", edit(kGood, "thickness = 3e-4", "thickness = 0 # <-"),
                "thickness", "expected a positive number, got 0"},
        BadCase{
            "missing_density",
            edit(edit(kGood, "density = 1000\n", ""), "[[membranes]]\n", "[[membranes]] # <-\n"),
            "density", "missing"},
        BadCase{"negative_damping",
                edit(kGood, "spring_damping = 0.15", "spring_damping = -0.1 # <-"),
                "spring_damping", "expected a number >= 0"},
        BadCase{"unknown_material",
                edit(kGood, "material = \"rubber\"", "material = \"latex\" # <-"), "material",
                "latex"},
        BadCase{"ring_on_sheet", edit(kGood, "fixed = \"edge\"", "fixed = \"bottom_ring\" # <-"),
                "fixed", "needs mesh = \"cylinder\""},
        BadCase{"unknown_fixed", edit(kGood, "fixed = \"edge\"", "fixed = \"rim\" # <-"), "fixed",
                "expected one of \"none\", \"edge\""},
        BadCase{"key_of_other_mesh",
                edit(kGood, "spacing = 0.004", "spacing = 0.004\nfrequency = 4 # <-"), "frequency",
                "not used by mesh = \"flat_sheet\""},
        BadCase{"sheet_smaller_than_spacing",
                edit(kGood, "size = [0.04, 0.04]", "size = [0.04, 0.001] # <-"), "size",
                "both sides at least the spacing"},
        BadCase{"odd_hemisphere",
                edit(kGood,
                     "mesh = \"flat_sheet\"\norigin = [0, 0, 0]\nsize = [0.04, 0.04]\n"
                     "spacing = 0.004",
                     "mesh = \"geodesic_hemisphere\"\nradius = 0.04\nfrequency = 3 # <-"),
                "frequency", "an even integer"},
        BadCase{"edge_of_closed_sphere",
                edit(edit(kGood,
                          "mesh = \"flat_sheet\"\norigin = [0, 0, 0]\nsize = [0.04, 0.04]\n"
                          "spacing = 0.004",
                          "mesh = \"geodesic_sphere\"\nradius = 0.04\nfrequency = 4"),
                     "fixed = \"edge\"", "fixed = \"edge\" # <-"),
                "fixed", "a closed membrane has no edge"},
        BadCase{"box_flat_size",
                edit(edit(kGood, kSheetMesh, kBoxMesh), "size = [0.08, 0.08, 0.4]",
                     "size = [0.08, 0.0, 0.4] # <-"),
                "size", "every side > 0"},
        BadCase{"box_radius_too_large",
                edit(edit(kGood, kSheetMesh, kBoxMesh), "edge_radius = 0.01",
                     "edge_radius = 0.05 # <-"),
                "edge_radius", "at most half the smallest side (0.04 m)"},
        BadCase{"box_spacing_too_coarse_for_radius",
                edit(edit(kGood, kSheetMesh, kBoxMesh), "spacing = 0.0089", "spacing = 0.02 # <-"),
                "spacing", "at most pi edge_radius / 2"},
        BadCase{"box_flat_part_too_short",
                edit(edit(kGood, kSheetMesh, kBoxMesh), "edge_radius = 0.01\nspacing = 0.0089",
                     "edge_radius = 0.039\nspacing = 0.0089 # <-"),
                "spacing", "twice the flat part"},
        BadCase{
            "box_has_no_edge",
            edit(edit(kGood, kSheetMesh, kBoxMesh), "fixed = \"edge\"", "fixed = \"edge\" # <-"),
            "fixed", "a closed membrane has no edge"},
        BadCase{
            "negative_ramp",
            edit(kGood, "fixed = \"edge\"", "fixed = \"edge\"\npressure_ramp = [-1, 0.01] # <-"),
            "pressure_ramp", "0 <= start < end"},
        BadCase{"self_contact_not_boolean",
                edit(kGood, "fixed = \"edge\"", "fixed = \"edge\"\nself_contact = 1 # <-"),
                "self_contact", "true or false"},
        BadCase{"linear_model",
                edit(edit(edit(edit(kGood, "model = \"viscoelastic_hertz\"", "model = \"linear\""),
                               "dissipation = 1e-4", "normal_stiffness = 1e5"),
                          "friction = 1.2", "friction = 1.2\nnormal_stiffness = 1e5"),
                     "material = \"rubber\"", "material = \"rubber\" # <-"),
                "material", "need contact.model"}),
    [](const testing::TestParamInfo<BadCase>& info) { return info.param.name; });

TEST(BadMembrane, TwoDimensionalRunRejectsMembranes) {
  std::string text = edit(kGood, "dimension = 3", "dimension = 2");
  text = edit(text, "position = [0.02, 0.02, 0.01]", "position = [0.02, 0.02]");
  const std::string message =
      cases::error_of([&] { parse_dem_scenario(load_scenario_text(text, "twod.toml")); });
  EXPECT_NE(message.find("membranes need run.dimension = 3"), std::string::npos) << message;
}

}  // namespace
}  // namespace talus::io
