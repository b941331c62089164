// 1D elastic bar vibration (mpm.md "Validation cases"; Sulsky et al. 1994):
// a bar of length L fixed at x = 0 and free at x = L, c = sqrt(E/rho), starts
// with v(x, 0) = v0 sin(pi x / 2L). Exact: v = v0 cos(wt) sin(pi x / 2L),
// w = pi c / 2L, centre-of-mass velocity (2 v0 / pi) cos(wt), energy constant.
// Modelled in 2D as one row of cells between rollers with nu = 0, which is the
// 1D bar exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "talus/mpm/solver.hpp"

namespace talus::mpm {
namespace {

constexpr double kLength = 1.0, kYoung = 100.0, kDensity = 1.0, kV0 = 0.05;
constexpr int kCells = 50, kPerCell = 2;

Solver<2> make_bar(ShapeKind shape, Scheme scheme, double flip) {
  const double h = kLength / kCells;
  Grid<2> grid(
      Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(kLength + 4 * h, h), h,
      {BoundaryKind::Fixed, BoundaryKind::Free, BoundaryKind::Roller, BoundaryKind::Roller});
  MaterialParams mp;
  mp.model = LinearElastic::name;
  mp.density = kDensity;
  mp.youngs_modulus = kYoung;
  mp.poisson_ratio = 0.0;
  SolverParams sp;
  sp.shape = shape;
  sp.scheme = scheme;
  sp.flip = flip;
  sp.cfl = 0.2;
  sp.gimp_half_width = 0.5 / kPerCell;
  Solver<2> s(grid, {make_material(mp)}, sp);
  const double dx = h / kPerCell;
  for (int i = 0; i < kCells * kPerCell; ++i)
    for (int j = 0; j < kPerCell; ++j) {
      const Eigen::Vector2d x((i + 0.5) * dx, (j + 0.5) * dx);
      const Eigen::Vector2d v(kV0 * std::sin(M_PI * x.x() / (2 * kLength)), 0.0);
      s.particles.add(x, v, kDensity * dx * dx, dx * dx, 0, MaterialState{});
    }
  return s;
}

double energy(const Solver<2>& s) {
  double e = kinetic_energy(s.particles);
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    const double sxx = s.particles.state[p].stress(0, 0);
    e += s.particles.volume[p] * sxx * sxx / (2.0 * kYoung);
  }
  return e;
}

struct BarResult {
  double period = 0.0, max_com_error = 0.0, max_energy_drift = 0.0;
};

BarResult run_bar(ShapeKind shape, Scheme scheme, double flip) {
  Solver<2> s = make_bar(shape, scheme, flip);
  const double c = std::sqrt(kYoung / kDensity), omega = M_PI * c / (2 * kLength);
  const double period = 2 * M_PI / omega;
  const double e0 = energy(s);
  BarResult r;
  std::vector<double> crossings;
  double t_prev = 0.0, v_prev = centre_of_mass_velocity(s.particles).x();
  while (s.time < 1.6 * period) {
    s.advance();
    const double v = centre_of_mass_velocity(s.particles).x();
    const double exact = 2 * kV0 / M_PI * std::cos(omega * s.time);
    r.max_com_error = std::max(r.max_com_error, std::abs(v - exact));
    r.max_energy_drift = std::max(r.max_energy_drift, std::abs(energy(s) - e0) / e0);
    if ((v_prev > 0) != (v > 0))  // linear interpolation of the zero crossing
      crossings.push_back(t_prev + (s.time - t_prev) * v_prev / (v_prev - v));
    t_prev = s.time;
    v_prev = v;
  }
  // Crossings at T/4, 3T/4, 5T/4: two half periods.
  if (crossings.size() >= 3) r.period = crossings[2] - crossings[0];
  r.max_com_error /= 2 * kV0 / M_PI;
  return r;
}

const double kExactPeriod = 4 * kLength / std::sqrt(kYoung / kDensity);

// Tolerances: the semi-discrete frequency error of this grid is (k h)^2/24 ~
// 4e-5 for k = pi/2L, h = L/50, and the step's about (c dt / h)^2 ~ 1e-3, so
// 1 % on the period and 2 % of the amplitude on the centre-of-mass velocity
// leave room only for those; pure FLIP with MUSL conserves energy to O(dt)
// (Sulsky et al. 1995), 1 %.
void expect_exact(const BarResult& r, const char* what) {
  std::printf("%s: period/exact = %.5f, max |v_com error|/amplitude = %.4f, energy drift = %.2e\n",
              what, r.period / kExactPeriod, r.max_com_error, r.max_energy_drift);
  EXPECT_NEAR(r.period / kExactPeriod, 1.0, 0.01) << what;
  EXPECT_LT(r.max_com_error, 0.02) << what;
  EXPECT_LT(r.max_energy_drift, 0.01) << what;
}

TEST(MpmBarVibration, MuslFlipLinear) {
  expect_exact(run_bar(ShapeKind::Linear, Scheme::Musl, 1.0), "linear MUSL");
}
TEST(MpmBarVibration, MuslFlipGimp) {
  expect_exact(run_bar(ShapeKind::Gimp, Scheme::Musl, 1.0), "GIMP MUSL");
}
TEST(MpmBarVibration, MuslFlipCubicBSpline) {
  expect_exact(run_bar(ShapeKind::CubicBSpline, Scheme::Musl, 1.0), "B-spline MUSL");
}
TEST(MpmBarVibration, UslFlipGimp) {
  expect_exact(run_bar(ShapeKind::Gimp, Scheme::Usl, 1.0), "GIMP USL");
}

// PIC averages the velocity field through the grid every step and is known to
// be dissipative (Brackbill 1988): it must lose energy where FLIP keeps it.
TEST(MpmBarVibration, PicDissipates) {
  const BarResult pic = run_bar(ShapeKind::Gimp, Scheme::Musl, 0.0);
  const BarResult flip = run_bar(ShapeKind::Gimp, Scheme::Musl, 1.0);
  std::printf("energy drift: PIC %.3e, FLIP %.3e\n", pic.max_energy_drift, flip.max_energy_drift);
  EXPECT_GT(pic.max_energy_drift, 2.0 * flip.max_energy_drift);
}

}  // namespace
}  // namespace talus::mpm
