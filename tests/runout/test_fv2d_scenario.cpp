// 2D runout scenarios (run.model = "fv2d"): the bundled one parses, builds
// and runs conserving its released volume; the resolved TOML reads back; bad
// input names file, line and key.
#include <gtest/gtest.h>

#include "talus/core/error.hpp"
#include "talus/run/loop.hpp"
#include "talus/run/methods/fv2d.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/runout/grid/fv2d_builder.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::io {
namespace {

const std::string kScenarios = std::string(TALUS_SOURCE_DIR) + "/scenarios/runout/";
const std::string kFile = kScenarios + "runout_terrain_2d.toml";

void expect_error(const std::vector<std::string>& sets, const std::string& needle) {
  try {
    parse_runout_scenario(load_scenario_file(kFile, sets));
    ADD_FAILURE() << "no error; expected one containing " << needle;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("runout_terrain_2d.toml"), std::string::npos) << msg;
    EXPECT_NE(msg.find(needle), std::string::npos) << msg;
  }
}

TEST(Fv2dScenario, BundledScenarioBuildsAndConservesVolume) {
  auto sc = parse_runout_scenario(load_scenario_file(kFile, {}));
  ASSERT_EQ(sc.model, runout::RunoutModel::Fv2d);
  EXPECT_EQ(sc.grid.shape.nx, 90u);
  EXPECT_EQ(sc.grid.shape.ny, 50u);
  EXPECT_EQ(sc.grid.shape.dx, 5.0);
  auto solver = runout::build_fv2d(sc);
  // scripts/make_runout_terrain.py: 60 m x 40 m x 3 m released = 7200 m^3.
  EXPECT_NEAR(solver.volume(), 7200.0, 1e-9);
  // The barrier raster (4 m on 2 x 30 cells, columns 53-54) is added to the terrain.
  EXPECT_NEAR(solver.terrain().elevation()[sc.grid.shape.index(53, 20)] -
                  sc.grid.elevation[sc.grid.shape.index(53, 20)],
              4.0, 1e-12);
  EXPECT_EQ(sc.control.stop_momentum_fraction, 0.01);
  auto shorter = sc;
  shorter.control.duration = 20.0;
  run::Fv2dSimulation sim(shorter);
  run::RunLoop loop(sim, {});
  loop.start(true);
  loop.run();
  const auto& after = sim.solver();
  EXPECT_GT(sim.maxima().peak_speed, 5.0);
  EXPECT_LT(std::abs(after.volume() + after.outflow_volume() - 7200.0) / 7200.0, 1e-12);
}

TEST(Fv2dScenario, ResolvedTomlReadsBack) {
  const auto sc = parse_runout_scenario(load_scenario_file(kFile, {}));
  const auto again = parse_runout_scenario(load_scenario_text(runout_scenario_to_toml(sc), kFile));
  EXPECT_EQ(runout_scenario_to_json(again).dump(), runout_scenario_to_json(sc).dump());
}

TEST(Fv2dScenario, BadInputNamesFileAndKey) {
  expect_error({"terrain.resolution=2"}, "resolution");
  expect_error({"earth_pressure.model=\"hungr\""}, "model");
  expect_error({"terrain.file=\"missing.asc\""}, "file");
  expect_error({"terrain.order=3"}, "order");
  expect_error({"run.courant=0.8"}, "courant");
  expect_error({"output.tail_fraction=0.1"}, "tail_fraction");
  expect_error({"run.stop_momentum_fraction=1"}, "stop_momentum_fraction");
  expect_error({"run.stop_momentum_fraction=-0.1"}, "stop_momentum_fraction");
}

}  // namespace
}  // namespace talus::io
