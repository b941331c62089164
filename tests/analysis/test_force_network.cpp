// analysis::force_network on made-up pair forces: the means and the fraction
// of contacts within the tolerance of the Coulomb limit (Götz 2024 §5.3.4).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "talus/analysis/force_network.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {
namespace {

TEST(ForceNetwork, MeansAndCoulombFraction) {
  const std::vector<dem::PairContactForce> pairs = {
      {0, 1, 3.0, 4.0, 2.0},   // |F| = 5, far from the limit (4 < 0.95 * 6)
      {1, 2, 1.0, 0.5, 0.5},   // at the limit
      {2, 3, 2.0, 0.96, 0.5},  // 4 % below it: counts
      {3, 4, 2.0, 0.94, 0.5},  // 6 % below it: does not
      {4, 5, 1.0, 0.0, 0.0}};  // frictionless: always at its limit
  const ForceNetwork n = force_network(pairs);
  EXPECT_EQ(n.contacts, 5u);
  EXPECT_NEAR(n.mean_normal, 9.0 / 5, 1e-15);
  EXPECT_NEAR(n.mean_tangential, (4.0 + 0.5 + 0.96 + 0.94) / 5, 1e-15);
  const double mean_force =
      (5.0 + std::hypot(1.0, 0.5) + std::hypot(2.0, 0.96) + std::hypot(2.0, 0.94) + 1.0) / 5;
  EXPECT_NEAR(n.mean_force, mean_force, 1e-15);
  EXPECT_DOUBLE_EQ(n.coulomb_fraction, 3.0 / 5);
  // A tolerance of 10 % takes the fourth contact in too.
  EXPECT_DOUBLE_EQ(force_network(pairs, 0.1).coulomb_fraction, 4.0 / 5);
}

TEST(ForceNetwork, EmptyAndBadTolerance) {
  const ForceNetwork n = force_network({});
  EXPECT_EQ(n.contacts, 0u);
  EXPECT_EQ(n.mean_force, 0.0);
  EXPECT_EQ(n.coulomb_fraction, 0.0);
  EXPECT_THROW(force_network({}, 1.0), InputError);
  EXPECT_THROW(force_network({}, -0.1), InputError);
}

}  // namespace
}  // namespace talus::analysis
