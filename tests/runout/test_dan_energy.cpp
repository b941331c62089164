// DAN's divergence form of the pressure term and the energy blow-up check
// (dan.hpp; docs/validation.md "2D flume against 1D DAN").
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "talus/core/error.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/runout/builder.hpp"
#include "talus/runout/release.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::runout {
namespace {

RunoutScenario bundled(const std::string& name) {
  const std::string file = std::string(TALUS_SOURCE_DIR) + "/scenarios/runout/" + name;
  return io::parse_runout_scenario(io::load_scenario_file(file, {}));
}

// A frictionless flat with a parabolic pile whose blocks take k_a or k_p by the
// sign of their strain (Savage-Hutter switch): k jumps between neighbours.
DanModel pile_on_flat(PressureForm form) {
  const RunoutPath flat = path_from_profile({{0, 0}, {4, 0}}, {1, 1}, 0.0, 1e-3);
  DanParams p;
  p.density = 1600;
  p.rheology.tan_friction = 0.0;
  p.pressure.mode = EarthPressureMode::SavageHutter;
  p.pressure.phi_internal = 30.9 * M_PI / 180;
  p.pressure.tan_phi_basal = std::tan(21.7 * M_PI / 180);
  p.pressure.modify_basal_angle = false;
  p.smoothing.enabled = false;
  p.pressure_form = form;
  auto depth = [](double s) { return 0.1 * std::max(0.0, 1.0 - (s - 1.5) * (s - 1.5) / 0.25); };
  // Blocks of uneven length, so the strains (and k) differ from block to block.
  DanBlocks b = blocks_from_depth(flat, 1.0, 2.0, 41, depth);
  for (std::size_t i = 1; i + 1 < b.s.size(); ++i) b.s[i] += (i % 2 ? 0.004 : -0.004);
  return DanModel(flat, p, std::move(b));
}

TEST(DanEnergy, DivergenceFormConservesMomentumWithJumpsInK) {
  // Pressure forces of the divergence form act pairwise across each boundary
  // block (P_{j-1} - P_j on a path of constant width), so the momentum of a
  // frictionless pile on a flat stays zero to round-off, however k jumps.
  DanModel model = pile_on_flat(PressureForm::Divergence);
  double ke_max = 0.0;
  bool mixed = false;
  for (int k = 0; k < 400; ++k) {
    model.step(0.5 * model.stable_time_step(0.5));
    ke_max = std::max(ke_max, model.kinetic_energy());
    const auto& kk = model.blocks().k;
    for (std::size_t j = 1; j < kk.size(); ++j) mixed = mixed || kk[j] != kk[j - 1];
  }
  EXPECT_TRUE(mixed);  // k did jump between neighbours
  double scale = 0.0;
  for (std::size_t i = 0; i < model.size(); ++i)
    scale += model.node_mass(i) * std::abs(model.blocks().v[i]);
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(std::abs(model.momentum()), 1e-12 * scale);
}

TEST(DanEnergy, UnstableFlumeRunStopsWithEnergyBlowUp) {
  // The flume with the Savage-Hutter switch, no basal-angle modification and
  // eq. 2.35's gradient form at 400 blocks gains energy after ~1.5 s until the
  // deposit climbs over the barrier (docs/validation.md: regrowth of ~320 J
  // against a peak kinetic energy of 170 J without the check). The check must
  // stop it with a RunError that says so.
  RunoutScenario sc = bundled("runout_flume_A.toml");
  sc.params.pressure.mode = EarthPressureMode::SavageHutter;
  sc.params.pressure.modify_basal_angle = false;
  sc.params.pressure_form = PressureForm::Gradient;
  sc.release.blocks = 400;
  try {
    run::simulate_dan(sc);
    FAIL() << "the unstable run was not stopped";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("energy blow-up"), std::string::npos) << e.what();
  }
  // The same run in the divergence form is stable and passes the check.
  sc.params.pressure_form = PressureForm::Divergence;
  EXPECT_NO_THROW(run::simulate_dan(sc));
}

TEST(DanEnergy, BundledScenariosPassTheCheck) {
  // Healthy runs regrow by at most ~0.11 of the check's scale (measured on the
  // flume with 50-400 blocks, both forms, both laws): the bundled DAN
  // scenarios run to their end with the default tolerance.
  for (const char* name : {"runout_flume_A.toml", "runout_profile_slope.toml"}) {
    const RunoutScenario sc = bundled(name);
    ASSERT_GT(sc.params.energy_growth_tolerance, 0.0);
    EXPECT_NO_THROW(run::simulate_dan(sc)) << name;
  }
}

}  // namespace
}  // namespace talus::runout
