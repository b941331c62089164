// Overlap of turned boxes (geometry/oriented_box.hpp), against cases whose
// answer follows from the drawing.
#include <gtest/gtest.h>

#include <cmath>

#include "talus/geometry/oriented_box.hpp"

namespace talus::geometry {
namespace {

Eigen::Matrix3d about(const Vec3& axis, double degrees) {
  return Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
}

OrientedBox unit_cube_at(const Vec3& centre) {
  return OrientedBox::turned(centre - Vec3::Constant(0.5), centre + Vec3::Constant(0.5),
                             Eigen::Matrix3d::Identity(), Vec3::Zero());
}

TEST(OrientedBox, AlignedCubesOverlapByTheirShift) {
  // Unit cubes 0.75 apart along x share a slab 0.25 thick.
  EXPECT_NEAR(overlap_depth(unit_cube_at(Vec3::Zero()), unit_cube_at(Vec3(0.75, 0.1, 0.0))), 0.25,
              1e-12);
  // Faces touching: depth 0 (a block resting on a plate is not an overlap).
  EXPECT_NEAR(overlap_depth(unit_cube_at(Vec3::Zero()), unit_cube_at(Vec3(1.0, 0.0, 0.0))), 0.0,
              1e-12);
  EXPECT_LT(overlap_depth(unit_cube_at(Vec3::Zero()), unit_cube_at(Vec3(1.2, 0.0, 0.0))), 0.0);
}

TEST(OrientedBox, TurnedAboutAPivotMovesTheCentre) {
  // The box [1, 2] x [0, 1] x [0, 1] turned 90 deg about z through the origin
  // lies in [-1, 0] x [1, 2] x [0, 1].
  const auto b =
      OrientedBox::turned(Vec3(1, 0, 0), Vec3(2, 1, 1), about(Vec3::UnitZ(), 90.0), Vec3::Zero());
  EXPECT_NEAR((b.centre - Vec3(-0.5, 1.5, 0.5)).norm(), 0.0, 1e-12);
  EXPECT_GT(overlap_depth(b, unit_cube_at(Vec3(-0.5, 1.5, 0.5))), 0.99);
  EXPECT_LE(overlap_depth(b, unit_cube_at(Vec3(0.5, 0.5, 0.5))), 1e-12);
}

TEST(OrientedBox, CornerOfATurnedCubeReachesIn) {
  // A unit cube turned 45 deg about z reaches sqrt(2)/2 from its centre along
  // x: at a centre distance of 1.1 it pokes 0.5 + 0.7071 - 1.1 into an aligned
  // cube.
  const auto a = unit_cube_at(Vec3::Zero());
  auto b = OrientedBox::turned(Vec3::Constant(-0.5), Vec3::Constant(0.5),
                               about(Vec3::UnitZ(), 45.0), Vec3::Zero());
  b.centre = Vec3(1.1, 0.0, 0.0);
  EXPECT_NEAR(overlap_depth(a, b), 0.5 + std::sqrt(0.5) - 1.1, 1e-12);
  b.centre = Vec3(1.25, 0.0, 0.0);
  EXPECT_LT(overlap_depth(a, b), 0.0);
}

TEST(OrientedBox, EdgeAgainstEdgeNeedsTheCrossAxes) {
  // Two long bars of diamond section (0.2 x 0.2 turned 45 deg about their own
  // axis), one along x, one along y above it at height h: the lower one's top
  // edge and the upper one's bottom edge cross. Every face normal meets a bar's
  // 10 m length; only the cross product of the long edges (z) separates them.
  // Each bar reaches 0.1 sqrt(2) along z, so the depth is 0.2 sqrt(2) - h.
  const auto along_x = OrientedBox::turned(Vec3(-5, -0.1, -0.1), Vec3(5, 0.1, 0.1),
                                           about(Vec3::UnitX(), 45.0), Vec3::Zero());
  for (double h : {0.25, 0.3}) {
    const Vec3 c(0.0, 0.0, h);
    const auto along_y = OrientedBox::turned(c - Vec3(0.1, 5, 0.1), c + Vec3(0.1, 5, 0.1),
                                             about(Vec3::UnitY(), 45.0), c);
    EXPECT_NEAR(overlap_depth(along_x, along_y), 0.2 * std::sqrt(2.0) - h, 1e-12) << h;
  }
}

}  // namespace
}  // namespace talus::geometry
