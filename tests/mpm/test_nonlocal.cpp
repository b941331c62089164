// The non-local average that drives the regularised cohesion loss
// (mpm/nonlocal.hpp): a uniform field is kept, and a single dilating point
// spreads its value over a fixed physical neighbourhood (at most 2 ell away,
// the tent functions' reach there and back) whatever the point spacing.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "talus/mpm/nonlocal.hpp"

namespace talus::mpm {
namespace {

// Points on a square lattice of the given spacing over [0, 0.2]^2.
Particles<2> lattice(double spacing, std::vector<int>& list) {
  Particles<2> p;
  const int n = static_cast<int>(std::lround(0.2 / spacing));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      list.push_back(static_cast<int>(p.size()));
      p.add(Eigen::Vector2d((i + 0.5) * spacing, (j + 0.5) * spacing), Eigen::Vector2d::Zero(), 1.0,
            spacing * spacing, 0, MaterialState{});
    }
  return p;
}

TEST(MpmNonlocal, UniformFieldIsKept) {
  std::vector<int> list;
  const Particles<2> p = lattice(0.005, list);
  std::vector<double> values(list.size(), 0.3), scratch;
  nonlocal_average(p, list, 0.02, values, scratch);
  for (double v : values) EXPECT_NEAR(v, 0.3, 1e-14);
}

// One point near the middle dilates (value x volume = 1, the same dilated
// volume on both lattices, 5 mm and 2.5 mm): the average is zero beyond
// 2 ell = 4 cm and positive next to it, and the volume-weighted total is kept
// exactly: with tents summing to 1 at each point, sum_k V_k avg_k =
// sum_a (M_a / W_a) sum_k w_ka V_k = sum_a M_a = sum_q V_q e_q (round-off).
TEST(MpmNonlocal, OnePointSpreadsOverAFixedLength) {
  const double ell = 0.02;
  for (const double spacing : {0.005, 0.0025}) {
    std::vector<int> list;
    const Particles<2> p = lattice(spacing, list);
    std::vector<double> values(list.size(), 0.0), scratch;
    std::size_t centre = 0;
    for (std::size_t k = 0; k < list.size(); ++k)
      if ((p.x[k] - Eigen::Vector2d(0.1, 0.1)).norm() <
          (p.x[centre] - Eigen::Vector2d(0.1, 0.1)).norm())
        centre = k;
    values[centre] = 1.0 / (spacing * spacing);
    nonlocal_average(p, list, ell, values, scratch);
    double total = 0.0;
    for (std::size_t k = 0; k < list.size(); ++k) {
      const double r = (p.x[k] - p.x[centre]).cwiseAbs().maxCoeff();
      if (r >= 2.0 * ell) {
        EXPECT_EQ(values[k], 0.0) << r;
      } else if (r < 0.5 * ell) {
        EXPECT_GT(values[k], 0.0) << r;
      }
      total += values[k] * p.volume[k];
    }
    EXPECT_NEAR(total, 1.0, 1e-12) << spacing;
  }
}

}  // namespace
}  // namespace talus::mpm
