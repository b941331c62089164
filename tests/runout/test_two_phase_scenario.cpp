// Two-phase runout scenarios (run.model = "two_phase"): the bundled debris
// flow parses and builds with its solid-fraction raster, its resolved TOML
// reads back, and every new key refuses bad input naming file, line and key.
#include <gtest/gtest.h>

#include <fstream>

#include "io/scenario_cases.hpp"
#include "talus/runout/grid/two_phase_builder.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::io {
namespace {

using cases::bundled;
using cases::edit;
using cases::error_of;

const std::string kScenarios = std::string(TALUS_SOURCE_DIR) + "/scenarios/runout/";
const std::string kName = "two_phase_debris_valley.toml";

// The bundled scenario with `from` replaced by `to`, read as if it were the
// file itself; the error must start with "file:line:" of the line marked
// "# <-", quote `key` and contain `expected`.
void expect_error(const std::string& from, const std::string& to, const std::string& key,
                  const std::string& expected) {
  const std::string text = edit(bundled("runout/" + kName), from, to);
  const std::string path = kScenarios + kName;
  const std::string message =
      error_of([&] { parse_runout_scenario(load_scenario_text(text, path)); });
  const std::string head = path + ":" + std::to_string(cases::marked_line(text)) + ":";
  EXPECT_EQ(message.rfind(head, 0), 0u) << message << "\nexpected to start with " << head;
  EXPECT_NE(message.find("'" + key + "'"), std::string::npos) << message;
  EXPECT_NE(message.find(expected), std::string::npos) << message;
}

TEST(TwoPhaseScenario, BundledScenarioBuildsWithItsSolidFraction) {
  const auto sc = parse_runout_scenario(load_scenario_file(kScenarios + kName, {}));
  ASSERT_EQ(sc.model, runout::RunoutModel::TwoPhase);
  EXPECT_EQ(sc.grid.shape.nx, 100u);
  EXPECT_EQ(sc.grid.shape.ny, 50u);
  const auto& p = sc.two_phase.params;
  EXPECT_EQ(p.drag.solid_density, 2650.0);
  EXPECT_EQ(p.drag.fluid_density, 1100.0);
  EXPECT_EQ(p.drag.exponent, 2);
  EXPECT_NEAR(p.tan_basal_friction, std::tan(20.0 * M_PI / 180.0), 1e-15);
  const auto solver = runout::build_two_phase(sc);
  // scripts/make_debris_valley.py: 2.5 m on 10 x 8 cells of 5 m = 5000 m^3, the
  // solid fraction linear in x from 0.64 to 0.46 over the ten columns (mean
  // 0.55): 2750 m^3 of solid, 2250 of fluid.
  EXPECT_NEAR(solver.solid_volume(), 2750.0, 1e-9);
  EXPECT_NEAR(solver.fluid_volume(), 2250.0, 1e-9);
}

TEST(TwoPhaseScenario, ResolvedTomlReadsBack) {
  const auto sc = parse_runout_scenario(load_scenario_file(kScenarios + kName, {}));
  const auto again =
      parse_runout_scenario(load_scenario_text(runout_scenario_to_toml(sc), kScenarios + kName));
  EXPECT_EQ(runout_scenario_to_json(again).dump(), runout_scenario_to_json(sc).dump());
  // A constant fraction and rates come back too (rates in mm/h).
  const std::string text =
      edit(bundled("runout/" + kName), "solid_fraction_file = \"debris_valley/solid_fraction.asc\"",
           "solid_fraction = 0.6\nfluid_fraction = 0.4\n[hydrology]\nrainfall = 36\n"
           "infiltration = 3.6");
  const auto constant = parse_runout_scenario(load_scenario_text(text, kScenarios + kName));
  EXPECT_EQ(constant.two_phase.solid_fraction, 0.6);
  EXPECT_NEAR(constant.two_phase.params.rainfall, 1e-5, 1e-20);  // 36 mm/h in m/s
  EXPECT_NEAR(constant.two_phase.params.infiltration, 1e-6, 1e-21);
  const auto back = parse_runout_scenario(
      load_scenario_text(runout_scenario_to_toml(constant), kScenarios + kName));
  EXPECT_EQ(runout_scenario_to_json(back).dump(), runout_scenario_to_json(constant).dump());
}

const std::string kFractionFile = "solid_fraction_file = \"debris_valley/solid_fraction.asc\"";

TEST(TwoPhaseScenario, FractionsOutOfRangeOrNotSummingToOne) {
  expect_error(kFractionFile, "solid_fraction = -0.1 # <-", "solid_fraction", "[0, 1]");
  expect_error(kFractionFile, "solid_fraction = 1.2 # <-", "solid_fraction", "[0, 1]");
  expect_error(kFractionFile, "solid_fraction = 0.6\nfluid_fraction = 0.3 # <-", "fluid_fraction",
               "expected alpha_s + alpha_f = 1");
  expect_error(kFractionFile, "solid_fraction = 0.6\n" + kFractionFile + " # <-",
               "solid_fraction_file", "expected one of them");
  // Neither: named at the table's header.
  const std::string text =
      edit(edit(bundled("runout/" + kName), kFractionFile, ""), "[release]", "[release] # <-");
  const std::string path = kScenarios + kName;
  const std::string message =
      error_of([&] { parse_runout_scenario(load_scenario_text(text, path)); });
  EXPECT_EQ(message.rfind(path + ":" + std::to_string(cases::marked_line(text)) + ":", 0), 0u)
      << message;
  EXPECT_NE(message.find("expected one of 'solid_fraction'"), std::string::npos) << message;
}

TEST(TwoPhaseScenario, FractionRastersOffTheGridOrAboveOne) {
  const std::string dir = testing::TempDir();
  // A fraction of 1.5 in one cell, on the terrain's grid.
  {
    std::ifstream in(kScenarios + "debris_valley/solid_fraction.asc");
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    const auto at = text.find("0.6400");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 6, "1.5000");
    std::ofstream(dir + "fraction_high.asc") << text;
  }
  expect_error(kFractionFile, "solid_fraction_file = \"" + dir + "fraction_high.asc\" # <-",
               "solid_fraction_file", "is 1.5; expected a fraction in [0, 1]");
  // On a grid of another extent.
  std::ofstream(dir + "fraction_small.asc")
      << "ncols 2\nnrows 2\nxllcorner 600000\nyllcorner 5200000\ncellsize 5\n"
         "NODATA_value -9999\n0.5 0.5\n0.5 0.5\n";
  expect_error(kFractionFile, "solid_fraction_file = \"" + dir + "fraction_small.asc\" # <-",
               "solid_fraction_file", "is not the terrain's");
}

TEST(TwoPhaseScenario, PhasesOutOfRange) {
  expect_error("density = 1100", "density = 3000 # <-", "density", "lighter than the solid");
  expect_error("basal_friction = 20", "basal_friction = 40 # <-", "basal_friction",
               "above internal_friction");
  expect_error("grain_diameter = 0.005", "grain_diameter = 0 # <-", "grain_diameter", "positive");
  // A required key left out: named with its table.
  const std::string text = edit(bundled("runout/" + kName), "grain_diameter = 0.005\n", "");
  const std::string message =
      error_of([&] { parse_runout_scenario(load_scenario_text(text, kScenarios + kName)); });
  EXPECT_NE(message.find("grain_diameter"), std::string::npos) << message;
  expect_error("manning = 0.06", "manning = -0.01 # <-", "manning", "");
  expect_error("viscosity_alpha = 0.002", "viscosity_alpha = 0 # <-", "viscosity_alpha",
               "positive");
  expect_error("exponent = 2", "exponent = 3 # <-", "exponent", "1 (linear drag) or 2");
}

TEST(TwoPhaseScenario, RatesAndTablesOfOtherModels) {
  expect_error("[output]", "[hydrology]\nrainfall = -1 # <-\n[output]", "rainfall", "");
  expect_error("[output]",
               "[hydrology]\nrainfall = 10\nrainfall_file = \"debris_valley/release.asc\" # <-\n"
               "[output]",
               "rainfall_file", "expected one of them");
  expect_error("[output]", "[material] # <-\ndensity = 2000\n[output]", "material",
               "is not used by model 'two_phase'");
  expect_error("duration = 120.0", "duration = 120.0\nstop_momentum_fraction = 0.01 # <-",
               "stop_momentum_fraction", "is only used by model 'fv2d'");
  // The two-phase tables in a single-phase grid run.
  const std::string fv2d = edit(bundled("runout/runout_terrain_2d.toml"), "[output]",
                                "[fluid] # <-\ndensity = 1000\n[output]");
  const std::string path = kScenarios + "runout_terrain_2d.toml";
  const std::string message =
      error_of([&] { parse_runout_scenario(load_scenario_text(fv2d, path)); });
  EXPECT_NE(message.find("'fluid': is only used by model 'two_phase'"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace talus::io
