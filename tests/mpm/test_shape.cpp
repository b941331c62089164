// Shape functions: partition of unity, gradients summing to zero, and linear
// completeness (sum N_i x_i = x, sum x_i (x) grad N_i = I) at random points,
// for every shape type in 2D and 3D. These are exact identities of the linear
// hat, uniform GIMP and uniform cubic B-spline on a regular grid (mpm.md:
// "partition of unity must hold everywhere"), so the tolerance is round-off.
#include <gtest/gtest.h>

#include <random>

#include "talus/mpm/grid.hpp"

namespace talus::mpm {
namespace {

template <int D, class Shape>
void check_identities(double half_width) {
  using Vec = typename Space<D>::Vec;
  std::array<BoundaryKind, 2 * D> faces;
  faces.fill(BoundaryKind::Free);
  const Vec lo = Vec::Constant(-0.3), hi = Vec::Constant(0.7);
  const Grid<D> grid(lo, hi, 0.1, faces);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Stencil<D, Shape> st;
  for (int trial = 0; trial < 2000; ++trial) {
    Vec x;
    for (int d = 0; d < D; ++d) x[d] = lo[d] + u(rng) * (hi[d] - lo[d]);
    ASSERT_TRUE(st.compute(grid, x, half_width));
    double sum = 0.0;
    Vec grad_sum = Vec::Zero(), x_sum = Vec::Zero();
    Eigen::Matrix<double, D, D> reproduce = Eigen::Matrix<double, D, D>::Zero();
    for (int k = 0; k < st.count; ++k) {
      EXPECT_GE(st.w[k], -1e-15);
      std::array<int, D> i;
      std::int64_t rest = st.node[k];
      for (int d = 0; d < D; ++d) {
        i[d] = static_cast<int>(rest % grid.n[d]);
        rest /= grid.n[d];
      }
      const Vec xi = grid.node_position(i);
      sum += st.w[k];
      grad_sum += st.grad[k];
      x_sum += st.w[k] * xi;
      reproduce += xi * st.grad[k].transpose();
    }
    EXPECT_NEAR(sum, 1.0, 1e-13) << Shape::name << " at " << x.transpose();
    EXPECT_NEAR(grad_sum.norm(), 0.0, 1e-10) << Shape::name;
    EXPECT_NEAR((x_sum - x).norm(), 0.0, 1e-13) << Shape::name;
    const auto identity = Eigen::Matrix<double, D, D>::Identity();
    EXPECT_NEAR((reproduce - identity).norm(), 0.0, 1e-10) << Shape::name;
  }
}

TEST(MpmShape, LinearIdentities2D) { check_identities<2, LinearShape>(0.0); }
TEST(MpmShape, LinearIdentities3D) { check_identities<3, LinearShape>(0.0); }
TEST(MpmShape, GimpIdentities2D) { check_identities<2, GimpShape>(0.25); }
TEST(MpmShape, GimpIdentities3D) { check_identities<3, GimpShape>(0.25); }
TEST(MpmShape, GimpIdentitiesWidestParticle) { check_identities<2, GimpShape>(0.5); }
TEST(MpmShape, CubicBSplineIdentities2D) { check_identities<2, CubicBSplineShape>(0.0); }
TEST(MpmShape, CubicBSplineIdentities3D) { check_identities<3, CubicBSplineShape>(0.0); }

// The 1D weights against the formulas written out in mpm.md and in
// Bardenhagen & Kober (2004), at hand-computed points.
TEST(MpmShape, OneDimensionalValues) {
  double w, dw;
  CubicBSplineShape::eval(0.0, 0.0, w, dw);
  EXPECT_NEAR(w, 2.0 / 3.0, 1e-15);  // N(0) = 2/3
  CubicBSplineShape::eval(1.0, 0.0, w, dw);
  EXPECT_NEAR(w, 1.0 / 6.0, 1e-15);  // -1/6 + 1 - 2 + 4/3
  EXPECT_NEAR(dw, -0.5, 1e-15);      // -1/2 + 2 - 2
  CubicBSplineShape::eval(-1.5, 0.0, w, dw);
  EXPECT_NEAR(w, 0.5 * 0.5 * 0.5 / 6.0, 1e-15);  // (2 - |x|)^3 / 6
  GimpShape::eval(0.0, 0.25, w, dw);
  EXPECT_NEAR(w, 1.0 - 0.25 / 2.0, 1e-15);  // 1 - l/2 at the node
  GimpShape::eval(1.0, 0.25, w, dw);
  EXPECT_NEAR(w, 0.25 / 4.0, 1e-15);  // l/4 one cell away
  LinearShape::eval(0.3, 0.0, w, dw);
  EXPECT_NEAR(w, 0.7, 1e-15);
  EXPECT_EQ(dw, -1.0);
}

// A particle that left the grid is reported, not read out of bounds.
TEST(MpmShape, OutsideTheGridIsRefused) {
  const std::array<BoundaryKind, 4> faces{};
  const Grid<2> grid(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), 0.1, faces);
  Stencil<2, CubicBSplineShape> st;
  EXPECT_TRUE(st.compute(grid, Eigen::Vector2d(0.99, 0.01), 0.0));
  EXPECT_FALSE(st.compute(grid, Eigen::Vector2d(1.5, 0.5), 0.0));
  EXPECT_FALSE(st.compute(grid, Eigen::Vector2d(std::nan(""), 0.5), 0.0));
}

}  // namespace
}  // namespace talus::mpm
