// [flume] builds the flume's walls and release fill from beta and R; the
// expected coordinates are Kuen's Table 2 as corrected in spec flume.md.
#include <gtest/gtest.h>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

const std::string kData = std::string(TALUS_TEST_DATA) + "/scenarios/";

// A 2D scenario with one material and nothing else: each case adds a [flume].
const std::string kHead = R"(method = "dem"
[run]
dimension = 2
duration = 1
[contact]
model = "linear"
[[materials]]
name = "m"
density = 2000
normal_stiffness = 1e6
friction = 0.3
)";

dem::DemScenario parse_text(const std::string& text) {
  return parse_dem_scenario(load_scenario_text(text, "flume.toml"));
}

const dem::WallParams& wall(const dem::DemScenario& s, const std::string& name) {
  for (const auto& w : s.walls) {
    if (w.name == name) return w;
  }
  throw std::runtime_error("no wall " + name);
}

TEST(ScenarioFlume, GeometryBWallsMatchTable2AndTheGateIsLifted) {
  const auto s = parse_dem_scenario(load_scenario_file(kData + "flume_2d.toml", {}));
  ASSERT_TRUE(s.flume);
  ASSERT_EQ(s.walls.size(), 6u);  // chute, arc, barrier, gate, lid + "end"
  // Table 2, beta = 7 deg, R = 0.10 m; 0.5 mm is the table's rounding.
  const double tol = 0.5e-3;
  EXPECT_NEAR(wall(s, "chute").b.x(), 1.4475, tol);
  EXPECT_NEAR(wall(s, "chute").b.y(), 0.3126, tol);
  EXPECT_NEAR(wall(s, "arc").center.x(), 1.4960, tol);
  EXPECT_NEAR(wall(s, "arc").center.y(), 0.4001, tol);
  EXPECT_NEAR(wall(s, "arc").angle_end * 180 / M_PI, 277.0, 1e-9);
  EXPECT_NEAR(wall(s, "barrier").a.x(), 1.5082, tol);
  EXPECT_NEAR(wall(s, "barrier").b.x(), 2.2523, tol);
  EXPECT_NEAR(wall(s, "barrier").b.y(), 0.3922, tol);
  // Table 3: the gate from (0.5276, 0.8226) to (0.5276, 1.1150), lifted at
  // 2 m/s from t = 0.05 s and gone once its foot passed the lid (0.2924 m).
  const auto& gate = wall(s, "gate");
  EXPECT_NEAR(gate.a.y(), 0.8226, tol);
  EXPECT_NEAR(gate.motion.velocity.y(), 2.0, 0.0);
  EXPECT_NEAR(gate.motion.move_start, 0.05, 0.0);
  EXPECT_NEAR(gate.motion.remove_at, 0.05 + (gate.b - gate.a).norm() / 2.0, 1e-12);
  EXPECT_NEAR(wall(s, "lid").motion.remove_at, 0.05, 0.0);
  EXPECT_EQ(s.flume->layers, 4);
  // The release fill: the triangle of area 0.07714 m^2 (flume.md) with Kuen's defaults.
  ASSERT_EQ(s.sources.size(), 1u);
  const auto& fill = s.sources[0];
  EXPECT_TRUE(fill.generated);
  EXPECT_EQ(fill.kind, dem::SourceKind::RandomFill);
  ASSERT_EQ(fill.polygon.size(), 3u);
  const Vec3 a = fill.polygon[1] - fill.polygon[0], b = fill.polygon[2] - fill.polygon[0];
  EXPECT_NEAR(0.5 * std::abs(a.x() * b.y() - a.y() * b.x()), 0.07714, 1e-5);
  EXPECT_DOUBLE_EQ(fill.porosity, 0.1662);
  EXPECT_DOUBLE_EQ(fill.shrink, 0.03);
  EXPECT_DOUBLE_EQ(fill.radius_max, 4e-3);
  EXPECT_TRUE(fill.settle.enabled);
}

TEST(ScenarioFlume, DeletedGateByDefaultAndNoParticlesTableNeeded) {
  const std::string text = kHead + R"([flume]
beta = 33
arc_radius = 0.1
wall_material = "m"
[flume.release]
material = "m"
)";
  const auto s = parse_text(text);
  EXPECT_EQ(wall(s, "gate").motion.remove_at, 0.0);
  EXPECT_EQ(wall(s, "gate").motion.velocity.norm(), 0.0);
  EXPECT_NEAR(*s.flume->shape.l_star, 1.7163, 1e-12);  // Table 2, 33 deg, 0.10 m
  const std::string written = scenario_to_toml(s);
  EXPECT_NE(written.find("[flume]"), std::string::npos);
  EXPECT_EQ(written.find("[[walls]]"), std::string::npos);  // generated walls stay in [flume]
}

void expect_error(const std::string& text, const std::string& fragment) {
  const std::string message = cases::error_of([&] { parse_text(text); });
  EXPECT_NE(message.find(fragment), std::string::npos) << fragment << ": " << message;
  EXPECT_NE(message.find("flume.toml:"), std::string::npos) << message;
}

TEST(ScenarioFlume, BadFlumesAreRefusedWithFileLineAndKey) {
  expect_error(kHead + "[flume]\nbeta = 95\narc_radius = 0.1\nwall_material = \"m\"\n", "beta");
  expect_error(kHead + "[flume]\nbeta = 33\narc_radius = 0.1\nwall_material = \"steel\"\n",
               "wall_material");
  expect_error(
      kHead + "[flume]\nbeta = 33\narc_radius = 0.1\nwall_material = \"m\"\ngate = \"up\"\n",
      "gate");
  expect_error(kHead + "[flume]\nbeta = 33\nwall_material = \"m\"\n", "arc_radius");
  expect_error(kHead + "[flume]\nbeta = 33\narc_radius = 0.1\nwall_material = \"m\"\nbarier = 1\n",
               "barier");
  // A wall of the user's may not take a generated wall's name.
  expect_error(kHead +
                   "[flume]\nbeta = 33\narc_radius = 0.1\nwall_material = \"m\"\n"
                   "[flume.release]\nmaterial = \"m\"\n"
                   "[[walls]]\nname = \"gate\"\ntype = \"segment\"\nmaterial = \"m\"\n"
                   "a = [0, 0]\nb = [1, 0]\n",
               "used twice");
  // Without [flume.release] the particles must come from [[particles]].
  expect_error(kHead + "[flume]\nbeta = 33\narc_radius = 0.1\nwall_material = \"m\"\n",
               "particles");
  // The flume is 2D.
  std::string three_d = kHead;
  three_d.replace(three_d.find("dimension = 2"), 13, "dimension = 3");
  expect_error(three_d + "[flume]\nbeta = 33\narc_radius = 0.1\nwall_material = \"m\"\n", "2D");
}

}  // namespace
}  // namespace talus::io
