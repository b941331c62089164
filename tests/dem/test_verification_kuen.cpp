// Kuen's rolling resistance (Kuen 2011 §2.3.5.4 and eq. 2.75; spec/dem.md
// "Rolling resistance"): at walls |omega| drops every step by
// g c_rr / (r (r_rr - 2/5 r)) dt without changing sign; a particle touching
// another particle has omega multiplied by mu_Br (0.5) every step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/kuen_rolling.hpp"
#include "verification_cases.hpp"

using namespace talus;
using namespace talus::dem;
using namespace talus::dem::verification;

namespace {

constexpr double kG = 9.81;
constexpr double kDepth = 0.15e-3;  // Kuen's u_rr

// The spec's check values (rounded to 1 rad/s^2).
TEST(KuenRolling, WallDecelerationMatchesSpecValues) {
  EXPECT_NEAR(kuen_wall_deceleration(kG, 1.0e-3, kDepth), 11484, 0.5);
  EXPECT_NEAR(kuen_wall_deceleration(kG, 1.5e-3, kDepth), 5701, 0.5);
  EXPECT_NEAR(kuen_wall_deceleration(kG, 2.0e-3, kDepth), 3550, 0.5);
}

template <class Dim>
class KuenRun : public ::testing::Test {};
using Dims = ::testing::Types<Dim2, Dim3>;
TYPED_TEST_SUITE(KuenRun, Dims);

// Kuen's linear contacts; friction 0 so that no contact torque competes with
// the rolling resistance.
DemScenario kuen_scenario(int dim, double dt, const Vec3& gravity, double reference_step = 0.0) {
  DemScenario sc = scenario(dim, LinearSpringDashpot::name, dt, gravity);
  sc.contact.rolling = RollingModel::Kuen;
  sc.contact.kuen_wall_depth = kDepth;
  sc.contact.kuen_particle_factor = 0.5;
  sc.contact.kuen_reference_step = reference_step;
  sc.materials.push_back(linear_material("sand", 2650, 1e8, 1e8, 0.5, 0.0));
  sc.materials.push_back(rigid_material("rigid"));
  return sc;
}

// A spinning particle (r 1.5 mm) resting on the floor: |omega| falls linearly
// at 5701 rad/s^2, reaches exactly zero and stays there.
TYPED_TEST(KuenRun, SpinningParticleOnWallDeceleratesAtKuenRate) {
  constexpr int D = TypeParam::value;
  const double r = 1.5e-3, w0 = 8.0;
  DemScenario sc = kuen_scenario(D, 0.0, -kG * up<D>());
  sc.walls.push_back(floor_wall<D>("rigid"));
  const double m = 2650 * Space<D>::volume(r);
  const double xi = m * kG / 1e8;  // resting overlap of the linear spring
  // Spin about an axis in the wall plane (3D: oblique, to check the direction is kept).
  const Vec3 axis = D == 2 ? Vec3(Vec3::UnitZ()) : Vec3(1, 1, 0).normalized();
  add_balls(sc, {ball((r - xi) * up<D>(), Vec3::Zero(), r, "sand", -w0 * axis)});
  auto run = build_dem<D>(sc, {});
  run->stepper->prime();
  const auto& p = run->system.particles;
  const double dt = run->system.dt;
  const double rate = kuen_wall_deceleration(kG, r, kDepth);
  if (D == 2) {
    EXPECT_NEAR(rate, 5701, 0.5);
  }
  const int64_t stop_steps = static_cast<int64_t>(std::ceil(w0 / (rate * dt)));
  double worst = 0.0;
  for (int64_t n = 1; n <= stop_steps + 100; ++n) {
    run->stepper->advance(1);
    const Vec3 w = Space<D>::rot_to3(p.w[0]);
    const double expected = std::max(0.0, w0 - n * rate * dt);
    // Sign never flips: omega stays along -axis (or is zero).
    ASSERT_GE(-w.dot(axis), 0.0) << n;
    ASSERT_NEAR((w + w.dot(-axis) * axis).norm(), 0.0, 1e-12) << n;
    worst = std::max(worst, std::abs(w.norm() - expected));
  }
  std::printf(
      "[verif] case8 D=%d rate %.1f rad/s^2 dt %.3e stop after %lld steps, max |omega error| "
      "%.2e\n",
      D, rate, dt, static_cast<long long>(stop_steps), worst);
  // Exact per step up to round-off (no contact torque, friction 0).
  EXPECT_LT(worst, 1e-12 * w0);
  EXPECT_EQ(Space<D>::rot_norm(p.w[0]), 0.0);
  EXPECT_GT(p.wall_contacts[0], 0);
}

// mu_Br: two touching particles lose half their spin every step; a third one,
// touching nothing, keeps its spin. No gravity and no walls.
// With a reference step t_ref (kuen_reference_step) the factor per step is
// mu_Br^(dt / t_ref): here t_ref = 2 dt, so the spin halves every second step.
template <int D>
void particle_contact_decays_spin(double steps_per_halving) {
  const double r = 1.5e-3;
  const double m = 2650 * Space<D>::volume(r);
  // A step far below sqrt(m/k) keeps the slightly overlapping pair together for
  // hundreds of steps while they push apart.
  const double dt = 0.01 * std::sqrt(m / 2 / 1e8);
  DemScenario sc =
      kuen_scenario(D, dt, Vec3::Zero(), steps_per_halving == 1.0 ? 0.0 : steps_per_halving * dt);
  const Vec3 spin = D == 2 ? Vec3(Vec3::UnitZ()) : Vec3(Vec3::UnitY());
  add_balls(sc, {ball(Vec3::Zero(), Vec3::Zero(), r, "sand", 4.0 * spin),
                 ball(Vec3(2 * r - 1e-6, 0, 0), Vec3::Zero(), r, "sand", -6.0 * spin),
                 ball(Vec3(0.1, 0, 0), Vec3::Zero(), r, "sand", 5.0 * spin)});
  auto run = build_dem<D>(sc, {});
  run->stepper->prime();
  const auto& p = run->system.particles;
  for (int n = 1; n <= 6; ++n) {
    run->stepper->advance(1);
    const double factor = std::pow(0.5, n / steps_per_halving);
    EXPECT_NEAR(Space<D>::rot_to3(p.w[index_of(p, 0)]).dot(spin), 4.0 * factor, 1e-12) << n;
    EXPECT_NEAR(Space<D>::rot_to3(p.w[index_of(p, 1)]).dot(spin), -6.0 * factor, 1e-12) << n;
    EXPECT_EQ(Space<D>::rot_to3(p.w[index_of(p, 2)]).dot(spin), 5.0) << n;
  }
}

TYPED_TEST(KuenRun, ParticleContactHalvesSpinEveryStep) {
  particle_contact_decays_spin<TypeParam::value>(1.0);
}

TYPED_TEST(KuenRun, ReferenceStepKeepsTheDecayPerUnitTime) {
  particle_contact_decays_spin<TypeParam::value>(2.0);
}

}  // namespace
