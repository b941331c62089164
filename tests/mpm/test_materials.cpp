// Constitutive models: the Drucker-Prager constants and return mapping of
// mpm.md (Bui et al. 2008), the Mohr-Coulomb return with corners, cohesion
// loss, and objectivity of every model under a rigid rotation.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "talus/core/space.hpp"
#include "talus/mpm/materials.hpp"

namespace talus::mpm {
namespace {

MaterialParams soil(std::string_view model, double phi_deg, double c, double psi_deg = 0.0) {
  MaterialParams p;
  p.model = model;
  p.density = 2000.0;
  p.youngs_modulus = 20e6;
  p.poisson_ratio = 0.3;
  p.friction_angle = deg2rad(phi_deg);
  p.dilatancy_angle = deg2rad(psi_deg);
  p.cohesion = c;
  return p;
}

Mat3 random_symmetric(std::mt19937& rng, double scale) {
  std::normal_distribution<double> n(0.0, scale);
  Mat3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a(i, j) = n(rng);
  return sym(a);
}

// mpm.md check values (alpha_phi = tan(phi)/sqrt(9 + 12 tan^2 phi),
// k_c = 3c/sqrt(9 + 12 tan^2 phi)), given there to 5 digits.
TEST(MpmDruckerPrager, FittedConstantsMatchSpec) {
  EXPECT_NEAR(DruckerPrager::alpha(deg2rad(28.0)), 0.15104, 1e-5);
  EXPECT_NEAR(DruckerPrager::kc(deg2rad(28.0), 26.7e3), 22.754e3, 1.0);
  EXPECT_NEAR(DruckerPrager::alpha(deg2rad(27.0)), 0.14639, 1e-5);
  EXPECT_NEAR(DruckerPrager::kc(deg2rad(27.0), 18.3e3), 15.773e3, 1.0);
}

// Random strain paths from a compressed state: after every step f <= 0 (to
// round-off), and with psi = 0 the plastic strain has no volumetric part, so
// the mean stress is exactly the elastic trial's.
TEST(MpmDruckerPrager, ReturnStaysOnConeWithoutPlasticVolumeChangeAtZeroDilatancy) {
  const auto dp = std::get<DruckerPrager>(make_material(soil(DruckerPrager::name, 28, 26.7e3)));
  std::mt19937 rng(7);
  MaterialState s;
  s.cohesion = 26.7e3;
  s.stress = -100e3 * Mat3::Identity();
  int plastic_steps = 0;
  for (int step = 0; step < 2000; ++step) {
    const Mat3 l = random_symmetric(rng, 1.0) + skew(random_symmetric(rng, 1.0) * 3.0);
    const double dt = 2e-4;
    MaterialState trial_state = s;
    LinearElastic{dp.k, dp.density}.update(trial_state, l, dt, 0.0);
    const Mat3 plastic = dp.update_returning(s, l, dt, 0.0);
    const double scale = 100e3;
    EXPECT_LE(dp.yield(s.stress, s.cohesion), 1e-9 * scale) << "step " << step;
    // Off the apex (the tension cut-off removes volume by design).
    const double apex = dp.kc(dp.phi, s.cohesion) / (3.0 * DruckerPrager::alpha(dp.phi));
    if (plastic.norm() > 0.0 && trial_state.stress.trace() / 3.0 < apex) {
      ++plastic_steps;
      EXPECT_NEAR(plastic.trace(), 0.0, 1e-14) << "step " << step;
      EXPECT_NEAR(s.stress.trace(), trial_state.stress.trace(), 1e-9 * scale) << "step " << step;
    }
  }
  EXPECT_GT(plastic_steps, 100);  // the path did load the cone
}

// With psi > 0 the flow rule g = sqrt(J2) + 3 I1 sin(psi) dilates by
// tr(d eps_p) = 9 sin(psi) d lambda > 0, and the return still ends on the cone.
TEST(MpmDruckerPrager, DilatancyExpands) {
  const auto dp = std::get<DruckerPrager>(make_material(soil(DruckerPrager::name, 30, 10e3, 10)));
  MaterialState s;
  s.cohesion = 10e3;
  s.stress = -50e3 * Mat3::Identity();
  Mat3 shear = Mat3::Zero();
  shear(0, 1) = shear(1, 0) = 1.0;
  double dilation = 0.0;
  for (int step = 0; step < 200; ++step) {
    dilation += dp.update_returning(s, shear, 1e-4, 0.0).trace();
    EXPECT_LE(dp.yield(s.stress, s.cohesion), 1e-6);
  }
  EXPECT_GT(dilation, 0.0);
  EXPECT_GT(s.plastic_strain, 0.0);
}

// For a small step from a point on the cone the return mapping must agree
// with the rate form of mpm.md: sigma-dot = 2G e-dot + K eps-dot_v delta -
// lambda-dot (9K sin(psi) delta + G/sqrt(J2) s), lambda-dot = (3 alpha K
// eps-dot_v + G/sqrt(J2) s:eps-dot) / (27 alpha K sin(psi) + G), to first
// order in dt.
TEST(MpmDruckerPrager, SmallStepMatchesBuiRateForm) {
  const auto dp = std::get<DruckerPrager>(make_material(soil(DruckerPrager::name, 28, 26.7e3, 5)));
  const double a = DruckerPrager::alpha(dp.phi), kc = DruckerPrager::kc(dp.phi, 26.7e3);
  // A state on the cone: deviator along a shear, mean stress -80 kPa.
  Mat3 dev = Mat3::Zero();
  dev(0, 1) = dev(1, 0) = 1.0;
  const double p = -80e3, sqrt_j2 = kc - 3.0 * a * p;  // f = 0
  MaterialState s;
  s.cohesion = 26.7e3;
  s.stress = dev * sqrt_j2 + p * Mat3::Identity();  // sqrt(J2) of dev is 1
  ASSERT_NEAR(dp.yield(s.stress, s.cohesion), 0.0, 1e-6);
  Mat3 rate = Mat3::Zero();  // loading: more shear, a little compression
  rate(0, 1) = rate(1, 0) = 1.0;
  rate(2, 2) = -0.2;
  const double g = dp.k.shear, k = dp.k.bulk, sp = std::sin(dp.psi);
  const Mat3 sd = deviator(s.stress);
  const double sj = std::sqrt(j2(s.stress)), ev = rate.trace();
  const double ldot =
      (3.0 * a * k * ev + g / sj * (sd.array() * rate.array()).sum()) / (27.0 * a * k * sp + g);
  ASSERT_GT(ldot, 0.0);
  const Mat3 id = Mat3::Identity();
  const Mat3 expected =
      2.0 * g * deviator(rate) + k * ev * id - ldot * (9.0 * k * sp * id + g / sj * sd);
  const double dt = 1e-7;
  const Mat3 before = s.stress;
  dp.update(s, rate, dt, 0.0);
  const Mat3 got = (s.stress - before) / dt;
  EXPECT_LT((got - expected).norm(), 1e-4 * expected.norm());
}

// Beyond the apex in tension the stress goes to the apex (tension cut-off)
// and a lower user cut-off caps the mean stress there.
TEST(MpmDruckerPrager, TensionCutOff) {
  auto params = soil(DruckerPrager::name, 28, 26.7e3);
  params.tension_cutoff = 5e3;
  const auto dp = std::get<DruckerPrager>(make_material(params));
  MaterialState s;
  s.cohesion = 26.7e3;
  dp.update(s, Mat3::Identity(), 1e-3, 0.0);  // trial mean stress K * 3e-3 ~ 50 kPa
  EXPECT_NEAR(s.stress.trace() / 3.0, 5e3, 1e-6);
  EXPECT_LE(dp.yield(s.stress, s.cohesion), 1e-9);
}

// Random trial states of every kind (main plane, both edges, apex): after the
// return f <= 0, and no plastic volume change at psi = 0 off the apex.
TEST(MpmMohrCoulomb, ReturnFromRandomTrialStates) {
  for (double c : {0.0, 20e3}) {
    const auto mc = std::get<MohrCoulomb>(make_material(soil(MohrCoulomb::name, 31, c)));
    std::mt19937 rng(11);
    int edges = 0;
    for (int trial = 0; trial < 3000; ++trial) {
      MaterialState s;
      s.cohesion = c;
      s.stress = random_symmetric(rng, 50e3) - 60e3 * Mat3::Identity();
      const Mat3 strain = random_symmetric(rng, 2e-3);
      const Mat3 plastic = mc.update_returning(s, strain, 1.0, 0.0);
      EXPECT_LE(mc.yield(s.stress, c), 1e-8 * 1e5) << "trial " << trial;
      Eigen::SelfAdjointEigenSolver<Mat3> eig(s.stress);
      const auto sig = eig.eigenvalues();
      const double apex = c * std::cos(mc.phi) / std::sin(mc.phi);
      const bool at_apex = std::abs(sig[0] - apex) < 1e-6 && std::abs(sig[2] - apex) < 1e-6;
      if (!at_apex) {
        EXPECT_NEAR(plastic.trace(), 0.0, 1e-12) << "trial " << trial;
      }
      if (std::abs(sig[1] - sig[0]) < 1e-6 || std::abs(sig[2] - sig[1]) < 1e-6) ++edges;
    }
    EXPECT_GT(edges, 10);  // corner returns were exercised
  }
}

// Cohesion loss (mpm.md, van den Bout eq. 26): while yielding and dilating,
// c falls by c0/(2 eps_c) dV/V0, never rises, never below zero.
TEST(MpmCohesionLoss, FallsWithDilationWhileYielding) {
  auto params = soil(DruckerPrager::name, 28, 26.7e3);
  params.critical_volume_strain = 0.01;
  const auto dp = std::get<DruckerPrager>(make_material(params));
  MaterialState s;
  s.cohesion = params.cohesion;
  s.stress = -10e3 * Mat3::Identity();
  Mat3 shear = Mat3::Zero();
  shear(0, 1) = shear(1, 0) = 1.0;
  for (int i = 0; i < 100; ++i) dp.update(s, shear, 1e-4, 0.0);  // to the cone
  ASSERT_TRUE(s.yielding);
  const double c_before = s.cohesion;
  dp.update(s, shear, 1e-4, 1e-3);  // dV/V0 = 1e-3
  EXPECT_NEAR(s.cohesion, c_before - 26.7e3 / (2 * 0.01) * 1e-3, 1e-6);
  dp.update(s, shear, 1e-4, -1e-3);  // compaction restores nothing
  EXPECT_LE(s.cohesion, c_before - 26.7e3 / (2 * 0.01) * 1e-3 + 1e-6);
  for (int i = 0; i < 100; ++i) dp.update(s, shear, 1e-4, 1e-3);
  EXPECT_EQ(s.cohesion, 0.0);
  EXPECT_LE(dp.yield(s.stress, s.cohesion), 1e-6);
}

// Crack-band form (materials.hpp): a band one cell wide is open at w_c =
// 2 eps_c h, so eps_c = w_c / (2 h); without w_c the volume strain is used as
// given whatever the cell.
TEST(MpmCohesionLoss, CrackBandOpeningSetsCriticalStrainPerCell) {
  auto params = soil(DruckerPrager::name, 27, 18.3e3);
  params.critical_volume_strain = 0.03;
  EXPECT_EQ(critical_volume_strain(params, 0.01), 0.03);
  EXPECT_EQ(critical_volume_strain(params, 0.005), 0.03);
  params.critical_opening = 2e-4;
  EXPECT_DOUBLE_EQ(critical_volume_strain(params, 0.01), 0.01);
  EXPECT_DOUBLE_EQ(critical_volume_strain(params, 0.005), 0.02);
  EXPECT_DOUBLE_EQ(critical_volume_strain(params, 0.04), 0.0025);
}

// Objectivity: a stressed point spun rigidly (velocity gradient = spin) keeps
// its invariants and its stress turns with it, sigma = R sigma0 R^T.
template <class Model>
void check_rigid_rotation(const Model& model, MaterialState s) {
  const double omega = 2.0, dt = 1e-3;
  Mat3 spin = Mat3::Zero();
  spin(0, 1) = -omega;
  spin(1, 0) = omega;
  const Mat3 s0 = s.stress;
  Eigen::SelfAdjointEigenSolver<Mat3> e0(s0, Eigen::EigenvaluesOnly);
  const int steps = static_cast<int>(std::round(M_PI / 2 / omega / dt));  // a quarter turn
  for (int i = 0; i < steps; ++i) model.update(s, spin, dt, 0.0);
  Eigen::SelfAdjointEigenSolver<Mat3> e1(s.stress, Eigen::EigenvaluesOnly);
  const double scale = s0.norm();
  EXPECT_LT((e1.eigenvalues() - e0.eigenvalues()).norm(), 1e-10 * scale);
  const double angle = omega * dt * steps;
  const Mat3 r = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  // The Cayley rotation's angle per step differs from omega dt by
  // (omega dt)^3/12, far below this.
  EXPECT_LT((s.stress - r * s0 * r.transpose()).norm(), 1e-5 * scale);
}

TEST(MpmObjectivity, RigidRotationKeepsInvariants) {
  MaterialState s;
  s.stress << -50e3, 20e3, 5e3, 20e3, -80e3, 0.0, 5e3, 0.0, -30e3;
  s.cohesion = 26.7e3;
  check_rigid_rotation(std::get<LinearElastic>(make_material(soil(LinearElastic::name, 0, 0))), s);
  check_rigid_rotation(
      std::get<DruckerPrager>(make_material(soil(DruckerPrager::name, 28, 26.7e3))), s);
  check_rigid_rotation(std::get<MohrCoulomb>(make_material(soil(MohrCoulomb::name, 31, 26.7e3))),
                       s);
  MaterialParams fluid;
  fluid.model = NewtonianFluid::name;
  fluid.density = 1000;
  fluid.bulk_modulus = 2e6;
  fluid.viscosity = 1.0;
  MaterialState pressure;
  pressure.stress = -10e3 * Mat3::Identity();
  check_rigid_rotation(std::get<NewtonianFluid>(make_material(fluid)), pressure);
  // Neo-Hookean: a pre-stretched point (F = diag(1.1, 0.95, 1)) spun rigidly.
  const auto nh = std::get<NeoHookean>(make_material(soil(NeoHookean::name, 0, 0)));
  MaterialState stretched;
  stretched.deformation = Eigen::Vector3d(1.1, 0.95, 1.0).asDiagonal();
  nh.update(stretched, Mat3::Zero(), 1e-3, 0.0);  // stress of that F
  check_rigid_rotation(nh, stretched);
}

}  // namespace
}  // namespace talus::mpm
