// Runout scenario files (method = "runout"): the bundled ones parse and build,
// the resolved TOML reads back to the same values, and bad input names the
// file, line and key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "talus/core/error.hpp"
#include "talus/runout/builder.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::io {
namespace {

const std::string kScenarios = std::string(TALUS_SOURCE_DIR) + "/scenarios/runout/";

const std::string kBase = R"(method = "runout"
[run]
duration = 1.0
[path]
type = "flume"
beta = 33
arc_radius = 0.1
[material]
density = 1630
internal_friction = 30.9
basal_friction = 21.7
[release]
type = "flume"
blocks = 20
)";

std::string edit(const std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.substr(0, at) + to + text.substr(at + from.size());
}

// Expects an InputError whose message has "file:line:" and the key.
void expect_error(const std::string& text, int line, const std::string& needle) {
  try {
    parse_runout_scenario(load_scenario_text(text, "case.toml"));
    ADD_FAILURE() << "no error; expected one containing " << needle;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("case.toml:" + std::to_string(line) + ":"), std::string::npos) << msg;
    EXPECT_NE(msg.find(needle), std::string::npos) << msg;
  }
}

TEST(RunoutScenario, BundledScenariosParseAndBuild) {
  for (const char* name : {"runout_flume_A.toml", "runout_profile_slope.toml"}) {
    const auto sc = parse_runout_scenario(load_scenario_file(kScenarios + name, {}));
    const auto setup = runout::build_dan(sc);
    EXPECT_GE(setup.model.size(), 2u) << name;
  }
  const auto flume =
      parse_runout_scenario(load_scenario_file(kScenarios + "runout_flume_A.toml", {}));
  // flume.md: release triangle 0.07714 m^2; per metre of width.
  EXPECT_NEAR(runout::build_dan(flume).model.deformed_volume(), 0.07714, 1e-5);
  EXPECT_NEAR(flume.params.pressure.phi_internal, 30.9 * M_PI / 180, 1e-15);
}

TEST(RunoutScenario, ResolvedTomlReadsBack) {
  for (const char* name : {"runout_flume_A.toml", "runout_profile_slope.toml"}) {
    const auto sc = parse_runout_scenario(load_scenario_file(kScenarios + name, {}));
    const std::string toml = runout_scenario_to_toml(sc);
    const auto again =
        parse_runout_scenario(load_scenario_text(toml, kScenarios + "resolved.toml"));
    EXPECT_EQ(runout_scenario_to_json(again).dump(), runout_scenario_to_json(sc).dump()) << toml;
  }
}

TEST(RunoutScenario, OverridesApply) {
  const auto sc = parse_runout_scenario(
      load_scenario_text(kBase, "case.toml", {"release.blocks=64", "material.basal_friction=25"}));
  EXPECT_EQ(sc.release.blocks, 64u);
  EXPECT_NEAR(sc.params.rheology.tan_friction, std::tan(25 * M_PI / 180), 1e-15);
}

TEST(RunoutScenario, BadInputNamesFileLineKey) {
  expect_error(edit(kBase, "density = 1630", "densty = 1630"), 9, "densty");
  expect_error(edit(kBase, "beta = 33", "beta = 95"), 6, "beta");
  expect_error(edit(kBase, "blocks = 20", "blocks = 1"), 14, "blocks");
  expect_error(edit(kBase, "basal_friction = 21.7", "basal_friction = 21.7\nturbulence = 400"), 12,
               "turbulence");
  expect_error(edit(kBase, "[run]\n", "[run]\nmodel = \"fv\"\n"), 3, "model");
  expect_error(edit(kBase, "duration = 1.0", "duration = -1"), 3, "duration");
  // A profile path cannot take the flume's release triangle.
  const std::string csv = (std::filesystem::temp_directory_path() /
                           ("talus_profile_" + std::to_string(::getpid()) + ".csv"))
                              .string();
  std::ofstream(csv) << "x,y,width\n0,1,1\n2,0,1\n";
  const std::string profile =
      edit(edit(kBase, "beta = 33\narc_radius = 0.1\n", "file = \"" + csv + "\"\n"),
           "type = \"flume\"\n", "type = \"profile\"\n");
  expect_error(profile, 12, "'flume' needs a path of type 'flume'");
}

TEST(RunoutScenario, ProfileCsvErrorsNameFileAndLine) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string bad = (dir / "talus_bad_profile.csv").string();
  std::ofstream(bad) << "x,y,width\n0,1,1\n2,0,1\n1,0,1\n";
  std::vector<Eigen::Vector2d> points;
  std::vector<double> widths;
  try {
    read_profile_csv(bad, points, widths);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(bad + ":4:"), std::string::npos) << e.what();
  }
  std::ofstream(bad) << "x,y\n0,1\n";
  EXPECT_THROW(read_profile_csv(bad, points, widths), InputError);
}

}  // namespace
}  // namespace talus::io
