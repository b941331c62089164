// Input that used to be silently accepted (issue 28, section 4): tables the
// chosen runout model does not read, and fixed-length arrays with a number
// too many or too few.
#include <gtest/gtest.h>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/io/scenario.hpp"
#include "talus/io/scenario_runout.hpp"

namespace talus::io {
namespace {

using cases::bundled;
using cases::edit;
using cases::error_of;

const std::string kScenarios = std::string(TALUS_SOURCE_DIR) + "/scenarios/";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The runout scenario NAME with `from` replaced by `to`, as if it were the file
// itself (relative file names resolve in scenarios/); the message of its error
// must start with "file:line:" of the line marked "# <-" and contain expected.
void expect_runout_error(const std::string& name, const std::string& from, const std::string& to,
                         const std::string& expected) {
  const std::string text = edit(bundled(name), from, to);
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
                      "'terrain': is only used by model 'fv2d'");
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
  const std::string sheet = bundled("membrane_sheet_drop.toml");
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

}  // namespace
}  // namespace talus::io
