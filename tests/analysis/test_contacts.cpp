// Contact number from the grains' geometry: lattices of touching spheres and disks, and the
// rounds of rattler removal on a hand-made 2D cluster.
#include <gtest/gtest.h>

#include <cmath>

#include "lattices.hpp"
#include "talus/analysis/cell_list.hpp"
#include "talus/analysis/contacts.hpp"

namespace talus::analysis {
namespace {

using test::Lattice;

// Touching lattice grains are exactly r_i + r_j apart up to the round-off of a * i (~1e-19 m
// at a = 1 mm); a gap tolerance of 1e-9 a takes them in and nothing else (the next distance is
// sqrt(2) a in both lattices).
constexpr double kA = 1e-3, kGap = 1e-9 * kA;

TEST(ContactNumber, SimpleCubicLatticeHasSixContactsInside) {
  const int n = 5;
  const Lattice l = test::simple_cubic(n, kA);
  const auto count = contact_counts(l.position, l.radius, kGap);
  for (std::size_t g = 0; g < count.size(); ++g) {
    // Neighbours missing at the block's faces: 6 inside, 5 on a face, 4 on an edge, 3 at a corner.
    int faces = 0;
    for (int d = 0; d < 3; ++d) {
      const long c = std::lround(l.position[g][d] / kA);
      faces += c == 0 || c == n - 1;
    }
    EXPECT_EQ(count[g], 6 - faces) << g;
  }
  // 3 n^2 (n - 1) pairs: z = 6 (n - 1) / n = 4.8 for n = 5, exactly.
  const ContactNumber z = contact_number(l.position, l.radius, 4, kGap);
  EXPECT_EQ(z.contacts, 300u);
  EXPECT_DOUBLE_EQ(z.z, 4.8);
}

TEST(ContactNumber, FccLatticeHasTwelveContactsInside) {
  const int n = 4;
  const Lattice l = test::fcc(n, kA);
  const auto count = contact_counts(l.position, l.radius, kGap);
  int inside = 0;
  for (std::size_t g = 0; g < count.size(); ++g) {
    EXPECT_LE(count[g], 12);
    // A centre at least a/2 inside the block's outermost planes has all 12 neighbours.
    const Vec3& x = l.position[g];
    if (x.minCoeff() >= 0.5 * kA - 1e-12 && x.maxCoeff() <= (n - 1) * kA + 1e-12) {
      EXPECT_EQ(count[g], 12) << g;
      ++inside;
    }
  }
  EXPECT_GT(inside, 50);
}

TEST(ContactNumber, OverlapCountsWithoutToleranceAndGapsDoNot) {
  // Compressed by 0.1 %: every neighbour pair overlaps, so gap = 0 (the DEM's own definition)
  // finds all of them; stretched by 0.1 % none touch.
  Lattice l = test::simple_cubic(4, kA);
  for (auto& x : l.position) x *= 0.999;
  EXPECT_EQ(contact_number(l.position, l.radius, 4).contacts, 3u * 16 * 3);
  for (auto& x : l.position) x *= 1.002 / 0.999;
  EXPECT_EQ(contact_number(l.position, l.radius, 4).contacts, 0u);
  // ... unless the gap tolerance reaches across the 0.2 % gaps (2e-6 m).
  EXPECT_EQ(contact_number(l.position, l.radius, 4, 3e-6).contacts, 3u * 16 * 3);
}

TEST(ContactNumber, RattlersAreRemovedInRounds) {
  // 2D, threshold 3 (D + 1): a hexagonal rosette (a centre touching six, each ring disk touching
  // the centre and its two ring neighbours: 12 contacts, none below 3), a disk X in the notch
  // between two ring disks (3 contacts: both ring disks and Y), and Y touching only X.
  // Round 1 removes Y (1 contact); X is left with 2 and goes in round 2; the rosette stays.
  Lattice l;
  l.position.push_back(Vec3::Zero());
  for (int k = 0; k < 6; ++k)
    l.position.push_back(kA * Vec3(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0));
  const Vec3 x = l.position[1] + l.position[2];  // touches ring disks 1 and 2, sqrt(3) a out
  l.position.push_back(x);
  l.position.push_back(x + kA * Vec3(std::cos(M_PI / 6), std::sin(M_PI / 6), 0));
  l.radius.assign(l.position.size(), 0.5 * kA);
  const ContactNumber z = contact_number(l.position, l.radius, 3, kGap);
  EXPECT_EQ(z.grains, 9u);
  EXPECT_EQ(z.contacts, 15u);         // 12 + X's 3
  EXPECT_DOUBLE_EQ(z.z, 30.0 / 9.0);  // the source's z over all grains
  EXPECT_EQ(z.rattlers, 2u);          // Y, then X
  EXPECT_DOUBLE_EQ(z.z_no_rattlers, 24.0 / 7.0);
  // With threshold 0 nothing is a rattler.
  EXPECT_EQ(contact_number(l.position, l.radius, 0, kGap).rattlers, 0u);
}

TEST(CellList, FindsTheSamePairsAsAllPairs) {
  // Random points, some far away from the others: the sorted-key cell list must find exactly
  // the pairs closer than the cutoff that the O(N^2) loop finds.
  std::vector<Vec3> x;
  unsigned s = 12345;
  auto u = [&] { return (s = s * 1103515245u + 12345u) / 4294967296.0; };
  for (int i = 0; i < 400; ++i) x.push_back(Vec3(u(), u(), u()) * (i % 50 == 0 ? 100.0 : 1.0));
  const double cut = 0.15;
  std::size_t pairs = 0, brute = 0;
  CellList(x, cut).for_each_pair([&](std::size_t i, std::size_t j, double d) {
    ++pairs;
    EXPECT_LT(i, j);
    EXPECT_NEAR(d, (x[i] - x[j]).norm(), 1e-15);
  });
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j) brute += (x[i] - x[j]).norm() < cut;
  EXPECT_EQ(pairs, brute);
  EXPECT_GT(brute, 500u);
}

}  // namespace
}  // namespace talus::analysis
