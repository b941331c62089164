// Radial distribution function: peaks of touching lattices at the lattice distances with the
// right number of neighbours, g = 1 for uncorrelated points, refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lattices.hpp"
#include "talus/analysis/rdf.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {
namespace {

// Bins of width 0.03 a put the FCC distances a/sqrt2, a, sqrt(3/2) a, sqrt2 a inside bins 23,
// 33, 40, 47 (none within 0.1 bin of an edge, so round-off cannot move a pair across).
TEST(Rdf, FccShellsAtLatticeDistancesWithTheirCoordination) {
  const double a = 2e-3;
  const test::Lattice l = test::fcc(6, a);
  const Rdf rdf = radial_distribution(l.position, l.radius, {3, 1.5 * a, 50});
  ASSERT_EQ(rdf.g.size(), 50u);
  EXPECT_GT(rdf.reference_grains, 100u);
  // The coordination integral counts centres, whatever the density: 12, +6, +24, +12 (exact:
  // counts of pairs divided by the count of reference grains).
  const int shell_bin[4] = {23, 33, 40, 47};
  const double shell_sum[4] = {12, 18, 42, 54};
  for (int s = 0; s < 4; ++s) {
    EXPECT_DOUBLE_EQ(rdf.coordination[shell_bin[s]], shell_sum[s]) << s;
    EXPECT_DOUBLE_EQ(rdf.coordination[shell_bin[s] - 1], s ? shell_sum[s - 1] : 0.0) << s;
    EXPECT_GT(rdf.g[shell_bin[s]], 1.0);
  }
  // Nothing between the shells and nothing closer than touching.
  for (int b = 0; b < 50; ++b) {
    const bool peak = b == 23 || b == 33 || b == 40 || b == 47;
    if (!peak) {
      EXPECT_EQ(rdf.g[b], 0.0) << b;
    }
  }
  EXPECT_NEAR(rdf.r[23], 0.705 * a, 1e-12);
}

TEST(Rdf, SimpleCubicFirstPeakHeightFromTheLatticeDensity) {
  // n^3 touching spheres fill the box n a on a side exactly, so rho = 1/a^3 and the first
  // shell (6 neighbours at a, bin 33 = [0.99 a, 1.02 a) of width 0.03 a) has
  // g = 6 / (rho V_shell) to round-off.
  const double a = 1e-3;
  const test::Lattice l = test::simple_cubic(8, a);
  const Rdf rdf = radial_distribution(l.position, l.radius, {3, 1.2 * a, 40});
  EXPECT_NEAR(rdf.density, 1 / (a * a * a), 1e-9 / (a * a * a));
  const double r0 = 33 * 0.03 * a, r1 = 34 * 0.03 * a;
  const double shell = 4.0 / 3.0 * M_PI * (r1 * r1 * r1 - r0 * r0 * r0);
  EXPECT_NEAR(rdf.g[33], 6 / (rdf.density * shell), 1e-9 * rdf.g[33]);
  EXPECT_DOUBLE_EQ(rdf.coordination[33], 6.0);
  EXPECT_DOUBLE_EQ(rdf.coordination[32], 0.0);
  // Reference grains: centres at least 1.2 a inside the box [-a/2, 7.5 a]: i = 1..6.
  EXPECT_EQ(rdf.reference_grains, 6u * 6 * 6);
}

TEST(Rdf, TwoDimensionalLatticesCountFourAndSixNeighbours) {
  const double a = 1e-3;
  const test::Lattice sq = test::square(12, a), hex = test::hexagonal(14, 14, a);
  // Bins of 0.06 a (none of the distances near an edge): a in bin 16 (a / 0.06 a = 16.7),
  // sqrt2 a in bin 23 (23.6); sqrt3 a = 1.73 a is beyond r_max = 1.5 a.
  const Rdf s = radial_distribution(sq.position, sq.radius, {2, 1.5 * a, 25});
  EXPECT_DOUBLE_EQ(s.coordination[16], 4.0);
  EXPECT_DOUBLE_EQ(s.coordination[15], 0.0);
  EXPECT_DOUBLE_EQ(s.coordination[23], 8.0);  // + 4 diagonal neighbours at sqrt2 a
  const Rdf h = radial_distribution(hex.position, hex.radius, {2, 1.5 * a, 25});
  EXPECT_DOUBLE_EQ(h.coordination[16], 6.0);
  EXPECT_DOUBLE_EQ(h.coordination[24], 6.0);  // no hexagonal neighbour between a and 1.5 a
}

TEST(Rdf, UncorrelatedPointsGiveOne) {
  // 20000 uniform points in a unit cube (tiny radii): an ideal gas, g = 1 up to the Poisson
  // noise of each bin's count n_b (sd sqrt(n_b)): every bin from 0.01 on must lie within 5 sd
  // (fixed seed: the test is deterministic; 5 sd leaves room for any seed).
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> x;
  for (int i = 0; i < 20000; ++i) x.push_back(Vec3(u(rng), u(rng), u(rng)));
  const std::vector<double> r(x.size(), 1e-7);
  const Rdf rdf = radial_distribution(x, r, {3, 0.1, 20});
  for (int b = 2; b < 20; ++b) {
    const double expected = rdf.reference_grains * rdf.density * 4.0 / 3.0 * M_PI *
                            (std::pow(0.005 * (b + 1), 3) - std::pow(0.005 * b, 3));
    EXPECT_NEAR(rdf.g[b], 1.0, 5.0 / std::sqrt(expected)) << b;
  }
}

TEST(Rdf, RefusesBadOptionsAndTooLargeRmax) {
  const test::Lattice l = test::simple_cubic(4, 1.0);
  EXPECT_THROW(radial_distribution(l.position, l.radius, {3, -1.0, 10}), InputError);
  EXPECT_THROW(radial_distribution(l.position, l.radius, {3, 0.0, 10}), InputError);
  EXPECT_THROW(radial_distribution(l.position, l.radius, {3, 1.0, 0}), InputError);
  EXPECT_THROW(radial_distribution(l.position, l.radius, {4, 1.0, 10}), InputError);
  // The box is 4 wide: no centre is 2.1 inside every face.
  EXPECT_THROW(radial_distribution(l.position, l.radius, {3, 2.1, 10}), InputError);
}

}  // namespace
}  // namespace talus::analysis
