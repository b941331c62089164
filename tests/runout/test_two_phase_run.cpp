// The two-phase model as a method of the run loop (run/methods/two_phase.hpp):
// without fluid, a scenario run gives fv2d's run of the same granular mass;
// the bundled debris flow keeps each phase's volume; rain and infiltration
// from rasters add and take what their rates say.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "talus/run/loop.hpp"
#include "talus/run/methods/fv2d.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/run/methods/two_phase.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::run {
namespace {

const std::string kScenarios = std::string(TALUS_SOURCE_DIR) + "/scenarios/runout/";

// An ESRI ASCII grid of 30 x 16 cells of 2 m with value(i, j) (j = 0 the
// northern row), in the test's temporary folder.
template <class F>
std::string write_grid(const std::string& name, F value) {
  const std::string path = testing::TempDir() + "talus_two_phase_" + name + ".asc";
  std::ofstream out(path);
  out << "ncols 30\nnrows 16\nxllcorner 0\nyllcorner 0\ncellsize 2\nNODATA_value -9999\n";
  for (int j = 0; j < 16; ++j) {
    for (int i = 0; i < 30; ++i) out << value(i, j) << ' ';
    out << '\n';
  }
  return path;
}

// A plane falling along x at 1 in 2 (26.6 deg; whole metres per cell, so
// that the file holds it exactly: no curvature, where fv2d's centripetal term
// is zero as the two-phase model's) and a 3 m box released on it.
struct Plane {
  std::string terrain = write_grid("plane", [](int i, int) { return 30 - i; });
  std::string release = write_grid(
      "box", [](int i, int j) { return i >= 3 && i < 9 && j >= 5 && j < 11 ? 3.0 : 0.0; });
};

// A fresh run through the run loop to its end, writing no files.
void run_to_end(Simulation& sim) {
  RunLoop loop(sim, {});
  loop.start(true);
  loop.run();
}

runout::RunoutScenario parse(const std::string& text) {
  return io::parse_runout_scenario(io::load_scenario_text(text, testing::TempDir() + "s.toml"));
}

std::string common(const Plane& p, const std::string& model) {
  return "method = \"runout\"\n[run]\nmodel = \"" + model +
         "\"\nduration = 4.0\n[terrain]\nfile = \"" + p.terrain + "\"\nboundary = \"open\"\n";
}

TEST(TwoPhaseRun, WithoutFluidTheMethodRunsFv2dsGranularModel) {
  const Plane plane;
  const auto fv2d = parse(common(plane, "fv2d") +
                          "[material]\ndensity = 2000\ninternal_friction = 35\nbasal_friction = "
                          "20\n[release]\ntype = \"raster\"\nfile = \"" +
                          plane.release + "\"\n");
  // Fluid of density 0 and none released: gamma = 0, no drag, no buoyancy.
  const auto two = parse(common(plane, "two_phase") +
                         "[solid]\ndensity = 2000\ninternal_friction = 35\nbasal_friction = 20\n"
                         "grain_diameter = 0.001\n[fluid]\ndensity = 0\nmanning = 0.05\n"
                         "[release]\ntype = \"raster\"\nfile = \"" +
                         plane.release + "\"\nsolid_fraction = 1\n");
  Fv2dSimulation a(fv2d);
  TwoPhaseSimulation b(two);
  run_to_end(a), run_to_end(b);
  EXPECT_EQ(a.steps(), b.steps());
  const auto& h = a.solver().state().h;
  const auto& hs = b.solver().state().hs;
  double worst = 0.0, moved = 0.0;
  for (std::size_t c = 0; c < h.size(); ++c) {
    worst = std::max(worst, std::abs(h[c] - hs[c]));
    const bool box = c % 30 >= 3 && c % 30 < 9 && c / 30 >= 5 && c / 30 < 11;
    moved = std::max(moved, std::abs(h[c] - (box ? 3.0 : 0.0)));
  }
  // The solvers agree to 2.8e-16 m at the solver level (test_two_phase_limits:
  // WithoutFluidEachOrderIsFv2ds); through the scenario and the run loop the
  // same steps must give the same depths, to round-off of the 3 m column.
  std::printf("largest depth difference to fv2d through the run loop: %.2e m\n", worst);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(moved, 0.5);  // the box slid (0.5 > tan 20 deg): not a vacuous match
  EXPECT_EQ(a.report().metrics["max_height_m"], b.report().metrics["max_height_m"]);
  EXPECT_NEAR(a.report().metrics["max_speed_m_s"].get<double>(),
              b.report().metrics["max_solid_speed_m_s"].get<double>(), 1e-12);
}

// The bundled avalanche terrain (a slope easing into a valley: curved bed,
// a barrier, open edges), frictional: the solid's centripetal load is fv2d's.
TEST(TwoPhaseRun, WithoutFluidOnCurvedTerrainTheMethodRunsFv2ds) {
  std::ifstream in(kScenarios + "runout_terrain_2d.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string base = text.str();
  const auto cut = [&](const std::string& from, const std::string& to) {
    const auto a = base.find(from), b = base.find(to, a);
    EXPECT_NE(a, std::string::npos);
    EXPECT_NE(b, std::string::npos);
    return base.substr(0, a) + "%s" + base.substr(b);
  };
  base = cut("[material]", "[earth_pressure]");
  base.replace(base.find("stop_momentum_fraction = 0.01"), 29, "");
  base.replace(base.find("duration = 150.0"), 16, "duration = 20.0");
  const auto with = [&](const std::string& model, const std::string& tables) {
    std::string t = base;
    t.replace(t.find("%s"), 2, tables);
    t.replace(t.find("model = \"fv2d\""), 14, "model = \"" + model + "\"");
    if (model == "two_phase")
      t.replace(t.find("release.asc\""), 12, "release.asc\"\nsolid_fraction = 1");
    return io::parse_runout_scenario(io::load_scenario_text(t, kScenarios + "curved.toml"));
  };
  const auto fv2d =
      with("fv2d", "[material]\ndensity = 2000\ninternal_friction = 35\nbasal_friction = 25\n");
  auto two = with("two_phase",
                  "[solid]\ndensity = 2000\ninternal_friction = 35\nbasal_friction = 25\n"
                  "grain_diameter = 0.001\n[fluid]\ndensity = 0\nmanning = 0.05\n");
  Fv2dSimulation a(fv2d);
  TwoPhaseSimulation b(two);
  run_to_end(a), run_to_end(b);
  const auto& h = a.solver().state().h;
  const auto& hs = b.solver().state().hs;
  double worst = 0.0;
  for (std::size_t c = 0; c < h.size(); ++c) worst = std::max(worst, std::abs(h[c] - hs[c]));
  std::printf("curved terrain: largest depth difference to fv2d %.2e m (peak speed %.3g m/s)\n",
              worst, a.maxima().peak_speed);
  EXPECT_EQ(a.steps(), b.steps());
  // The same terms in another order of operations: round-off (measured 5.6e-15 m).
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(a.maxima().peak_speed, 5.0);  // it ran down the curved slope
  // Without the term the two differ: the check is not vacuous.
  two.two_phase.params.curvature = false;
  TwoPhaseSimulation c(two);
  run_to_end(c);
  double apart = 0.0;
  for (std::size_t k = 0; k < h.size(); ++k)
    apart = std::max(apart, std::abs(h[k] - c.solver().state().hs[k]));
  std::printf("curved terrain without the centripetal term: %.2e m\n", apart);
  EXPECT_GT(apart, 1e-3);
}

TEST(TwoPhaseRun, BundledDebrisFlowKeepsEachPhasesVolume) {
  auto sc = io::parse_runout_scenario(
      io::load_scenario_file(kScenarios + "two_phase_debris_valley.toml", {}));
  sc.control.duration = 30.0;
  TwoPhaseSimulation sim(sc);
  run_to_end(sim);
  const auto m = sim.report().metrics;
  // Mass of each phase exact up to summation round-off (fluxes cancel pairwise).
  EXPECT_LT(m["solid_volume_error_relative"].get<double>(), 1e-12) << m.dump();
  EXPECT_LT(m["fluid_volume_error_relative"].get<double>(), 1e-12) << m.dump();
  EXPECT_NEAR(m["released_solid_volume_m3"].get<double>(), 2750.0, 1e-9);
  // It flowed: down 22 deg at more than a few m/s, over more than its release.
  EXPECT_GT(m["max_solid_speed_m_s"].get<double>(), 5.0);
  EXPECT_GT(m["affected_area_m2"].get<double>(), 3 * 2000.0);
  // Every per-cell maximum at least the value at the end.
  const auto& st = sim.solver().state();
  const auto& mx = sim.maxima();
  for (std::size_t c = 0; c < st.hs.size(); ++c) {
    ASSERT_GE(mx.solid_height[c], sim.solver().normal_height(c, runout::Phase::Solid));
    ASSERT_GE(mx.fluid_speed[c], sim.solver().speed(c, runout::Phase::Fluid));
  }
}

TEST(TwoPhaseRun, RainAndInfiltrationRastersAddAndTakeTheirRates) {
  const Plane plane;
  // 36 mm/h (1e-5 m/s) on the northern half, none on the southern; 3.6 mm/h
  // infiltration everywhere (less than the rain: the north never dries).
  const std::string rain = write_grid("rain", [](int, int j) { return j < 8 ? 36.0 : 0.0; });
  auto sc = parse(common(plane, "two_phase") +
                  "[solid]\ndensity = 2600\ninternal_friction = 35\nbasal_friction = 30\n"
                  "grain_diameter = 0.001\n[fluid]\ndensity = 1000\nmanning = 0.05\n"
                  "[hydrology]\nrainfall_file = \"" +
                  rain + "\"\ninfiltration = 3.6\n[release]\ntype = \"raster\"\nfile = \"" +
                  plane.release + "\"\nsolid_fraction = 0.6\n");
  sc.control.duration = 2.0;
  TwoPhaseSimulation sim(sc);
  run_to_end(sim);
  const auto m = sim.report().metrics;
  // 30 x 8 cells of 4 m^2 at 1e-5 m/s for 2 s.
  EXPECT_NEAR(m["rained_volume_m3"].get<double>(), 240 * 4.0 * 1e-5 * 2.0, 1e-15);
  EXPECT_GT(m["infiltrated_volume_m3"].get<double>(), 0.0);
  EXPECT_LT(m["fluid_volume_error_relative"].get<double>(), 1e-12) << m.dump();
  EXPECT_FALSE(sim.stopped());  // rain: never at rest
}

}  // namespace
}  // namespace talus::run
