// StepperBase::pair_contact_forces: the contact law evaluated on the current
// state without changing it; checked against the Hertz force of a resting
// pair and the Coulomb limit of a sliding one.
#include <gtest/gtest.h>

#include <cmath>

#include "talus/analysis/force_network.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "verification_cases.hpp"

using namespace talus;
using namespace talus::dem;
using namespace talus::dem::verification;

namespace {

constexpr double kR = 0.002, kE = 1e8, kNu = 0.245, kRho = 2000, kMu = 0.3;

// Two 2 mm spheres along x, overlapping by `overlap`, the second moving at
// `slide` along y; no gravity, restitution 1 (no normal damping).
std::unique_ptr<DemRun<3>> pair_run(double overlap, double slide) {
  DemScenario sc = scenario(3, HertzMindlin::name, 1e-7, Vec3::Zero());
  sc.materials.push_back(hertz_material("grain", kRho, kE, kNu, 1.0, kMu));
  const double half = kR - 0.5 * overlap;
  add_balls(sc, {ball(-half * Vec3::UnitX(), Vec3::Zero(), kR, "grain"),
                 ball(half * Vec3::UnitX(), slide * Vec3::UnitY(), kR, "grain")});
  auto run = build_dem<3>(sc, {});
  run->stepper->prime();
  return run;
}

TEST(PairContactForces, RestingPairHasTheHertzForceAndNoShear) {
  const double overlap = 2e-5;
  auto run = pair_run(overlap, 0.0);
  const auto forces = run->stepper->pair_contact_forces();
  ASSERT_EQ(forces.size(), 1u);
  // Hertz: f_n = (4/3) E* sqrt(R* d) d with E* = E / (2 (1 - nu^2)), R* = R / 2.
  const double e_star = kE / (2 * (1 - kNu * kNu));
  const double hertz = 4.0 / 3.0 * e_star * std::sqrt(0.5 * kR * overlap) * overlap;
  EXPECT_NEAR(forces[0].normal, hertz, 1e-9 * hertz);
  EXPECT_EQ(forces[0].tangential, 0.0);
  EXPECT_DOUBLE_EQ(forces[0].friction, kMu);
  // The same as the force the step loop applied, and asking again changes nothing.
  EXPECT_NEAR(run->system.particles.f[0].norm(), hertz, 1e-9 * hertz);
  const auto again = run->stepper->pair_contact_forces();
  EXPECT_EQ(again[0].normal, forces[0].normal);
}

TEST(PairContactForces, SlidingPairSitsOnTheCoulombLimit) {
  // 1 m/s of slip: the Mindlin spring (8 G* sqrt(R* d), about 1.4e4 N/m here)
  // reaches mu f_n (about 0.1 N) after some 7 um of slip, 70 steps.
  auto run = pair_run(2e-5, 1.0);
  run->stepper->advance(200);
  const auto forces = run->stepper->pair_contact_forces();
  ASSERT_EQ(forces.size(), 1u);
  ASSERT_GT(forces[0].normal, 0.0);
  // Sliding, the law caps the spring at mu |f_n| of this very evaluation (dt = 0 adds no
  // slip), so only rounding separates them.
  EXPECT_NEAR(forces[0].tangential, kMu * forces[0].normal, 1e-6 * forces[0].normal);
  const auto shear_before = run->system.neighbours.pair_shear;
  const auto net = analysis::force_network(forces);
  EXPECT_EQ(net.contacts, 1u);
  EXPECT_DOUBLE_EQ(net.coulomb_fraction, 1.0);
  EXPECT_NEAR(net.mean_force, forces[0].normal * std::sqrt(1 + kMu * kMu), 1e-6 * net.mean_force);
  // The evaluation left the history alone.
  EXPECT_EQ(run->system.neighbours.pair_shear, shear_before);
}

TEST(PairContactForces, ApartPairHasNone) {
  auto run = pair_run(-1e-5, 0.0);  // a 10 um gap
  EXPECT_TRUE(run->stepper->pair_contact_forces().empty());
}

}  // namespace
