// The Mancarella & Hungr flume against Kuen (2011) Table 2 as corrected in
// /work/shared/spec/flume.md, and its path coordinate.
#include <gtest/gtest.h>

#include "talus/core/error.hpp"
#include "talus/geometry/flume.hpp"
#include "talus/geometry/wall.hpp"

namespace talus::geometry {
namespace {

struct Row {
  double beta, radius, l_star;
  Vec2 w1_end, w2_centre, w3_start, w3_end;
  double arc_end_deg;
};

// Copied from flume.md (corrected table), metres.
const Row kRows[] = {
    {7, 0.10, 1.6875, {1.4475, 0.3126}, {1.4960, 0.4001}, {1.5082, 0.3008}, {2.2523, 0.3922}, 277},
    {13, 0.10, 1.7018, {1.4549, 0.3086}, {1.5033, 0.3960}, {1.5258, 0.2986}, {2.1990, 0.4540}, 283},
    {22, 0.10, 1.7075, {1.4517, 0.3103}, {1.5002, 0.3978}, {1.5376, 0.3050}, {2.2850, 0.6070}, 292},
    {33, 0.02, 1.7194, {1.4933, 0.2872}, {1.5030, 0.3047}, {1.5139, 0.2879}, {2.4410, 0.8900}, 303},
    {33, 0.10, 1.7163, {1.4486, 0.3121}, {1.4970, 0.3995}, {1.5515, 0.3156}, {2.4390, 0.8920}, 303},
    {33, 0.26, 1.7179, {1.3658, 0.3579}, {1.4919, 0.5853}, {1.6335, 0.3672}, {2.4400, 0.8910}, 303},
    {61, 0.02, 1.7569, {1.5192, 0.2729}, {1.5291, 0.2904}, {1.5464, 0.2807}, {2.0210, 1.1370}, 331},
    {61, 0.10, 1.7570, {1.4492, 0.3117}, {1.4977, 0.3991}, {1.5852, 0.3507}, {1.9030, 0.9240}, 331},
};

constexpr double kHalfMm = 0.5e-3;

// Where the lines a0-a1 and b0-b1 meet.
Vec2 intersect(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  const Vec2 da = a1 - a0, db = b1 - b0, r = b0 - a0;
  const double t = (r.x() * db.y() - r.y() * db.x()) / (da.x() * db.y() - da.y() * db.x());
  return a0 + t * da;
}

TEST(Flume, ReproducesEveryRowOfTheCorrectedTable) {
  for (const Row& row : kRows) {
    SCOPED_TRACE(testing::Message() << "beta " << row.beta << " R " << row.radius);
    const FlumeGeometry f = make_flume({deg2rad(row.beta), row.radius, {}, {}});
    EXPECT_NEAR((f.chute_start - Vec2(0, 1.115)).norm(), 0, 1e-12);
    EXPECT_LT((f.chute_end - row.w1_end).norm(), kHalfMm);
    EXPECT_LT((f.arc_centre - row.w2_centre).norm(), kHalfMm);
    EXPECT_LT((f.barrier_start - row.w3_start).norm(), kHalfMm);
    EXPECT_LT((f.barrier_end - row.w3_end).norm(), kHalfMm);
    EXPECT_NEAR(rad2deg(f.arc_angle_start), 241.0, 1e-9);
    EXPECT_NEAR(rad2deg(f.arc_angle_end), row.arc_end_deg, 1e-9);
    // L*: chute top to the meeting point of the built chute and barrier lines.
    const Vec2 corner = intersect(f.chute_start, f.chute_end, f.barrier_start, f.barrier_end);
    EXPECT_NEAR((corner - f.chute_start).norm(), row.l_star, kHalfMm);
    // Tangency: both straight pieces end at R from the centre, perpendicular to the radius.
    EXPECT_NEAR((f.chute_end - f.arc_centre).norm(), row.radius, 1e-12);
    EXPECT_NEAR((f.barrier_start - f.arc_centre).norm(), row.radius, 1e-12);
    EXPECT_NEAR((f.chute_end - f.arc_centre).dot(f.chute_end - f.chute_start), 0, 1e-12);
    EXPECT_NEAR((f.barrier_start - f.arc_centre).dot(f.barrier_end - f.barrier_start), 0, 1e-12);
  }
}

TEST(Flume, GateLidAndReleaseTriangle) {
  const FlumeGeometry f = make_flume({deg2rad(33), 0.10, {}, {}});
  // Table 3: W4 (0.5276, 0.8226)-(0.5276, 1.1150), W5 to (0, 1.1150).
  EXPECT_LT((f.gate_bottom - Vec2(0.5276, 0.8226)).norm(), kHalfMm);
  EXPECT_NEAR((f.gate_top - Vec2(0.5276, 1.1150)).norm(), 0, 1e-12);
  EXPECT_NEAR((f.lid_end - Vec2(0, 1.1150)).norm(), 0, 1e-12);
  // The gate foot is exactly on the chute line: y = 1.115 - 0.5276 tan 29 deg.
  EXPECT_NEAR(f.gate_bottom.y(), 1.115 - 0.5276 * std::tan(deg2rad(29)), 1e-12);
  // flume.md: area 0.07714 m^2 (= 0.5276 * 0.2924 / 2).
  EXPECT_NEAR(f.release_area(), 0.07714, 1e-5);
}

TEST(Flume, PathCoordinateAlongChuteArcAndBarrier) {
  const FlumeGeometry f = make_flume({deg2rad(33), 0.10, {}, {}});
  // s = 0 at the gate foot; the chute top is 0.5276 / cos 29 deg = 0.603227 upstream.
  EXPECT_NEAR(f.chute_start_s(), -0.5276 / std::cos(deg2rad(29)), 1e-12);
  EXPECT_NEAR((f.point_at(0) - f.gate_bottom).norm(), 0, 1e-12);
  EXPECT_NEAR((f.point_at(f.chute_start_s()) - f.chute_start).norm(), 0, 1e-12);
  // W1 length (1.7163 - 0.1 tan 31 deg = 1.656214) minus 0.603227.
  EXPECT_NEAR(f.chute_end_s(),
              1.7163 - 0.1 * std::tan(deg2rad(31)) - 0.5276 / std::cos(deg2rad(29)), 1e-12);
  // The arc spans 29 + 33 = 62 deg: length 0.1 * 62 pi / 180 = 0.108210.
  EXPECT_NEAR(f.arc_end_s() - f.chute_end_s(), 0.1 * deg2rad(62), 1e-12);
  EXPECT_NEAR((f.point_at(f.chute_end_s()) - f.chute_end).norm(), 0, 1e-12);
  EXPECT_NEAR((f.point_at(f.arc_end_s()) - f.barrier_start).norm(), 0, 1e-12);
  EXPECT_NEAR((f.point_at(f.path_end_s()) - f.barrier_end).norm(), 0, 1e-12);

  const double h = 1e-6;
  for (double s = f.chute_start_s(); s <= f.path_end_s(); s += 0.0137) {
    SCOPED_TRACE(s);
    const Vec2 x = f.point_at(s), t = f.tangent_at(s);
    EXPECT_NEAR(f.path_coordinate(x), s, 1e-9);
    EXPECT_NEAR(t.norm(), 1, 1e-12);
    EXPECT_NEAR((t - (f.point_at(s + h) - f.point_at(s - h)) / (2 * h)).norm(), 0, 1e-6);
    // A point 5 cm above the path (on the flow side, left of the tangent)
    // projects back to the same s (the arc radius is 0.1 > 0.05).
    EXPECT_NEAR(f.path_coordinate(x + 0.05 * Vec2(-t.y(), t.x())), s, 1e-9);
  }
}

TEST(Flume, OtherGeometriesInterpolateOrTakeExplicitValues) {
  // Test 10 (45 deg, R = 0.10): between the 33 and 61 deg rows, weight 12/28:
  // L* = 1.7163 + (12/28)(1.7570 - 1.7163) = 1.733743.
  EXPECT_NEAR(flume_l_star(45, 0.10), 1.7163 + 12.0 / 28 * (1.7570 - 1.7163), 1e-12);
  EXPECT_NEAR(flume_l_star(3, 0.10), 1.6875, 1e-12);   // below the first row
  EXPECT_NEAR(flume_l_star(33, 0.05), 1.7163, 1e-12);  // R = 0.10 rows are the reference
  const FlumeGeometry f = make_flume({deg2rad(45), 0.05, 1.8, 1.0});
  EXPECT_NEAR(f.l_star, 1.8, 0);
  const Vec2 corner = intersect(f.chute_start, f.chute_end, f.barrier_start, f.barrier_end);
  EXPECT_NEAR((corner - f.chute_start).norm(), 1.8, 1e-12);
  EXPECT_NEAR((f.barrier_end - corner).norm(), 1.0, 1e-12);
}

TEST(Flume, RejectsGeometriesThatDoNotFit) {
  EXPECT_THROW(make_flume({deg2rad(0), 0.1, {}, {}}), InputError);
  EXPECT_THROW(make_flume({deg2rad(95), 0.1, {}, {}}), InputError);
  EXPECT_THROW(make_flume({deg2rad(33), 0, {}, {}}), InputError);
  EXPECT_THROW(make_flume({deg2rad(33), 2.0, {}, {}}),
               InputError);  // arc would start above the gate
  EXPECT_THROW(make_flume({deg2rad(33), 0.1, std::nullopt, 0.01}), InputError);
}

TEST(Flume, WallParamsBuildTwoDimensionalWallsOnThePath) {
  const FlumeGeometry f = make_flume({deg2rad(7), 0.10, {}, {}});
  const FlumeWalls w = f.walls("metal");
  for (const WallParams* p : {&w.chute, &w.arc, &w.barrier, &w.gate, &w.lid}) {
    EXPECT_EQ(p->material, "metal");
    const Wall wall = make_wall(*p, 0, 2);
    EXPECT_EQ(wall.current.size(), 1u);
  }
  // The middle of the arc (path coordinate) lies on the arc wall.
  const Wall arc = make_wall(w.arc, 0, 2);
  Closest<2> c;
  const Vec2 mid = f.point_at(0.5 * (f.chute_end_s() + f.arc_end_s()));
  ASSERT_TRUE(closest_point<2>(arc.current[0], mid, 1e-3, c));
  EXPECT_NEAR(c.distance, 0, 1e-12);
  EXPECT_EQ(w.gate.a, Space<2>::to3(f.gate_bottom));
}

}  // namespace
}  // namespace talus::geometry
