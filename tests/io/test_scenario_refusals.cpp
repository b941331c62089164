// Input that used to be silently accepted (issue 28, section 4): tables the
// chosen runout model does not read, fixed-length arrays with a number too
// many, and a time step above the critical one, which must name the file, the
// line and the keys behind it.
#include <gtest/gtest.h>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/dem/builder.hpp"
#include "talus/scenario/scenario.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::io {
namespace {

using cases::bundled;
using cases::edit;
using cases::error_of;

const std::string kScenarios = std::string(TALUS_SOURCE_DIR) + "/scenarios/runout/";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The runout scenario NAME with `from` replaced by `to`, as if it were the file
// itself (relative file names resolve in scenarios/runout/); the message of its error
// must start with "file:line:" of the line marked "# <-" and contain expected.
void expect_runout_error(const std::string& name, const std::string& from, const std::string& to,
                         const std::string& expected) {
  const std::string text = edit(bundled("runout/" + name), from, to);
  const std::string path = kScenarios + name;
  const std::string message =
      error_of([&] { parse_runout_scenario(load_scenario_text(text, path)); });
  const std::string head = path + ":" + std::to_string(cases::marked_line(text)) + ":";
  EXPECT_EQ(message.rfind(head, 0), 0u) << message << "\nexpected to start with " << head;
  EXPECT_TRUE(contains(message, expected)) << message;
}

TEST(Refusals, TablesOfTheOtherRunoutModel) {
  expect_runout_error("runout_flume_A.toml", "[output]",
                      "[terrain] # <-\nfile = \"runout_terrain/terrain.asc\"\n[output]",
                      "'terrain': is only used by models 'fv2d' and 'two_phase'");
  expect_runout_error("runout_terrain_2d.toml", "[output]",
                      "[path] # <-\ntype = \"flume\"\nbeta = 33\narc_radius = 0.1\n[output]",
                      "'path': is not used by model 'fv2d'");
  expect_runout_error("runout_terrain_2d.toml", "[output]",
                      "[smoothing] # <-\nc_end = 0.004\n[output]",
                      "'smoothing': is not used by model 'fv2d'");
}

TEST(Refusals, FixedLengthArraysWithANumberTooMany) {
  expect_runout_error("runout_profile_slope.toml", "polygon = [[1.0, 9.3], [4.0, 7.2],",
                      "polygon = [[1.0, 9.3, 0], [4.0, 7.2], # <-\n",
                      "expected a list of points [[x, y], ...]");
  const std::string sheet = bundled("dem/membrane_sheet_drop.toml");
  for (const char* ramp : {"[0, 0.02, 5]", "[0, 0.02, 0]", "[0.02]"}) {
    const std::string text =
        edit(sheet, "fixed = \"edge\"",
             "fixed = \"edge\"\npressure = -1000\npressure_ramp = " + std::string(ramp));
    const std::string message =
        error_of([&] { parse_dem_scenario(load_scenario_text(text, "sheet.toml")); });
    EXPECT_TRUE(contains(
        message,
        "[[membranes]] 'pressure_ramp': expected [start, end] in s, got " + std::string(ramp)))
        << message;
  }
  const std::string message = error_of([&] {
    parse_dem_scenario(
        load_scenario_text(edit(sheet, "size = [0.1, 0.1]", "size = [0.1, 0.1, 0]"), "sheet.toml"));
  });
  EXPECT_TRUE(contains(message, "'size': expected [lx, ly] in m, got [0.1, 0.1, 0]")) << message;
  // Still read: [start, end] and [lx, ly].
  const auto s = parse_dem_scenario(
      load_scenario_text(edit(sheet, "fixed = \"edge\"",
                              "fixed = \"edge\"\npressure = -1000\npressure_ramp = [0, 0.02]"),
                         "sheet.toml"));
  EXPECT_DOUBLE_EQ(s.membranes[0].pressure_ramp_end, 0.02);
  EXPECT_DOUBLE_EQ(s.membranes[0].size_y, 0.1);
}

const char* kTinyDem = R"(method = "dem"
[run]
dimension = 2
duration = 0.1
time_step = 1e-4
[contact]
model = "linear"
[[materials]]
name = "sand"
density = 2672
friction = 0.3
normal_stiffness = 1e6
[[particles]]
type = "list"
material = "sand"
[[particles.list]]
position = [0.5, 0.5]
radius = 0.01
)";

TEST(Refusals, TimeStepAboveCriticalNamesFileLineAndKeys) {
  const std::string path = cases::write_temp("tiny_dem", kTinyDem);
  // As written the step is fine; a much lighter grain makes it too long.
  const auto fine = parse_dem_scenario(load_scenario_file(path, {}));
  EXPECT_NO_THROW(dem::build_dem<2>(fine, {1, false}));
  const auto light = parse_dem_scenario(load_scenario_file(path, {"materials.0.density=2"}));
  std::string message = error_of([&] { dem::build_dem<2>(light, {1, false}); });
  EXPECT_EQ(message.rfind(path + ":5: [run] 'time_step': 0.0001 s is above the critical", 0), 0u)
      << message;
  EXPECT_TRUE(contains(message, "[[materials]] 'sand': materials.0.density = 2 kg/m^3")) << message;
  // A step given with --set is said to be.
  const auto set = parse_dem_scenario(load_scenario_file(path, {"run.time_step=1e-2"}));
  message = error_of([&] { dem::build_dem<2>(set, {1, false}); });
  EXPECT_EQ(message.rfind(path + ": --set run.time_step: 0.01 s is above", 0), 0u) << message;
}

// The grid models on a flume path (runout/grid/path_grid.hpp): the path's grid
// keys are checked, and what the path's grid does not do is refused.
TEST(Refusals, GridModelsOnAPath) {
  const std::string fv2d = "runout_flume_A_fv2d.toml";
  expect_runout_error(fv2d, "cell_size = 0.005", "cell_size = 0 # <-", "'cell_size'");
  expect_runout_error(fv2d, "rows = 3", "rows = 0 # <-", "an integer in [1, 1000]");
  expect_runout_error(fv2d, "[release]\ntype = \"flume\"",
                      "[release]\ntype = \"flume\"\nblocks = 100 # <-",
                      "'blocks': is only used by model 'dan'");
  expect_runout_error("runout_flume_A.toml", "width = 1.0", "width = 1.0\ncell_size = 0.005 # <-",
                      "'cell_size': is only used by the grid models");
  expect_runout_error(fv2d, "type = \"flume\"\nbeta = 33", "type = \"profile\" # <-\nbeta = 33",
                      "takes type 'flume'");
}

}  // namespace
}  // namespace talus::io
