// [[membranes]] in MPM scenario files: a valid table resolves to the expected
// parameters and reads back to the same values; bad input names the file, the
// line and the key; the bundled geotextile bag builds.
#include <gtest/gtest.h>

#include "mpm_scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario_mpm.hpp"

namespace talus::io {
namespace {

using mpm_cases::edit;
using mpm_cases::expect_error;

const std::string kBase = R"(method = "mpm"
[run]
dimension = 2
duration = 0.5
[grid]
min = [0, 0]
max = [2, 2]
cell_size = 0.1
[[materials]]
name = "sand"
model = "linear_elastic"
density = 2000
youngs_modulus = 1e6
poisson_ratio = 0.3
[[bodies]]
material = "sand"
box = { min = [0.5, 0.5], max = [1.0, 1.0] }
[[membranes]]
name = "bag"
model = "york"
points = [[0.45, 0.45], [1.05, 0.45], [1.05, 1.05], [0.45, 1.05]]
closed = true
youngs_modulus = 1e9
thickness = 2e-3
density = 500
slack = 0.1
slack_box = { min = [0.4, 0.4], max = [1.1, 0.5] }
)";

TEST(MpmMembraneScenario, ParsesRoundTripsAndBuilds) {
  const auto sc = parse_mpm_scenario(load_scenario_text(kBase, "m.toml"));
  ASSERT_EQ(sc.membranes.size(), 1u);
  const auto& m = sc.membranes[0];
  EXPECT_EQ(m.model, mpm::MembraneModel::York);
  EXPECT_TRUE(m.closed);
  EXPECT_EQ(m.points.size(), 4u);
  EXPECT_NEAR(m.stiffness, 2e6, 1e-6);    // J = E t
  EXPECT_NEAR(m.areal_mass, 1.0, 1e-15);  // rho t
  EXPECT_NEAR(m.spacing, 0.05, 1e-15);    // default: half a cell
  EXPECT_FALSE(m.slack_everywhere);
  const std::string resolved = mpm_scenario_to_toml(sc);
  const auto again = parse_mpm_scenario(load_scenario_text(resolved, "r.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump()) << resolved;
  const auto solver = mpm::build_mpm<2>(sc);
  ASSERT_EQ(solver.membranes.size(), 1u);
  // 4 edges of 0.6 m in pieces of 0.05 m.
  EXPECT_EQ(solver.membranes[0].size(), 48u);
}

TEST(MpmMembraneScenario, BadInputNamesFileLineAndKey) {
  expect_error(edit(kBase, "model = \"york\"", "model = \"sulsky\""),
               "bad.toml:20: [[membranes]] 'model'");
  expect_error(edit(kBase, "youngs_modulus = 1e9", "stiffness = 1e6\nyoungs_modulus = 1e9"),
               "'youngs_modulus'");
  expect_error(edit(kBase, "thickness = 2e-3\n", ""), "'thickness'");
  expect_error(edit(kBase, "thickness = 2e-3", "thickness = 2e-3\nmass_per_length = 1"),
               "'mass_per_length': was renamed areal_mass");
  expect_error(edit(kBase, "[1.05, 0.45]", "[2.05, 0.45]"), "outside the [grid]");
  expect_error(edit(kBase, "[1.05, 0.45], [1.05, 1.05], [0.45, 1.05]", "[1.05, 0.45]"),
               "at least 3 points");
  expect_error(edit(kBase, "closed = true", "closed = true\nfixed = \"first\""), "'fixed'");
  expect_error(edit(kBase, "slack = 0.1", "slack = -0.1"), "'slack'");
  expect_error(edit(kBase, "name = \"bag\"", "name = \"my bag\""), "[[membranes]] 'name'");
  expect_error(edit(kBase, "slack = 0.1\n", ""), "'slack_box'");
  expect_error(edit(kBase, "closed = true", "closed = true\nfixd = \"first\""),
               "did you mean 'fixed'");
  expect_error(edit(kBase, "[[membranes]]\nname = \"bag\"",
                    "[[membranes]]\nname = \"bag\"\n"
                    "model = \"fe\"\nstiffness = 1\n"
                    "areal_mass = 1\npoints = "
                    "[[0.1, 0.1], [0.2, 0.1]]\n"
                    "[[membranes]]\nname = \"bag\""),
               "membrane 'bag' is defined twice");
  expect_error(edit(kBase, "model = \"york\"", "model = \"york\"\nshape = \"sheet\""),
               "[[membranes]] 'shape'");
  expect_error(edit(kBase, "closed = true", "closed = true\npoisson_ratio = 0.3"),
               "'poisson_ratio'");
  // Checkpoints of runs with membranes are accepted (they hold the membranes).
  EXPECT_NO_THROW(parse_mpm_scenario(
      load_scenario_text(kBase + "[output]\ncheckpoint_interval = 0.1\n", "m.toml")));
}

// `friction`: the membrane in its own velocity field with Coulomb contact
// against the soil (FE only); absent, it shares the soil's field.
TEST(MpmMembraneScenario, SoilFrictionParsesRoundTripsAndBuilds) {
  EXPECT_LT(parse_mpm_scenario(load_scenario_text(kBase, "m.toml")).membranes[0].soil_friction,
            0.0);
  const std::string fe = edit(kBase, "model = \"york\"", "model = \"fe\"\nfriction = 0.45");
  const auto sc = parse_mpm_scenario(load_scenario_text(fe, "m.toml"));
  EXPECT_EQ(sc.membranes[0].soil_friction, 0.45);
  const std::string resolved = mpm_scenario_to_toml(sc);
  EXPECT_NE(resolved.find("friction = 0.45"), std::string::npos) << resolved;
  const auto again = parse_mpm_scenario(load_scenario_text(resolved, "r.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump());
  const auto solver = mpm::build_mpm<2>(sc);
  EXPECT_TRUE(solver.membranes[0].own_field());
  expect_error(edit(fe, "friction = 0.45", "friction = -0.1"), "[[membranes]] 'friction'");
  expect_error(edit(kBase, "model = \"york\"", "model = \"york\"\nfriction = 0.3"),
               "'friction': a membrane slips on the soil in the FE model only");
}

// 3D: a sheet held by its edges, a box and a sphere (bags); the resolved
// table reads back to the same values; bad input names the key.
const std::string k3d = R"(method = "mpm"
[run]
dimension = 3
duration = 0.5
[grid]
min = [0, 0, 0]
max = [2, 2, 2]
cell_size = 0.1
[[materials]]
name = "sand"
model = "linear_elastic"
density = 2000
youngs_modulus = 1e6
poisson_ratio = 0.3
[[bodies]]
material = "sand"
box = { min = [0.5, 0.5, 0.5], max = [1.0, 1.0, 1.0] }
[[membranes]]
name = "net"
shape = "sheet"
points = [[0.2, 0.2, 1.5], [1.8, 0.2, 1.5], [1.8, 1.8, 1.6], [0.2, 1.8, 1.6]]
fixed = "edges"
stiffness = 1e4
areal_mass = 0.5
poisson_ratio = 0.2
[[membranes]]
name = "bag"
shape = "box"
box = { min = [0.45, 0.45, 0.45], max = [1.05, 1.05, 1.05] }
youngs_modulus = 1e9
thickness = 2e-3
density = 500
slack = 0.1
slack_box = { min = [0.4, 0.4, 0.4], max = [1.1, 1.1, 0.46] }
[[membranes]]
name = "ball"
shape = "sphere"
centre = [1.5, 1.5, 0.5]
radius = 0.3
stiffness = 1e4
areal_mass = 0.5
)";

TEST(MpmMembraneScenario, ThreeDimensionalSurfacesParseRoundTripAndBuild) {
  const auto sc = parse_mpm_scenario(load_scenario_text(k3d, "m.toml"));
  ASSERT_EQ(sc.membranes.size(), 3u);
  EXPECT_EQ(sc.membranes[0].shape, mpm::MembraneShape::Sheet);
  EXPECT_EQ(sc.membranes[0].fixed, mpm::MembraneFixed::Edges);
  EXPECT_EQ(sc.membranes[0].poisson_ratio, 0.2);
  EXPECT_EQ(sc.membranes[1].shape, mpm::MembraneShape::Box);
  EXPECT_NEAR(sc.membranes[1].stiffness, 2e6, 1e-6);
  EXPECT_EQ(sc.membranes[2].shape, mpm::MembraneShape::Sphere);
  EXPECT_EQ(sc.membranes[2].radius, 0.3);
  const std::string resolved = mpm_scenario_to_toml(sc);
  const auto again = parse_mpm_scenario(load_scenario_text(resolved, "r.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump()) << resolved;
  const auto solver = mpm::build_mpm<3>(sc);
  ASSERT_EQ(solver.membranes.size(), 3u);
  // Sheet: 1.6 m / 0.05 by 1.6 m (1.603 m along the tilted sides) / 0.05.
  EXPECT_EQ(solver.membranes[0].size(), 33u * 33u);
  // Box 0.6 m a side in pieces of 0.05 m: 13^3 - 11^3 lattice nodes.
  EXPECT_EQ(solver.membranes[1].size(), 13u * 13u * 13u - 11u * 11u * 11u);
  // The slack is on the triangles of the bottom face (centroids at z 0.45):
  // their rest area is 1.1^2 times as drawn.
  double area = 0.0;
  for (double a : solver.membranes[1].rest_area) area += a;
  EXPECT_NEAR(area, 5 * 0.36 + 1.21 * 0.36, 1e-12);
}

TEST(MpmMembraneScenario, ThreeDimensionalBadInputNamesTheKey) {
  expect_error(edit(k3d, "shape = \"sheet\"\n", ""), "bad.toml:18: [[membranes]] 'shape'");
  expect_error(edit(k3d, "shape = \"sheet\"", "shape = \"polyline\""), "'shape'");
  expect_error(edit(k3d, "name = \"net\"", "name = \"net\"\nmodel = \"york\""), "'model'");
  expect_error(edit(k3d, "[0.2, 1.8, 1.6]]", "]"), "'points': expected the sheet's 4 corners");
  expect_error(edit(k3d, "[1.8, 1.8, 1.6]", "[1.0, 0.2, 1.5]"), "in a line");
  expect_error(edit(k3d, "[1.8, 0.2, 1.5]", "[2.8, 0.2, 1.5]"), "outside the [grid]");
  expect_error(edit(k3d, "fixed = \"edges\"", "fixed = \"first\""), "'fixed'");
  expect_error(edit(k3d, "fixed = \"edges\"", "closed = true"), "'closed'");
  expect_error(edit(k3d, "poisson_ratio = 0.2", "poisson_ratio = 1.0"), "'poisson_ratio'");
  expect_error(edit(k3d, "shape = \"box\"", "shape = \"box\"\nfixed = \"edges\""), "'fixed'");
  expect_error(edit(k3d, "shape = \"box\"", "shape = \"box\"\nradius = 1"), "'radius'");
  expect_error(edit(k3d, "max = [1.05, 1.05, 1.05]", "max = [1.05, 1.05, 2.05]"), "'box'");
  expect_error(edit(k3d, "radius = 0.3", "radius = 0.6"), "'radius'");
  expect_error(edit(k3d, "centre = [1.5, 1.5, 0.5]\n", ""), "'centre'");
}

TEST(MpmMembraneScenario, BundledGeotextileBagBuilds) {
  const auto file = load_scenario_file(
      std::string(TALUS_SOURCE_DIR) + "/scenarios/mpm/mpm_geotextile_bag.toml", {});
  const auto sc = parse_mpm_scenario(file);
  const auto solver = mpm::build_mpm<2>(sc);
  ASSERT_EQ(solver.membranes.size(), 1u);
  // Perimeter 2 (4.2 + 1.6) m in pieces of 0.05 m; the sand 41 x 15 cells x 4.
  EXPECT_EQ(solver.membranes[0].size(), 232u);
  EXPECT_EQ(solver.particles.size(), 82u * 30u);
  EXPECT_EQ(solver.rigid_bodies.size(), 4u);
}

}  // namespace
}  // namespace talus::io
