// Energy conservation for elastic contacts without damping and free fall
// (spec/dem.md "Verification cases"). What is asserted:
//  - free fall: velocity Verlet is exact for a constant force, so x(t) =
//    x0 + v0 t + g t^2 / 2 and v(t) = v0 + g t up to round-off;
//  - a ball bouncing elastically (Hertz, e = 1) on a floor: its energy between
//    contacts (kinetic + potential, no elastic part) stays within 1e-3 of the
//    start over 10 bounces;
//  - frictionless elastic particles (e = 1, beta = 0, mu = 0, so nothing
//    dissipates) bouncing in a closed box under gravity: the total energy,
//    kinetic + potential + elastic (computed here from the overlaps), stays
//    within the stated bound at every sample.
// Friction is left out on purpose: the Coulomb slider dissipates even at e = 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/system.hpp"
#include "verification_cases.hpp"

using namespace talus;
using namespace talus::dem;
using namespace talus::dem::verification;

namespace {

constexpr double kG = 9.81;

template <class Dim>
class Energy : public ::testing::Test {};
using Dims = ::testing::Types<Dim2, Dim3>;
TYPED_TEST_SUITE(Energy, Dims);

TYPED_TEST(Energy, FreeFallIsExactToRoundOff) {
  constexpr int D = TypeParam::value;
  const Vec3 g(0.3, -kG, D == 3 ? -2.0 : 0.0);  // any constant acceleration
  const Vec3 x0(0.1, 2.0, D == 3 ? -0.5 : 0.0), v0(0.7, 1.5, D == 3 ? 0.4 : 0.0);
  const double dt = 1e-5;  // below the critical step of the (unused) contact law
  DemScenario sc = scenario(D, HertzMindlin::name, dt, g);
  sc.materials.push_back(hertz_material("grain", 2500, 1e7, 0.3, 0.5, 0.5));
  add_balls(sc, {ball(x0, v0, 1e-3, "grain")});
  auto run = build<D>(sc);
  run->stepper->prime();
  const auto& p = run->system.particles;
  double worst_x = 0.0, worst_v = 0.0;
  for (int n = 1; n <= 50000; ++n) {
    run->stepper->advance(1);
    const double t = n * dt;
    const Vec3 x = x0 + v0 * t + 0.5 * g * t * t, v = v0 + g * t;
    worst_x = std::max(worst_x, (Space<D>::to3(p.x[0]) - x).norm());
    worst_v = std::max(worst_v, (Space<D>::to3(p.v[0]) - v).norm());
  }
  std::printf("[verif] case11 D=%d 1 s in 1e5 steps: max |x error| %.2e m, |v error| %.2e m/s\n", D,
              worst_x, worst_v);
  // Round-off: 1e5 steps adding dt v with relative error ~1e-16 each to
  // |x| <~ 5 m gives ~6e-11 m at most; velocities <~ 10 m/s likewise.
  EXPECT_LT(worst_x, 1e-10);
  EXPECT_LT(worst_v, 1e-10);
}

// A 5 mm ball dropped from 5 cm (above contact) on a rigid floor, 10 bounces.
TYPED_TEST(Energy, ElasticBouncingBallKeepsItsEnergy) {
  constexpr int D = TypeParam::value;
  const double R = 5e-3, h0 = 0.05, E = 1e8, nu = 0.3;
  const double m = 2650 * Space<D>::volume(R);
  const double v_hit = std::sqrt(2 * kG * h0);
  const double t_c = 2.87 * std::pow(m * m / (R * std::pow(E / (1 - nu * nu), 2) * v_hit), 0.2);
  DemScenario sc = scenario(D, HertzMindlin::name, t_c / 100, -kG * up<D>());
  sc.materials.push_back(hertz_material("grain", 2650, E, nu, 1.0, 0.0));
  sc.materials.push_back(rigid_material("rigid"));
  sc.walls.push_back(floor_wall<D>("rigid"));
  add_balls(sc, {ball((R + h0) * up<D>(), Vec3::Zero(), R, "grain")});
  auto run = build<D>(sc);
  run->stepper->prime();
  const auto& p = run->system.particles;
  auto energy = [&] { return 0.5 * m * p.v[0].squaredNorm() + m * kG * (p.x[0][kUp<D>] - R); };
  const double e0 = energy();
  double worst = 0.0;
  int bounces = 0;
  bool touching = false;
  while (bounces < 10) {
    run->stepper->advance(1);
    const bool now = p.wall_contacts[0] > 0;
    if (touching && !now) ++bounces;
    touching = now;
    if (!now) worst = std::max(worst, std::abs(energy() - e0));
    ASSERT_LT(run->system.time, 10.0);
  }
  std::printf("[verif] case9 D=%d bouncing ball: 10 bounces in %.3f s, max |dE|/E %.2e\n", D,
              run->system.time, worst / e0);
  EXPECT_LT(worst / e0, 1e-3);
  // Time-step bound: velocity Verlet's energy error through one contact is
  // O((dt / t_c)^2) = 1e-4 and does not accumulate for a symplectic scheme.
  EXPECT_LT(worst / e0, 1e-4);
}

// Elastic energy of a contact of overlap xi: Hertz (8/15) E* sqrt(R*) xi^(5/2);
// linear k xi^2 / 2.
struct ElasticLaw {
  bool hertz;
  double pair, wall;  // E* sqrt-free constants: E* (Hertz) or k (linear) of pair / wall contacts
  double energy(double k_or_e, double r_eff, double xi) const {
    if (xi <= 0.0) return 0.0;
    return hertz ? 8.0 / 15.0 * k_or_e * std::sqrt(r_eff) * std::pow(xi, 2.5)
                 : 0.5 * k_or_e * xi * xi;
  }
};

// Kinetic + rotational + potential (above the floor at 0) + elastic energy of
// particles in the box [0, L]^D.
template <int D>
double total_energy(const DemSystem<D>& s, const ElasticLaw& law, double L) {
  const auto& p = s.particles;
  double e = kinetic_energy(p) + rotational_energy(p);
  for (std::size_t i = 0; i < p.size(); ++i) {
    e += p.m[i] * kG * p.x[i][kUp<D>];
    for (int d = 0; d < D; ++d) {
      e += law.energy(law.wall, p.r[i], p.r[i] - p.x[i][d]);
      e += law.energy(law.wall, p.r[i], p.r[i] - (L - p.x[i][d]));
    }
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double xi = p.r[i] + p.r[j] - (p.x[i] - p.x[j]).norm();
      e += law.energy(law.pair, p.r[i] * p.r[j] / (p.r[i] + p.r[j]), xi);
    }
  }
  return e;
}

// 27 (3D) or 25 (2D) particles of slightly different sizes on a lattice with
// deterministic pseudo-random velocities up to ~0.5 m/s, in a closed box of
// side 2 cm, for 0.3 s (hundreds of collisions).
template <int D>
void elastic_box(std::string_view model, double tolerance) {
  const double L = 0.02, r0 = 1.5e-3;
  const bool hertz = model == HertzMindlin::name;
  const int per_side = D == 3 ? 3 : 5;
  DemScenario sc = scenario(D, model, 0.0, -kG * up<D>());
  // Disks weigh rho pi r^2 per metre of depth, 500 times a sphere: stiffer
  // contacts keep the peak overlaps at a few percent of r in both.
  const double E = D == 3 ? 1e7 : 1e9, nu = 0.3, k = D == 3 ? 2e3 : 1e6;
  MaterialParams grain = hertz ? hertz_material("grain", 2500, E, nu, 1.0, 0.0)
                               : linear_material("grain", 2500, k, k, 0.0, 0.0);
  sc.materials.push_back(grain);
  sc.materials.push_back(rigid_material("rigid"));
  add_box<D>(sc, Vec3::Zero(), Vec3::Constant(L), "rigid", "rigid", true);
  std::vector<ParticleSpec> balls;
  int n = 0;
  for (int a = 0; a < per_side; ++a)
    for (int b = 0; b < per_side; ++b)
      for (int c = 0; c < (D == 3 ? per_side : 1); ++c, ++n) {
        const double spacing = L / per_side;
        Vec3 x((a + 0.5) * spacing, (b + 0.5) * spacing, D == 3 ? (c + 0.5) * spacing : 0.0);
        Vec3 v(std::sin(1.7 * n + 0.3), std::sin(2.3 * n + 1.1), D == 3 ? std::sin(3.1 * n) : 0.0);
        balls.push_back(ball(x, 0.5 * v, r0 * (1.0 + 0.1 * std::sin(5.3 * n)), "grain"));
      }
  add_balls(sc, balls);
  // Elastic constants as the contact laws combine them (pair_coefficients.hpp):
  // Hertz E* = E / (2 (1 - nu^2)) between grains, E / (1 - nu^2) at a rigid
  // wall; linear springs in series k/2 between grains, k at a rigid wall.
  const ElasticLaw law{hertz, hertz ? E / (2 * (1 - nu * nu)) : k / 2,
                       hertz ? E / (1 - nu * nu) : k};
  // The automatic step (0.8 of the critical one) is too coarse for a tight
  // energy bound; a twentieth of it keeps the Verlet error small.
  const double dt = 0.05 * build_dem<D>(sc, {})->system.dt;
  sc.run.time_step = dt;
  auto run = build<D>(sc);
  run->stepper->prime();
  const double e0 = total_energy(run->system, law, L);
  double worst = 0.0;
  int64_t pair_steps = 0, wall_steps = 0;
  const int64_t steps = std::llround(0.3 / dt);
  for (int64_t s = 0; s < steps; ++s) {
    run->stepper->advance(1);
    pair_steps += run->system.pair_contacts;
    wall_steps += run->system.wall_contacts;
    if (s % 20 == 0) worst = std::max(worst, std::abs(total_energy(run->system, law, L) - e0));
  }
  const double e1 = total_energy(run->system, law, L);
  std::printf(
      "[verif] case9 D=%d %s box: %lld steps, contact-steps pair %lld wall %lld, "
      "max |dE|/E %.2e, end drift %.2e\n",
      D, hertz ? "hertz" : "linear", static_cast<long long>(steps),
      static_cast<long long>(pair_steps), static_cast<long long>(wall_steps), worst / e0,
      (e1 - e0) / e0);
  // Many collisions of both kinds happened (a contact lasts tens of steps).
  EXPECT_GT(pair_steps, 2000);
  EXPECT_GT(wall_steps, 2000);
  EXPECT_LT(worst / e0, tolerance);
}

// Bounds, from the time step: velocity Verlet's energy error is O((omega dt)^2)
// per contact and does not drift (halving dt cut the linear error 4.6 times).
// Measured at dt = 0.04 of the critical step: Hertz max |dE|/E 2.4e-5 (2D),
// 7e-6 (3D); linear 1.9e-4 (2D), 1.1e-4 (3D), larger because the linear force
// has a kink at first touch where the Hertz one is smooth.
TYPED_TEST(Energy, FrictionlessElasticHertzBoxConservesEnergy) {
  elastic_box<TypeParam::value>(HertzMindlin::name, 1e-4);
}

TYPED_TEST(Energy, FrictionlessElasticLinearBoxConservesEnergy) {
  elastic_box<TypeParam::value>(LinearSpringDashpot::name, 1e-3);
}

}  // namespace
