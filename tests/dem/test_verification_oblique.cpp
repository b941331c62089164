// Oblique impact of an alumina sphere on a flat wall of the same material,
// Chung & Ooi (2011) case 4 in spec/dem.md: R 2.5 mm, E 3.8e11 Pa, nu 0.23,
// 3.9 m/s at 5-85 degrees from the normal, mu 0.092, e 0.98.
//
// Rigid-body impulse theory with inertia I = k m R^2 (k = 2/5 spheres, 1/2
// disks): the contact point stops slipping during the impact unless
// tan(theta) > mu (1 + e) (1 + 1/k) (32.5 deg for spheres, 28.6 deg for disks).
// Above it (gross sliding) the friction impulse is mu (1 + e) m v_n, so
//   omega = mu (1 + e) v_n / (k R),   v_t' / v_t = 1 - mu (1 + e) / tan(theta);
// below it the sphere leaves rolling with v_t' / v_t = 1 / (1 + k) (5/7, 2/3).
// Mindlin's tangential compliance makes the small angles deviate from 1/(1+k):
// the tangential spring stores energy and gives it back with a delay, so the
// contact point may even reverse (Maw, Barber & Fawcett 1976); that curve is
// printed and asserted only loosely.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "verification_cases.hpp"

using namespace talus;
using namespace talus::dem;
using namespace talus::dem::verification;

namespace {

constexpr double kR = 2.5e-3, kE = 3.8e11, kNu = 0.23, kSpeed = 3.9, kMu = 0.092, kE_n = 0.98;
// Chung & Ooi's alumina density; it scales time only, not the velocity ratios.
constexpr double kRho = 4000.0;

struct Rebound {
  double normal_restitution;  // -v_n' / v_n
  double tangential_ratio;    // v_t' / v_t of the centre
  double spin;                // |omega'| R / v_n, dimensionless
  double energy_ratio;        // (translational + rotational) kinetic energy after / before
  double overlap_ratio;       // peak overlap / R
};

template <int D>
Rebound oblique_impact(double theta_deg) {
  const double th = deg2rad(theta_deg);
  const double vn = kSpeed * std::cos(th), vt = kSpeed * std::sin(th);
  const double m = kRho * Space<D>::volume(kR);
  // Contact time of the normal Hertz impact (spec formula); 1500 steps per contact.
  const double e_star = kE / (2 * (1 - kNu * kNu));
  const double t_c = 2.87 * std::pow(m * m / (kR * e_star * e_star * vn), 0.2);
  DemScenario sc = scenario(D, HertzMindlin::name, t_c / 1500, Vec3::Zero());
  sc.materials.push_back(hertz_material("alumina", kRho, kE, kNu, kE_n, kMu));
  sc.walls.push_back(floor_wall<D>("alumina"));
  add_balls(sc, {ball((kR + 1e-7) * up<D>(), vt * Vec3::UnitX() - vn * up<D>(), kR, "alumina")});
  auto run = build<D>(sc);
  const Impact<D> imp = measure_impact(*run, 0, floor_overlap<D>(0), 100000);
  EXPECT_TRUE(imp.finished) << theta_deg;
  const double inertia = Space<D>::inertia_factor() * m * kR * kR;
  const double w2 = Space<D>::rot_dot(imp.w_out, imp.w_out);
  return {imp.v_out[kUp<D>] / vn, imp.v_out.x() / vt, std::sqrt(w2) * kR / vn,
          (0.5 * m * imp.v_out.squaredNorm() + 0.5 * inertia * w2) / (0.5 * m * kSpeed * kSpeed),
          imp.max_overlap / kR};
}

template <class Dim>
class ObliqueImpact : public ::testing::Test {};
using Dims = ::testing::Types<Dim2, Dim3>;
TYPED_TEST_SUITE(ObliqueImpact, Dims);

TYPED_TEST(ObliqueImpact, ChungOoiCase4AluminaOnPlane) {
  constexpr int D = TypeParam::value;
  const double k = Space<D>::inertia_factor();
  const double rolling_ratio = 1 / (1 + k);
  const double theta_c = rad2deg(std::atan(kMu * (1 + kE_n) * (1 + 1 / k)));
  if (D == 3) {
    EXPECT_NEAR(theta_c, 32.5, 0.05);  // the spec's value
  }
  for (int deg = 5; deg <= 85; deg += 5) {
    const Rebound r = oblique_impact<D>(deg);
    const double sliding_ratio = 1 - kMu * (1 + kE_n) / std::tan(deg2rad(deg));
    const double sliding_spin = kMu * (1 + kE_n) / k;
    std::printf(
        "[verif] case4 D=%d theta %2d e_n %.5f v_t'/v_t %.5f (sliding %.5f, rolling %.5f) "
        "omega R/v_n %.5f (sliding %.5f) energy %.5f overlap/R %.2e\n",
        D, deg, r.normal_restitution, r.tangential_ratio, sliding_ratio, rolling_ratio, r.spin,
        sliding_spin, r.energy_ratio, r.overlap_ratio);
    // Any angle: friction changes neither the normal restitution (1e-3: the
    // Hertz restitution test's time-step bound) nor creates energy, and the
    // friction impulse is at most mu times the normal one (Coulomb).
    EXPECT_NEAR(r.normal_restitution, kE_n, 1e-3) << deg;
    EXPECT_LE(r.energy_ratio, 1.0) << deg;
    EXPECT_GE(r.tangential_ratio, sliding_ratio - 2e-4) << deg;
    EXPECT_LE(r.spin, sliding_spin * (1 + 1e-4)) << deg;
    if (deg > theta_c) {
      // Gross sliding: the impulse relations above. The measured ratio agrees to
      // ~4e-5; 2e-4 leaves room for the time step (t_c / 1500). The spin is
      // smaller by the lever arm R - xi/2 of the contact point (stepper.cpp)
      // instead of R: at most xi_max / (2R) relative (0.2 % for spheres; 2 % for
      // disks, which weigh rho pi R^2 per metre of depth and overlap ten times more).
      EXPECT_NEAR(r.tangential_ratio, sliding_ratio, 2e-4) << deg;
      EXPECT_GE(r.spin, sliding_spin * (1 - 0.5 * r.overlap_ratio) - 1e-4) << deg;
    } else {
      // Below theta_c rigid bodies would leave rolling at 1/(1+k). Mindlin's
      // tangential spring (stiffness ratio k_t/k_n = 2(1-nu)/(2-nu), tangential
      // frequency sqrt(k_t/k_n (1 + 1/k)) ~ 1.7 times the normal one) stores
      // tangential energy and returns part of it before separation, so the
      // ratio deviates from 1/(1+k) by up to ~0.24 here (most at 5 degrees,
      // where the contact point leaves still slipping forward). Loose band:
      EXPECT_LE(r.tangential_ratio, 1.0) << deg;
      EXPECT_NEAR(r.tangential_ratio, rolling_ratio, 0.25) << deg;
    }
  }
}

}  // namespace
