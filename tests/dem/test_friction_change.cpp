// A friction change during a run (dem/friction_change.hpp; the granular
// beam's μ_init -> μ_p of Götz 2024 §5.3): a block sliding down an incline
// accelerates at g (sin θ - μ cos θ) with the old μ before the change and
// with the new one after it, and the change is applied once.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/dem_loop.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "verification_cases.hpp"

namespace talus::dem {
namespace {

using namespace verification;

constexpr double kG = 9.81;

struct SpeedLog final : run::Observer {
  explicit SpeedLog(const DemRun<3>& r) : run(r) {}
  void on_series() override {
    t.push_back(run.system.time);
    v.push_back(run.system.particles.v[0].x());
  }
  const DemRun<3>& run;
  std::vector<double> t, v;
};

TEST(FrictionChange, BlockSlidesWithTheOldThenTheNewFriction) {
  const double theta = std::atan(0.6), mu0 = 0.3, mu1 = 0.45, R = 1.5e-3;
  const Vec3 g = kG * (std::sin(theta) * Vec3::UnitX() - std::cos(theta) * Vec3::UnitZ());
  DemScenario sc = scenario(3, HertzMindlin::name, 0.0, g);
  sc.contact.lock_rotation = true;  // a block: it slides, it cannot roll
  sc.materials.push_back(hertz_material("grain", 2650, 1e8, 0.3, 0.5, mu0));
  sc.materials.push_back(rigid_material("rigid"));
  sc.walls.push_back(flat_wall<3>("floor", "rigid", Vec3::Zero(), Vec3::UnitZ(), 10.0));
  // Placed at the overlap that carries its weight: no bounce at the start.
  const auto& grain = sc.materials[0];
  const double m = grain.density * 4.0 / 3.0 * M_PI * R * R * R;
  const double e_star = grain.youngs_modulus / (1 - grain.poisson_ratio * grain.poisson_ratio);
  const double overlap =
      std::pow(3 * m * kG * std::cos(theta) / (4 * e_star * std::sqrt(R)), 2.0 / 3.0);
  add_balls(sc, {ball((R - overlap) * Vec3::UnitZ(), Vec3::Zero(), R, "grain")});
  auto run = build_dem<3>(sc, {});
  run::DemControl c;
  c.duration = 0.2;
  c.series_interval = 0.05;
  c.friction_change = FrictionChange{0.1, mu1, {0}};
  SpeedLog log(*run);
  test::run_dem<3>(*run, c, {&log});
  ASSERT_EQ(log.t.size(), 5u);  // 0, 0.05, 0.1, 0.15, 0.2 s
  EXPECT_DOUBLE_EQ(run->system.materials[0].friction, mu1);
  auto accel = [&](int a, int b) { return (log.v[b] - log.v[a]) / (log.t[b] - log.t[a]); };
  const double a0 = kG * (std::sin(theta) - mu0 * std::cos(theta));
  const double a1 = kG * (std::sin(theta) - mu1 * std::cos(theta));
  // Sliding friction is exact once the start's normal oscillation has died
  // out (within ~1 ms, test_verification_friction.cpp): 1e-3 relative.
  EXPECT_NEAR(accel(1, 2), a0, 1e-3 * a0);
  EXPECT_NEAR(accel(3, 4), a1, 1e-3 * a1);
}

}  // namespace
}  // namespace talus::dem
