// Closest points and bounding boxes of every primitive kind. Expected values
// are worked out by hand in the comments (Pythagoras, law of cosines).
#include <gtest/gtest.h>

#include <random>

#include "talus/geometry/primitive.hpp"

namespace talus::geometry {
namespace {

using V2 = Eigen::Vector2d;
constexpr double kTol = 1e-12;

Primitive segment(const Vec3& a, const Vec3& b) {
  Primitive p;
  p.kind = PrimitiveKind::Segment;
  p.p0 = a;
  p.p1 = b;
  return p;
}

Primitive arc(const Vec3& c, double r, double a0, double a1) {
  Primitive p;
  p.kind = PrimitiveKind::Arc;
  p.p0 = c;
  p.radius = r;
  p.angle_start = a0;
  p.angle_end = a1;
  return p;
}

Primitive plane(const Vec3& point, const Vec3& normal) {
  Primitive p;
  p.kind = PrimitiveKind::Plane;
  p.p0 = point;
  p.n = normal.normalized();
  return p;
}

Primitive cylinder(const Vec3& point, const Vec3& axis, double r, bool inside,
                   double length = kInf) {
  Primitive p;
  p.kind = PrimitiveKind::Cylinder;
  p.p0 = point;
  p.n = axis.normalized();
  p.radius = r;
  p.inside = inside;
  p.length = length;
  return p;
}

// The unit triangle of side 2 in the xy plane: a = 0, b = 2x, c = 2y, n = +z.
Primitive triangle() {
  Primitive p;
  EXPECT_TRUE(make_triangle(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), p));
  return p;
}

template <int D>
void expect_closest(const Primitive& p, const typename Space<D>::Vec& x,
                    const typename Space<D>::Vec& point, const typename Space<D>::Vec& normal,
                    double distance) {
  Closest<D> c;
  ASSERT_TRUE(closest_point<D>(p, x, 100.0, c));
  EXPECT_NEAR((c.point - point).norm(), 0, kTol) << c.point.transpose();
  EXPECT_NEAR((c.normal - normal).norm(), 0, kTol) << c.normal.transpose();
  EXPECT_NEAR(c.distance, distance, kTol);
}

TEST(Segment2D, InteriorBothSidesAndEnds) {
  const Primitive s = segment(Vec3(0, 0, 0), Vec3(2, 0, 0));
  expect_closest<2>(s, V2(1, 0.5), V2(1, 0), V2(0, 1), 0.5);
  expect_closest<2>(s, V2(1, -0.5), V2(1, 0), V2(0, -1), 0.5);
  // Beyond the end b = (2,0): offset (1,1), distance sqrt 2.
  expect_closest<2>(s, V2(3, 1), V2(2, 0), V2(1, 1).normalized(), std::sqrt(2.0));
  expect_closest<2>(s, V2(-1, 0), V2(0, 0), V2(-1, 0), 1.0);
  Closest<2> c;
  EXPECT_FALSE(closest_point<2>(s, V2(1, 0.5), 0.4, c));  // 0.5 > cutoff
  // On the segment: any unit normal perpendicular to it.
  ASSERT_TRUE(closest_point<2>(s, V2(1, 0), 0.1, c));
  EXPECT_NEAR(c.distance, 0, kTol);
  EXPECT_NEAR(c.normal.norm(), 1, kTol);
  EXPECT_NEAR(c.normal.x(), 0, kTol);
}

TEST(Arc2D, InsideOutsideAndBeyondTheEnds) {
  // Quarter circle, centre (1,1), R = 2, from 0 to 90 deg.
  const Primitive a = arc(Vec3(1, 1, 0), 2.0, 0.0, M_PI / 2);
  const V2 c(1, 1), u30(std::cos(M_PI / 6), std::sin(M_PI / 6)), u60(0.5, std::sqrt(3.0) / 2);
  // Inside at radius 1.5: 0.5 from the arc, pushed towards the centre.
  expect_closest<2>(a, c + 1.5 * u30, c + 2 * u30, -u30, 0.5);
  // Outside at radius 3: 1 from the arc, pushed outwards.
  expect_closest<2>(a, c + 3 * u60, c + 2 * u60, u60, 1.0);
  // At 180 deg, x = (-1,1): ends (3,1) at 4 and (1,3) at sqrt(8): the 90 deg end.
  expect_closest<2>(a, V2(-1, 1), V2(1, 3), V2(-1, -1).normalized(), std::sqrt(8.0));
  // At -45 deg, radius 2.5: the 0 deg end (3,1); law of cosines
  // d^2 = 2.5^2 + 2^2 - 2 * 2.5 * 2 cos 45 deg = 3.1789322.
  const V2 x = c + 2.5 * V2(std::cos(-M_PI / 4), std::sin(-M_PI / 4));
  expect_closest<2>(a, x, V2(3, 1), (x - V2(3, 1)).normalized(), std::sqrt(3.1789321881345245));
  // The centre itself: every arc point is at R; the mid angle (45 deg) is taken.
  const V2 u45 = V2(1, 1).normalized();
  expect_closest<2>(a, c, c + 2 * u45, -u45, 2.0);
  Closest<2> out;
  EXPECT_FALSE(closest_point<2>(a, c + 3 * u60, 0.9, out));  // distance 1 > cutoff
}

TEST(Arc2D, AnglesAboveTwoPiAndFullCircle) {
  // Right half circle given as 270..450 deg: angle 0 (= 360 deg) is inside.
  const Primitive right = arc(Vec3(0, 0, 0), 2.0, 1.5 * M_PI, 2.5 * M_PI);
  expect_closest<2>(right, V2(0.5, 0), V2(2, 0), V2(-1, 0), 1.5);
  // (-1, 0.5) is on the left: ends (0,-2) at sqrt(1 + 6.25), (0,2) at sqrt(1 + 2.25).
  expect_closest<2>(right, V2(-1, 0.5), V2(0, 2), V2(-1, -1.5).normalized(), std::sqrt(3.25));
  // A full circle has no ends: (-3, 0) is 1 from (-2, 0).
  const Primitive full = arc(Vec3(0, 0, 0), 2.0, 1.0, 1.0 + 2 * M_PI);
  expect_closest<2>(full, V2(-3, 0), V2(-2, 0), V2(-1, 0), 1.0);
}

TEST(Plane, TwoSidedIn2DAnd3D) {
  // 2D: the line y = 1.
  const Primitive line = plane(Vec3(0, 1, 0), Vec3(0, 1, 0));
  expect_closest<2>(line, V2(5, 3), V2(5, 1), V2(0, 1), 2.0);
  expect_closest<2>(line, V2(5, -1), V2(5, 1), V2(0, -1), 2.0);
  // 3D: tilted plane through p0 with n = (1,1,1)/sqrt 3; x = p0 + 2n + (1,-1,0)
  // (the last part lies in the plane).
  const Vec3 p0(1, 2, 3), n = Vec3(1, 1, 1).normalized();
  const Primitive p = plane(p0, n);
  expect_closest<3>(p, Vec3(p0 + 2 * n + Vec3(1, -1, 0)), Vec3(p0 + Vec3(1, -1, 0)), n, 2.0);
  expect_closest<3>(p, Vec3(p0 - 0.5 * n), p0, Vec3(-n), 0.5);
  Closest<3> c;
  EXPECT_FALSE(closest_point<3>(p, Vec3(p0 - 0.5 * n), 0.49, c));
}

TEST(Triangle3D, FaceEdgeAndVertexRegions) {
  const Primitive t = triangle();
  // Face, above and below.
  expect_closest<3>(t, Vec3(0.5, 0.5, 1), Vec3(0.5, 0.5, 0), Vec3(0, 0, 1), 1.0);
  expect_closest<3>(t, Vec3(0.5, 0.5, -0.3), Vec3(0.5, 0.5, 0), Vec3(0, 0, -1), 0.3);
  // Edges: ab (y = 0), ac (x = 0), bc (x + y = 2, nearest (1,1,0) to (2,2,0)).
  expect_closest<3>(t, Vec3(1, -1, 1), Vec3(1, 0, 0), Vec3(0, -1, 1).normalized(), std::sqrt(2.0));
  expect_closest<3>(t, Vec3(-1, 1, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), 1.0);
  expect_closest<3>(t, Vec3(2, 2, 0), Vec3(1, 1, 0), Vec3(1, 1, 0).normalized(), std::sqrt(2.0));
  // Vertices a, b, and c ((-0.5, 3) projects past c on both edges ac and bc).
  expect_closest<3>(t, Vec3(-1, -1, 1), Vec3(0, 0, 0), Vec3(-1, -1, 1).normalized(),
                    std::sqrt(3.0));
  expect_closest<3>(t, Vec3(3, -1, 0), Vec3(2, 0, 0), Vec3(1, -1, 0).normalized(), std::sqrt(2.0));
  expect_closest<3>(t, Vec3(-0.5, 3, 0), Vec3(0, 2, 0), Vec3(-0.5, 1, 0).normalized(),
                    std::sqrt(1.25));
  // In the face itself: distance 0, normal +n.
  expect_closest<3>(t, Vec3(0.5, 0.5, 0), Vec3(0.5, 0.5, 0), Vec3(0, 0, 1), 0.0);
  Closest<3> c;
  EXPECT_FALSE(closest_point<3>(t, Vec3(0.5, 0.5, 1), 0.9, c));
  // Near the plane but sqrt(2.01) from vertex a: passes the plane test, fails the cutoff.
  EXPECT_FALSE(closest_point<3>(t, Vec3(-1, -1, 0.1), 1.0, c));
}

TEST(Triangle3D, NeverFartherThanAnySampledPointOfTheTriangle) {
  // Brute force: the returned distance is the minimum over a dense sampling
  // of the triangle (within the sampling resolution).
  Primitive t;
  ASSERT_TRUE(make_triangle(Vec3(0.1, -0.2, 0.3), Vec3(1.3, 0.2, -0.1), Vec3(0.4, 1.1, 0.5), t));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 2.0);
  constexpr int kN = 60;
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 x(u(rng), u(rng), u(rng));
    Closest<3> c;
    ASSERT_TRUE(closest_point<3>(t, x, kInf, c));
    EXPECT_NEAR((x - c.point).norm(), c.distance, 1e-12);
    double best = kInf;
    for (int i = 0; i <= kN; ++i)
      for (int j = 0; i + j <= kN; ++j) {
        const Vec3 q = t.p0 + (t.p1 - t.p0) * i / kN + (t.p2 - t.p0) * j / kN;
        best = std::min(best, (x - q).norm());
      }
    EXPECT_LE(c.distance, best + 1e-12);
    EXPECT_GE(c.distance, best - 0.03);  // sample spacing ~ 1.3 / 60
  }
}

TEST(Cylinder3D, InsideOutsideFiniteAndTilted) {
  // Inside an infinite cylinder of radius 1 about z.
  const Primitive in = cylinder(Vec3::Zero(), Vec3::UnitZ(), 1.0, true);
  expect_closest<3>(in, Vec3(0.5, 0, 7), Vec3(1, 0, 7), Vec3(-1, 0, 0), 0.5);
  // A centre 0.2 beyond the wall: signed distance -0.2, still pushed inwards.
  expect_closest<3>(in, Vec3(1.2, 0, 0), Vec3(1, 0, 0), Vec3(-1, 0, 0), -0.2);
  Closest<3> c;
  EXPECT_FALSE(closest_point<3>(in, Vec3(1.2, 0, 0), 0.1, c));  // passed through
  // On the axis every wall point is at R.
  ASSERT_TRUE(closest_point<3>(in, Vec3(0, 0, 5), 2.0, c));
  EXPECT_NEAR(c.distance, 1.0, kTol);
  EXPECT_NEAR(c.normal.norm(), 1.0, kTol);
  EXPECT_NEAR(c.normal.z(), 0.0, kTol);
  EXPECT_NEAR((c.point - Vec3(0, 0, 5)).norm(), 1.0, kTol);
  // Outside: (0,3,1) is 2 from (0,1,1).
  const Primitive out = cylinder(Vec3::Zero(), Vec3::UnitZ(), 1.0, false);
  expect_closest<3>(out, Vec3(0, 3, 1), Vec3(0, 1, 1), Vec3(0, 1, 0), 2.0);
  // Finite, z in [0, 2]: above the top the nearest point is on the rim (1,0,2).
  const Primitive cup = cylinder(Vec3::Zero(), Vec3::UnitZ(), 1.0, true, 2.0);
  expect_closest<3>(cup, Vec3(0.5, 0, 3), Vec3(1, 0, 2), Vec3(-0.5, 0, 1).normalized(),
                    std::sqrt(1.25));
  // Axis along (1,1,0) through 0, outside: (2,2,3) is at axial 2 sqrt 2, radial 3 along z.
  const Primitive tilted = cylinder(Vec3::Zero(), Vec3(1, 1, 0), 1.0, false);
  expect_closest<3>(tilted, Vec3(2, 2, 3), Vec3(2, 2, 1), Vec3(0, 0, 1), 2.0);
}

TEST(ClosestPoint, KindsOfTheOtherDimensionAreNeverHit) {
  Closest<2> c2;
  EXPECT_FALSE(closest_point<2>(triangle(), V2(0.5, 0.5), kInf, c2));
  EXPECT_FALSE(
      closest_point<2>(cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, true), V2(0, 0), kInf, c2));
  Closest<3> c3;
  EXPECT_FALSE(closest_point<3>(arc(Vec3::Zero(), 1, 0, 1), Vec3(2, 0, 0), kInf, c3));
}

void expect_box(const Primitive& p, const Vec3& lo, const Vec3& hi) {
  Vec3 l, h;
  bounds(p, l, h);
  for (int i = 0; i < 3; ++i) {
    if (std::isinf(lo[i]))
      EXPECT_EQ(l[i], lo[i]) << i;
    else
      EXPECT_NEAR(l[i], lo[i], kTol) << i;
    if (std::isinf(hi[i]))
      EXPECT_EQ(h[i], hi[i]) << i;
    else
      EXPECT_NEAR(h[i], hi[i], kTol) << i;
  }
}

TEST(Bounds, EveryKind) {
  expect_box(segment(Vec3(1, 5, 0), Vec3(-2, 3, 1)), Vec3(-2, 3, 0), Vec3(1, 5, 1));
  expect_box(triangle(), Vec3(0, 0, 0), Vec3(2, 2, 0));
  // Quarter arc about (1,1), R 2: from (3,1) to (1,3).
  expect_box(arc(Vec3(1, 1, 0), 2, 0, M_PI / 2), Vec3(1, 1, 0), Vec3(3, 3, 0));
  // 45..135 deg passes the top (1,3); ends at x = 1 -+ sqrt 2, y = 1 + sqrt 2.
  const double s2 = std::sqrt(2.0);
  expect_box(arc(Vec3(1, 1, 0), 2, M_PI / 4, 3 * M_PI / 4), Vec3(1 - s2, 1 + s2, 0),
             Vec3(1 + s2, 3, 0));
  // 350..370 deg passes 360 deg: x reaches 3.
  expect_box(arc(Vec3(1, 1, 0), 2, deg2rad(350), deg2rad(370)),
             Vec3(1 + 2 * std::cos(deg2rad(10)), 1 - 2 * std::sin(deg2rad(10)), 0),
             Vec3(3, 1 + 2 * std::sin(deg2rad(10)), 0));
  expect_box(plane(Vec3(1, 2, 3), Vec3(0, 0, -1)), Vec3(-kInf, -kInf, 3), Vec3(kInf, kInf, 3));
  expect_box(plane(Vec3(1, 2, 3), Vec3(0, 1, 1)), Vec3::Constant(-kInf), Vec3::Constant(kInf));
  expect_box(cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, true, 2), Vec3(-1, -1, 0), Vec3(1, 1, 2));
  expect_box(cylinder(Vec3(0, 0, 5), Vec3::UnitZ(), 1, true), Vec3(-1, -1, -kInf),
             Vec3(1, 1, kInf));
  expect_box(cylinder(Vec3(1, 0, 0), Vec3::UnitX(), 0.5, false, 3), Vec3(1, -0.5, -0.5),
             Vec3(4, 0.5, 0.5));
}

}  // namespace
}  // namespace talus::geometry
