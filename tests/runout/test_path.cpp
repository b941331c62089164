// The 1D runout path: the flume (from geometry::FlumeGeometry) and profiles.
#include <gtest/gtest.h>

#include <cmath>

#include "talus/core/error.hpp"
#include "talus/runout/path.hpp"

namespace talus::runout {
namespace {

TEST(RunoutPath, FlumeFollowsFlumeGeometry) {
  const auto flume = geometry::make_flume({deg2rad(33), 0.10, {}, {}});
  const auto path = path_from_flume(flume, 0.35, 1e-3);
  EXPECT_DOUBLE_EQ(path.s_begin(), flume.chute_start_s());
  EXPECT_NEAR(path.s_end(), flume.path_end_s(), 1e-12);
  for (double s = path.s_begin(); s < path.s_end(); s += 0.0137) {
    // Linear interpolation between samples 1 mm apart on an arc of radius
    // 0.1 m: chord error ds^2 / (8 R) = 1.25e-6 m.
    EXPECT_LT((path.point(s) - flume.point_at(s)).norm(), 2e-6) << s;
    EXPECT_DOUBLE_EQ(path.width(s), 0.35);
  }
  // Curvature 1/R inside the arc, 0 on chute and barrier (away from the
  // joints, where the table spreads the jump over one sample).
  const double mid_arc = 0.5 * (flume.chute_end_s() + flume.arc_end_s());
  EXPECT_NEAR(path.curvature(mid_arc), 10.0, 1e-6);
  EXPECT_NEAR(path.curvature(0.0), 0.0, 1e-9);
  EXPECT_NEAR(path.curvature(flume.arc_end_s() + 0.1), 0.0, 1e-9);
  // Chute at -29 deg, barrier at +33 deg.
  EXPECT_NEAR(path.angle(0.0), -29.0 * M_PI / 180, 1e-12);
  EXPECT_NEAR(path.angle(flume.arc_end_s() + 0.1), 33.0 * M_PI / 180, 1e-12);
  // s_at_x inverts x(s): the gate foot is at x = 0.5276, s = 0.
  EXPECT_NEAR(path.s_at_x(geometry::kFlumeGateX), 0.0, 1e-9);
  EXPECT_NEAR(path.s_at_x(path.point(1.7).x()), 1.7, 1e-9);
}

TEST(RunoutPath, ProfileStraightLineIsExact) {
  const auto path = path_from_profile({{0, 1}, {2, 0}}, {1, 3}, 0.0, 1e-2);
  const double len = std::sqrt(5.0);
  EXPECT_NEAR(path.s_end(), len, 1e-12);
  EXPECT_NEAR((path.point(len / 2) - Vec2(1, 0.5)).norm(), 0, 1e-12);
  EXPECT_NEAR(path.width(len / 2), 2.0, 1e-12);
  EXPECT_NEAR(path.curvature(1.0), 0.0, 1e-12);
  EXPECT_NEAR(path.angle(0.3), std::atan2(-1, 2), 1e-12);
}

TEST(RunoutPath, ProfileKinkIsSmoothed) {
  // A 30 deg incline meeting a flat: the smoothed path turns through the full
  // 30 deg, spread over the smoothing window (so the curvature there is about
  // (pi/6) / window), and keeps both end tangents.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const auto path = path_from_profile({{0, s}, {c, 0}, {3, 0}}, {1, 1, 1}, 0.2, 1e-3);
  EXPECT_NEAR(path.angle(0.1), -M_PI / 6, 1e-12);
  EXPECT_NEAR(path.angle(path.s_end() - 0.1), 0.0, 1e-12);
  EXPECT_NEAR(path.curvature(1.0), (M_PI / 6) / 0.2, 0.05 * (M_PI / 6) / 0.2);
  // Rebuilding from the averaged angle lowers the flat by the integral of
  // sin(ramp) - sin(step) over the window: 1.2 mm for this kink.
  EXPECT_NEAR(path.point(path.s_end()).y(), 0.0, 2e-3);
}

TEST(RunoutPath, ProfileRejectsBadPoints) {
  EXPECT_THROW(path_from_profile({{0, 0}}, {1}, 0, 1e-3), InputError);
  EXPECT_THROW(path_from_profile({{0, 0}, {0, 1}}, {1, 1}, 0, 1e-3), InputError);
  EXPECT_THROW(path_from_profile({{0, 0}, {1, 1}}, {1, 0}, 0, 1e-3), InputError);
}

}  // namespace
}  // namespace talus::runout
