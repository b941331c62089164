// Non-affine displacement D^2_min (Falk & Langer): zero under homogeneous deformations, the
// hand-computed value for one displaced neighbour, and the grains it leaves out. Its spatial
// autocorrelation C(r) (Götz eq. 48-49): a constant field, a field on one half of a lattice
// (counted by hand) and an uncorrelated random field.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "lattices.hpp"
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

// --- spatial autocorrelation C(r) of D_min ---

// A constant D_min = D: every C_i(r) = D^2 / d wherever grain i has partners, and C(0) = D^2 / d,
// so C(r)/C(0) = 1 in every bin with pairs (up to round-off: sums of ~10 equal terms, 1e-12).
// The pair counts are the simple cubic lattice's (n = 5): 3 n^2 (n - 1) = 300 at a,
// 6 n (n - 1)^2 = 480 at sqrt 2 a, 4 (n - 1)^3 = 256 at sqrt 3 a; bins of 0.3 a put these
// distances well inside bins 3, 4 and 5.
TEST(D2minCorrelation, ConstantFieldIsOneAtEveryDistance) {
  const double a = 1e-3, value = 3e-5;
  const auto l = test::simple_cubic(5, a);
  std::vector<double> d_min(l.position.size(), value);
  const D2minCorrelation c = d2min_correlation(l.position, d_min, a, {3, 0.3 * a, 2.5 * a});
  ASSERT_EQ(c.r.size(), 9u);  // ceil(2.5 / 0.3)
  EXPECT_NEAR(c.r[3], 1.05 * a, 1e-15);
  EXPECT_EQ(c.valued, 125u);
  EXPECT_NEAR(c.c0, value * value / a, 1e-12 * value * value / a);
  for (int b = 0; b < 3; ++b) {  // nothing closer than a
    EXPECT_EQ(c.pairs[b], 0u) << b;
    EXPECT_TRUE(std::isnan(c.c[b])) << b;
  }
  EXPECT_EQ(c.pairs[3], 300u);
  EXPECT_EQ(c.pairs[4], 480u);
  EXPECT_EQ(c.pairs[5], 256u);
  EXPECT_EQ(c.grains[3], 125u);  // every grain has a face neighbour
  for (std::size_t b = 3; b < c.r.size(); ++b) {
    ASSERT_GT(c.pairs[b], 0u) << b;
    EXPECT_NEAR(c.c_over_c0[b], 1.0, 1e-12) << b;
  }
  // A grain without a value (left out of D2min) is neither centre nor partner: the interior
  // grain (2, 2, 2) takes its 6 face pairs with it and the rest is still 1.
  d_min[2 * 25 + 2 * 5 + 2] = std::numeric_limits<double>::quiet_NaN();
  const D2minCorrelation e = d2min_correlation(l.position, d_min, a, {3, 0.3 * a, 2.5 * a});
  EXPECT_EQ(e.valued, 124u);
  EXPECT_EQ(e.pairs[3], 294u);
  EXPECT_EQ(e.grains[3], 124u);
  for (std::size_t b = 3; b < e.r.size(); ++b) EXPECT_NEAR(e.c_over_c0[b], 1.0, 1e-12) << b;
}

// 4 x 4 square lattice (spacing a), D_min = D on the columns x = 0, a and 0 on x = 2a, 3a.
// C(0) = (8 D^2 / d) / 16 = D^2 / (2 d). C_i(r) = D_i (fraction of i's partners at r that are
// in the D half) D / d, so C(r) d / D^2 = (sum of that fraction over the D half) / (grains with
// partners at r). By hand:
//  r = a: column 0 has all its partners in the D half (fraction 1, 4 grains); column 1 has
//    one of its x partners outside: 2/3 at the rows y = 0, 3a (3 partners), 3/4 on the two
//    inner rows. Sum 4 + 4/3 + 3/2 = 41/6 over all 16 grains: C(a)/C(0) = (41/96) / (1/2) =
//    41/48. Pairs 2 n (n - 1) = 24.
//  r = 3a: partners only along a row or column, 3a apart. Column 0: its x partner (column 3)
//    is outside, its y partner (rows 0 <-> 3 only) inside: 1/2 at rows 0, 3 and 0 at rows 1,
//    2; column 1 has no x partner and a y partner in rows 0, 3 only (fraction 1) while its
//    inner rows have no partner at all and are not in the mean (likewise column 2). Grains
//    with partners: 8 (columns 0, 3) + 4 (rows 0, 3 of columns 1, 2) = 12; sum 1 + 2 = 3:
//    C(3a)/C(0) = (3/12) / (1/2) = 1/2. Pairs: 4 along x + 4 along y = 8.
// Bins of 0.26 a hold a (bin 3 = [0.78, 1.04) a) and 3a (bin 11 = [2.86, 3.12) a) alone: the
// nearest other distances are sqrt 8 a = 2.83 a and sqrt 10 a = 3.16 a. The grains are put at
// different z to check that a 2D analysis measures distances in the x-y plane only.
TEST(D2minCorrelation, HalfFieldGivesTheHandCountedFractions) {
  const double a = 1e-3, value = 2e-5;
  auto l = test::square(4, a);
  std::vector<double> d_min;
  for (std::size_t k = 0; k < l.position.size(); ++k) {
    d_min.push_back(l.position[k].x() < 1.5 * a ? value : 0.0);
    l.position[k].z() = 5 * a * static_cast<double>(k % 3);
  }
  const D2minCorrelation c = d2min_correlation(l.position, d_min, a, {2, 0.26 * a, 3.2 * a});
  ASSERT_EQ(c.r.size(), 13u);
  EXPECT_NEAR(c.c0, value * value / (2 * a), 1e-12 * value * value / a);
  EXPECT_EQ(c.pairs[3], 24u);
  EXPECT_EQ(c.grains[3], 16u);
  EXPECT_NEAR(c.c_over_c0[3], 41.0 / 48.0, 1e-12);
  EXPECT_EQ(c.pairs[11], 8u);
  EXPECT_EQ(c.grains[11], 12u);
  EXPECT_NEAR(c.c_over_c0[11], 0.5, 1e-12);
  EXPECT_NEAR(c.c[11], 0.25 * value * value / a, 1e-12 * value * value / a);
  // In 3D the z offsets (5a, 10a) separate grains of different k % 3 beyond 3.2 a: the face
  // neighbours are 1 or 4 apart in list order (never at one z, no pair at a), the pairs 3a
  // apart are 3 or 12 apart (always at one z, all 8 stay).
  const D2minCorrelation d = d2min_correlation(l.position, d_min, a, {3, 0.26 * a, 3.2 * a});
  EXPECT_EQ(d.pairs[3], 0u);
  EXPECT_EQ(d.pairs[11], 8u);
}

// Independent values D_i (uniform on [0, 1), simple cubic 10^3, fixed seeds): for i != j,
// E[D_i D_j] = mean^2, so C(r) d should be the squared mean of the field at every r > 0, and
// C(0) d = mean of D^2 exactly (here ~1/3, so C(r)/C(0) ~ 3/4). Against the field's own mean
// m the leading fluctuations cancel (C d - m^2 ~ sigma^2 / sqrt(N M) plus an edge term), a
// standard error of ~2e-3 by that estimate. The test measures it instead: 64 fields of
// different seeds give the standard deviation s_b of C d - m^2 in each bin; the first field
// must lie within 4 s_b, and the mean over the 64 within 4 s_b / 8 of zero up to the known
// bias E[m^2] - mean^2 = sigma^2 / N = 8e-5 (not a fluctuation; added to the tolerance).
TEST(D2minCorrelation, UncorrelatedFieldGivesTheSquaredMean) {
  const double a = 1e-3;
  const auto l = test::simple_cubic(10, a);
  const std::size_t n = l.position.size();
  const int fields = 64;
  const D2minCorrelationOptions o{3, 0.45 * a, 2.7 * a};
  std::vector<std::vector<double>> dev;  // [field][bin] C d - m^2
  for (int f = 0; f < fields; ++f) {
    std::mt19937_64 rng(1000 + f);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> d_min(n);
    for (double& v : d_min) v = u(rng);
    const double m = std::accumulate(d_min.begin(), d_min.end(), 0.0) / n;
    double m2 = 0.0;
    for (double v : d_min) m2 += v * v / n;
    const D2minCorrelation c = d2min_correlation(l.position, d_min, a, o);
    ASSERT_NEAR(c.c0 * a, m2, 1e-12);
    std::vector<double> row;
    for (std::size_t b = 0; b < c.r.size(); ++b)
      row.push_back(c.pairs[b] ? c.c[b] * a - m * m : std::numeric_limits<double>::quiet_NaN());
    dev.push_back(row);
  }
  int checked = 0;
  for (std::size_t b = 0; b < dev[0].size(); ++b) {
    if (std::isnan(dev[0][b])) continue;
    double mean = 0.0, var = 0.0;
    for (const auto& row : dev) mean += row[b] / fields;
    for (const auto& row : dev) var += (row[b] - mean) * (row[b] - mean) / (fields - 1);
    const double s = std::sqrt(var);
    EXPECT_LT(s, 5e-3) << "bin " << b;  // the estimate above, with room
    EXPECT_LT(std::abs(dev[0][b]), 4 * s) << "bin " << b;
    EXPECT_LT(std::abs(mean), 4 * s / std::sqrt(fields) + 1.0 / 12 / n) << "bin " << b;
    ++checked;
  }
  // Bins of 0.45 a: a, sqrt 2 a, ..., sqrt 6 a fall in bins 2 to 5, none near an edge.
  EXPECT_EQ(checked, 4);
}

TEST(D2minCorrelation, RefusesBadBinsAndMismatchedArrays) {
  const std::vector<Vec3> x(3, Vec3::Zero());
  const std::vector<double> v(3, 1.0);
  EXPECT_THROW(d2min_correlation(x, v, 1.0, {3, 0.0, 1.0}), InputError);
  EXPECT_THROW(d2min_correlation(x, v, 1.0, {3, -0.1, 1.0}), InputError);
  EXPECT_THROW(d2min_correlation(x, v, 1.0, {3, 0.1, 0.0}), InputError);
  EXPECT_THROW(d2min_correlation(x, v, 1.0, {3, 1e-9, 1.0}), InputError);  // 10^9 bins
  EXPECT_THROW(d2min_correlation(x, v, 0.0, {3, 0.1, 1.0}), InputError);
  EXPECT_THROW(d2min_correlation(x, v, 1.0, {4, 0.1, 1.0}), InputError);
  EXPECT_THROW(d2min_correlation(x, {1.0}, 1.0, {3, 0.1, 1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace talus::analysis
