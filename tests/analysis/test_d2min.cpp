// Non-affine displacement D^2_min (Falk & Langer): zero under homogeneous deformations, the
// hand-computed value for one displaced neighbour, and the grains it leaves out.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "talus/analysis/d2min.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {
namespace {

std::vector<Vec3> random_points(int n, int dimension, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1e-2);
  std::vector<Vec3> x;
  for (int i = 0; i < n; ++i) x.push_back(Vec3(u(rng), u(rng), dimension == 3 ? u(rng) : 0.0));
  return x;
}

TEST(D2min, ZeroUnderAnyHomogeneousDeformation3D) {
  // Stretch, shear and rotation (a general F with det > 0) plus a translation: every grain's
  // neighbourhood maps exactly by J = F, so D^2_min is zero up to round-off: |d| ~ 1e-3 m,
  // residuals ~ 1e-16 |d|, squared and summed over ~50 neighbours: < 1e-12 of |d|^2 = 1e-18 m^2.
  const auto x0 = random_points(300, 3, 1);
  const std::vector<double> r(x0.size(), 2e-4);
  Eigen::Matrix3d stretch = Eigen::Vector3d(1.1, 0.93, 1.04).asDiagonal();
  stretch(0, 1) = 0.2;  // simple shear
  stretch(2, 0) = -0.07;
  const Eigen::Matrix3d f =
      Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix() * stretch;
  std::vector<Vec3> x1;
  for (const Vec3& x : x0) x1.push_back(f * x + Vec3(3e-3, -1e-3, 0.5));
  const D2min d = non_affine_displacement(x0, x1, r, {3, 3e-3});
  EXPECT_GT(d.evaluated, 290u);
  for (std::size_t i = 0; i < x0.size(); ++i)
    if (!std::isnan(d.d2min[i])) {
      EXPECT_LT(d.d2min[i], 1e-12 * 1e-6) << i;
    }
  EXPECT_LT(d.mean_d2min, 1e-18);
  EXPECT_NEAR(d.mean_diameter, 4e-4, 1e-15);
}

TEST(D2min, ZeroUnderAnyHomogeneousDeformation2D) {
  const auto x0 = random_points(200, 2, 2);
  const std::vector<double> r(x0.size(), 2e-4);
  const double c = std::cos(0.4), s = std::sin(0.4);
  Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
  f.topLeftCorner<2, 2>() << c * 1.2 - s * 0.0, c * 0.3 - s * 0.9, s * 1.2, s * 0.3 + c * 0.9;
  std::vector<Vec3> x1;
  for (const Vec3& x : x0) x1.push_back(f * x + Vec3(-2e-3, 1e-3, 0));
  const D2min d = non_affine_displacement(x0, x1, r, {2, 2.5e-3});
  EXPECT_GT(d.evaluated, 190u);
  for (double v : d.d2min)
    if (!std::isnan(v)) {
      EXPECT_LT(v, 1e-18);
    }
}

// Grain 0 at the origin with four neighbours at (+-1, 0), (0, +-1) (a = 1 mm). Moving the
// neighbour (1, 0) to (1 + delta, 0): X = sum d1 d0^T = diag(2 + delta, 2), Y = sum d0 d0^T =
// diag(2, 2), J = X Y^-1 = diag(1 + delta/2, 1); residuals delta/2 at (+-1, 0), zero at
// (0, +-1): D^2_min = delta^2 / 2 (times a^2).
TEST(D2min, HandComputedValueForOneDisplacedNeighbour) {
  const double a = 1e-3, delta = 0.1;
  const std::vector<Vec3> x0{Vec3::Zero(), a * Vec3(1, 0, 0), a * Vec3(0, 1, 0), a * Vec3(-1, 0, 0),
                             a * Vec3(0, -1, 0)};
  auto x1 = x0;
  x1[1].x() += delta * a;
  const std::vector<double> r(5, 0.5 * a);  // d_mean = a
  const D2min d = non_affine_displacement(x0, x1, r, {2, 1.1 * a});
  EXPECT_EQ(d.neighbours[0], 4);
  EXPECT_NEAR(d.d2min[0], delta * delta / 2 * a * a, 1e-15 * a * a);
  // The source's form: sqrt(D^2 / n) / d_mean = sqrt(0.005 / 4) = 0.0353553...
  EXPECT_NEAR(d.d_min_norm[0], std::sqrt(0.005 / 4), 1e-12);
  // With cutoff 1.1 a the outer grains see only the centre (1 neighbour < D + 1): no value.
  for (int i = 1; i < 5; ++i) EXPECT_TRUE(std::isnan(d.d2min[i])) << i;
  EXPECT_EQ(d.evaluated, 1u);
  EXPECT_NEAR(d.mean_d2min, 0.005 * a * a, 1e-15 * a * a);
}

TEST(D2min, LeavesOutExcludedAndDegenerateNeighbourhoods) {
  const double a = 1e-3;
  // 3D, the centre's four neighbours all in the plane z = 0: J_zz is not determined.
  const std::vector<Vec3> flat{Vec3::Zero(), a * Vec3(1, 0, 0), a * Vec3(0, 1, 0),
                               a * Vec3(-1, 0, 0), a * Vec3(0, -1, 0)};
  const std::vector<double> r(5, 0.5 * a);
  const D2min d = non_affine_displacement(flat, flat, r, {3, 1.1 * a});
  EXPECT_EQ(d.neighbours[0], 4);
  EXPECT_TRUE(std::isnan(d.d2min[0]));
  EXPECT_EQ(d.evaluated, 0u);
  // 2D with grain 1 left out: the centre keeps 3 neighbours (still >= D + 1), grain 1 none.
  auto x1 = flat;
  x1[1].x() += 0.1 * a;  // the displaced grain is left out, so the rest moves affinely
  const D2min e = non_affine_displacement(flat, x1, r, {2, 1.1 * a}, {1, 0, 1, 1, 1});
  EXPECT_EQ(e.neighbours[0], 3);
  EXPECT_NEAR(e.d2min[0], 0.0, 1e-30);
  EXPECT_TRUE(std::isnan(e.d2min[1]));
  EXPECT_EQ(e.neighbours[1], 0);
}

TEST(D2min, RefusesBadCutoffAndMismatchedArrays) {
  const std::vector<Vec3> x(3, Vec3::Zero());
  const std::vector<double> r(3, 1.0);
  EXPECT_THROW(non_affine_displacement(x, x, r, {3, -1.0}), InputError);
  EXPECT_THROW(non_affine_displacement(x, x, r, {3, 0.0}), InputError);
  EXPECT_THROW(non_affine_displacement(x, {Vec3::Zero()}, r, {3, 1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace talus::analysis
