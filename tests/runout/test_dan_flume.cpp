// The bundled DAN flume scenario (geometry A): it runs, conserves mass, reports
// the flume results, and converges as blocks and time step are refined
// (issue 4: "Results converge as blocks and time step are refined").
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "talus/run/loop.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/runout/builder.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::runout {
namespace {

struct FlumeRun {
  RunoutResults results;
  double front_s, mass_error;
};

FlumeRun run_flume(std::size_t blocks, double courant) {
  const std::string file = std::string(TALUS_SOURCE_DIR) + "/scenarios/runout/runout_flume_A.toml";
  auto sc = io::parse_runout_scenario(io::load_scenario_file(file, {}));
  sc.release.blocks = blocks;
  sc.control.courant = courant;
  sc.control.time_step = 0;  // auto
  run::DanSimulation sim(sc);
  const double v0 = sim.model().deformed_volume();
  run::RunLoop loop(sim, {});
  loop.start(true);
  loop.run();
  return {sim.results(), sim.model().blocks().s.back(),
          std::abs(sim.model().deformed_volume() - v0) / v0};
}

TEST(DanFlume, RunsAndReportsFlumeResults) {
  const auto flume = geometry::make_flume({deg2rad(33), 0.10, {}, {}});
  const FlumeRun r = run_flume(100, 0.5);
  // Released volume per metre: the triangle behind the gate, 0.07714 m^2
  // (flume.md), kept to round-off.
  EXPECT_LT(r.mass_error, 1e-12);
  const auto& res = r.results;
  // The front reaches the barrier and climbs it, but not over its top.
  ASSERT_FALSE(std::isnan(res.barrier_arrival_time));
  EXPECT_GT(res.runup_final.s, flume.arc_end_s());
  EXPECT_LT(res.runup_max.s, flume.path_end_s());
  EXPECT_LE(res.runup_final.elevation, res.runup_max.elevation + 1e-12);
  EXPECT_GT(res.runup_max.elevation, flume.barrier_start.y());
  // The front series starts at the gate (s = 0) and never moves upstream of it.
  ASSERT_GT(res.front.size(), 100u);
  EXPECT_NEAR(res.front.front().s, 0.0, 1e-9);
  // The deposit: one point per boundary block, the tail on the chute.
  EXPECT_EQ(res.deposit.size(), 100u);
  EXPECT_LT(res.tail_s, flume.chute_end_s());
  EXPECT_GE(res.tail_s, res.tail_s_absolute);
  // simulate_dan (for talus compare) is the same run without files.
  const std::string file = std::string(TALUS_SOURCE_DIR) + "/scenarios/runout/runout_flume_A.toml";
  const auto same = run::simulate_dan(io::parse_runout_scenario(io::load_scenario_file(file, {})));
  EXPECT_EQ(same.runup_max.s, res.runup_max.s);
  EXPECT_EQ(same.front.size(), res.front.size());
}

TEST(DanFlume, ConvergesWithBlocksAndTimeStep) {
  // Successive differences must shrink under refinement (halving the block
  // size, halving the time step through the Courant number).
  const FlumeRun b50 = run_flume(50, 0.5), b100 = run_flume(100, 0.5), b200 = run_flume(200, 0.5);
  auto diff = [](const FlumeRun& a, const FlumeRun& b) { return std::abs(a.front_s - b.front_s); };
  auto diff_runup = [](const FlumeRun& a, const FlumeRun& b) {
    return std::abs(a.results.runup_max.elevation - b.results.runup_max.elevation);
  };
  EXPECT_LT(diff(b100, b200), diff(b50, b100));
  EXPECT_LT(diff_runup(b100, b200), diff_runup(b50, b100));
  const FlumeRun c25 = run_flume(100, 0.25), c125 = run_flume(100, 0.125);
  EXPECT_LT(diff(c25, c125), diff(b100, c25));
  EXPECT_LT(diff_runup(c25, c125), diff_runup(b100, c25));
  // The time-step error is already small at Courant 0.5: under 1 cm.
  EXPECT_LT(diff(b100, c125), 0.01);
}

}  // namespace
}  // namespace talus::runout
