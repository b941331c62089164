// [[membranes]] in MPM scenario files: a valid table resolves to the expected
// parameters and reads back to the same values; bad input names the file, the
// line and the key; the bundled geotextile bag builds.
#include <gtest/gtest.h>

#include "mpm_scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/io/scenario_mpm.hpp"

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
  EXPECT_NEAR(m.stiffness, 2e6, 1e-6);         // J = E t
  EXPECT_NEAR(m.mass_per_length, 1.0, 1e-15);  // rho t
  EXPECT_NEAR(m.spacing, 0.05, 1e-15);         // default: half a cell
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
                    "mass_per_length = 1\npoints = "
                    "[[0.1, 0.1], [0.2, 0.1]]\n"
                    "[[membranes]]\nname = \"bag\""),
               "membrane 'bag' is defined twice");
  // The MPM checkpoint holds no membrane nodes: a run that would write one is refused.
  expect_error(kBase + "[output]\ncheckpoint_interval = 0.1\n",
               "'checkpoint_interval': checkpoints of MPM runs with [[membranes]]");
}

TEST(MpmMembraneScenario, BundledGeotextileBagBuilds) {
  const auto file =
      load_scenario_file(std::string(TALUS_SOURCE_DIR) + "/scenarios/mpm_geotextile_bag.toml", {});
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
