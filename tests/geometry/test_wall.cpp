// Wall motion (exact at given times, consistent with velocity_at) and the
// checks of make_wall.
#include <gtest/gtest.h>

#include <filesystem>

#include "talus/core/error.hpp"
#include "talus/geometry/stl.hpp"
#include "talus/geometry/wall.hpp"

namespace talus::geometry {
namespace {

constexpr double kTol = 1e-12;

WallParams segment_params(const Vec3& a, const Vec3& b) {
  WallParams w;
  w.name = "seg";
  w.kind = WallKind::Segment;
  w.a = a;
  w.b = b;
  return w;
}

void expect_vec(const Vec3& got, const Vec3& want, double tol = kTol) {
  EXPECT_NEAR((got - want).norm(), 0.0, tol) << got.transpose() << " vs " << want.transpose();
}

TEST(WallMotion, TranslationOnlyBetweenStartAndStop) {
  WallParams w = segment_params(Vec3(0, 0, 0), Vec3(1, 0, 0));
  w.motion.velocity = Vec3(2, 1, 0);
  w.motion.move_start = 0.5;
  w.motion.move_stop = 1.5;
  Wall wall = make_wall(w, 3, 2);
  EXPECT_EQ(wall.material, 3);
  // Moved for 0, 0.5 and 1.0 s at (2,1) m/s.
  wall.update(0.25);
  expect_vec(wall.current[0].p0, Vec3(0, 0, 0));
  wall.update(1.0);
  expect_vec(wall.current[0].p0, Vec3(1, 0.5, 0));
  expect_vec(wall.current[0].p1, Vec3(2, 0.5, 0));
  wall.update(3.0);
  expect_vec(wall.current[0].p1, Vec3(3, 1, 0));
  expect_vec(wall.displacement(3.0), Vec3(2, 1, 0));
  expect_vec(wall.velocity_at(Vec3(0, 0, 0), 0.25), Vec3::Zero());
  expect_vec(wall.velocity_at(Vec3(0, 0, 0), 1.0), Vec3(2, 1, 0));
  expect_vec(wall.velocity_at(Vec3(0, 0, 0), 1.5), Vec3::Zero());  // stopped
  EXPECT_TRUE(wall.moves());
}

TEST(WallMotion, RotationOfSegmentAndArcAboutPivot) {
  // A quarter turn about z in 1 s (omega = pi/2) about the origin.
  WallParams s = segment_params(Vec3(1, 0, 0), Vec3(2, 0, 0));
  s.motion.angular_velocity = Vec3(0, 0, M_PI / 2);
  Wall seg = make_wall(s, 0, 2);
  seg.update(1.0);
  expect_vec(seg.current[0].p0, Vec3(0, 1, 0));
  expect_vec(seg.current[0].p1, Vec3(0, 2, 0));
  // omega x r = (pi/2) z x (0,1,0) = (-pi/2, 0, 0).
  expect_vec(seg.velocity_at(Vec3(0, 1, 0), 1.0), Vec3(-M_PI / 2, 0, 0));

  WallParams a;
  a.name = "arc";
  a.kind = WallKind::Arc;
  a.center = Vec3(3, 0, 0);
  a.radius = 1;
  a.angle_start = 0;
  a.angle_end = M_PI / 2;
  a.motion = s.motion;
  Wall arc = make_wall(a, 0, 2);
  arc.update(1.0);
  expect_vec(arc.current[0].p0, Vec3(0, 3, 0));
  EXPECT_NEAR(arc.current[0].angle_start, M_PI / 2, kTol);
  EXPECT_NEAR(arc.current[0].angle_end, M_PI, kTol);
}

TEST(WallMotion, RotationWithTranslationTurnsAboutTheMovingPivot) {
  WallParams p;
  p.name = "paddle";
  p.kind = WallKind::Plane;
  p.point = Vec3(2, 0, 0);
  p.normal = Vec3(1, 0, 0);
  p.motion.pivot = Vec3(1, 0, 0);
  p.motion.velocity = Vec3(0, 1, 0);
  p.motion.angular_velocity = Vec3(0, 0, 0.8);
  Wall wall = make_wall(p, 0, 3);
  // At t = 0.5: pivot at (1,0.5,0), turned by 0.4 rad; the point was 1 from the pivot along x.
  wall.update(0.5);
  const double th = 0.4;
  expect_vec(wall.pivot_at(0.5), Vec3(1, 0.5, 0));
  expect_vec(wall.current[0].p0, Vec3(1 + std::cos(th), 0.5 + std::sin(th), 0));
  expect_vec(wall.current[0].n, Vec3(std::cos(th), std::sin(th), 0));
  EXPECT_NEAR(wall.rotation_angle(0.5), th, kTol);
}

TEST(WallMotion, SinusoidalVibration) {
  WallParams p;
  p.name = "floor";
  p.kind = WallKind::Plane;
  p.point = Vec3(0, 0, 0);
  p.normal = Vec3(0, 0, 1);
  p.motion.amplitude = 0.01;
  p.motion.frequency = 5;
  p.motion.phase = 0.3;
  p.motion.direction = Vec3(0, 0, 2);  // not unit: only its direction counts
  Wall wall = make_wall(p, 0, 3);
  // z(0.1) = 0.01 sin(2 pi 5 0.1 + 0.3) = -0.01 sin 0.3 = -2.955202066613396e-3
  wall.update(0.1);
  EXPECT_NEAR(wall.current[0].p0.z(), -2.955202066613396e-3, kTol);
  // z'(0.1) = 0.01 * 10 pi * cos(pi + 0.3) = -0.1 pi cos 0.3 = -0.30012710...
  EXPECT_NEAR(wall.velocity_at(Vec3(5, 5, 0), 0.1).z(), -0.1 * M_PI * std::cos(0.3), kTol);
  // The given geometry is the rest position: at t = 0 the offset is A sin(phase).
  wall.update(0.0);
  EXPECT_NEAR(wall.current[0].p0.z(), 0.01 * std::sin(0.3), kTol);
}

TEST(WallMotion, Removal) {
  WallParams w = segment_params(Vec3(0, 0, 0), Vec3(1, 0, 0));
  w.motion.remove_at = 1.0;
  const Wall wall = make_wall(w, 0, 2);
  EXPECT_TRUE(wall.active(0.999));
  EXPECT_FALSE(wall.active(1.0));
  EXPECT_FALSE(wall.moves());
}

// All motions at once: the velocity of a material point equals the central
// difference of its position under update().
TEST(WallMotion, VelocityMatchesFiniteDifferenceOfUpdate) {
  WallParams p;
  p.name = "tri";
  p.kind = WallKind::Triangle;
  p.vertices = {Vec3(1, 0, 0), Vec3(0, 2, 0), Vec3(0, 0, 1.5)};
  p.motion.velocity = Vec3(0.3, -0.2, 0.1);
  p.motion.angular_velocity = Vec3(0.5, -1.0, 2.0);
  p.motion.pivot = Vec3(0.2, 0.1, -0.3);
  p.motion.move_start = 0.1;
  p.motion.move_stop = 2.0;
  p.motion.amplitude = 0.02;
  p.motion.frequency = 3;
  p.motion.direction = Vec3(1, 1, 0);
  Wall wall = make_wall(p, 0, 3);
  const double h = 1e-6;
  for (double t : {0.05, 0.7, 1.3, 2.5}) {
    for (int k = 0; k < 3; ++k) {
      auto vertex = [&](double time) {
        wall.update(time);
        const Primitive& q = wall.current[0];
        return k == 0 ? q.p0 : k == 1 ? q.p1 : q.p2;
      };
      const Vec3 fd = (vertex(t + h) - vertex(t - h)) / (2 * h);
      const Vec3 v = wall.velocity_at(vertex(t), t);
      // Central difference error ~ h^2 |x'''| plus rounding ~ 1e-16 / h.
      expect_vec(v, fd, 1e-8);
    }
  }
}

TEST(WallMotion, UpdateIsExactAndIndependentOfHistory) {
  WallParams w = segment_params(Vec3(0.3, 0.1, 0), Vec3(1, 0.7, 0));
  w.motion.velocity = Vec3(1, 2, 0);
  w.motion.angular_velocity = Vec3(0, 0, 3);
  w.motion.amplitude = 0.1;
  w.motion.frequency = 2;
  w.motion.direction = Vec3(0, 1, 0);
  Wall a = make_wall(w, 0, 2), b = make_wall(w, 0, 2);
  for (int i = 1; i <= 1000; ++i) a.update(i * 1e-3);  // many small steps...
  b.update(1000 * 1e-3);                               // ...or one jump
  EXPECT_EQ(a.current[0].p0, b.current[0].p0);
  EXPECT_EQ(a.current[0].p1, b.current[0].p1);
}

TEST(WallBounds, UnionOfCurrentPrimitives) {
  WallParams w = segment_params(Vec3(0, 0, 0), Vec3(1, 2, 0));
  w.motion.velocity = Vec3(1, 0, 0);
  Wall wall = make_wall(w, 0, 2);
  wall.update(2.0);  // moved by (2,0,0)
  Vec3 lo, hi;
  wall.bounds(lo, hi);
  expect_vec(lo, Vec3(2, 0, 0));
  expect_vec(hi, Vec3(3, 2, 0));
}

TEST(MakeWall, MeshFromStlWithScaleAndOffset) {
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / "talus_geom_wall_mesh.stl").string();
  Primitive t1, t2;
  ASSERT_TRUE(make_triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), t1));
  ASSERT_TRUE(make_triangle(Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), t2));
  write_stl(path, {t1, t2}, true);
  WallParams w;
  w.name = "box";
  w.kind = WallKind::Mesh;
  w.file = path;
  w.scale = 2.0;
  w.offset = Vec3(0, 0, 1);
  const Wall wall = make_wall(w, 1, 3);
  ASSERT_EQ(wall.current.size(), 2u);
  expect_vec(wall.current[1].p1, Vec3(2, 2, 1));  // 2 * (1,1,0) + (0,0,1)
  std::filesystem::remove(path);
}

// make_wall must throw InputError whose message names the wall.
void expect_rejected(WallParams w, int dimension, const std::string& fragment) {
  w.name = "culprit";
  try {
    make_wall(w, 0, dimension);
    ADD_FAILURE() << "accepted: " << fragment;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'culprit'"), std::string::npos) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
}

TEST(MakeWall, RejectsBadGeometry) {
  expect_rejected(segment_params(Vec3(1, 1, 0), Vec3(1, 1, 0)), 2, "coincide");
  // Differs only in z, which 2D ignores.
  expect_rejected(segment_params(Vec3(1, 1, 0), Vec3(1, 1, 5)), 2, "coincide");
  WallParams plane;
  plane.kind = WallKind::Plane;
  plane.normal = Vec3::Zero();
  expect_rejected(plane, 3, "normal");
  plane.normal = Vec3::UnitZ();
  expect_rejected(plane, 2, "normal");  // a 2D line needs an in-plane normal
  WallParams tri;
  tri.kind = WallKind::Triangle;
  tri.vertices = {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)};
  expect_rejected(tri, 3, "degenerate");
  tri.vertices.pop_back();
  expect_rejected(tri, 3, "3 vertices");
  WallParams arc;
  arc.kind = WallKind::Arc;
  arc.radius = 0;
  arc.angle_end = 1;
  expect_rejected(arc, 2, "radius");
  arc.radius = 1;
  arc.angle_end = -1;
  expect_rejected(arc, 2, "angle_end");
  WallParams cyl;
  cyl.kind = WallKind::Cylinder;
  cyl.radius = -1;
  expect_rejected(cyl, 3, "radius");
  WallParams mesh;
  mesh.kind = WallKind::Mesh;
  mesh.file = "/nonexistent/talus.stl";
  EXPECT_THROW(make_wall(mesh, 0, 3), InputError);
}

TEST(MakeWall, RejectsKindsOfTheOtherDimensionAndBadMotion) {
  WallParams w = segment_params(Vec3(0, 0, 0), Vec3(1, 0, 0));
  expect_rejected(w, 3, "not available in 3D");
  w.kind = WallKind::Arc;
  expect_rejected(w, 3, "not available in 3D");
  w.kind = WallKind::Triangle;
  expect_rejected(w, 2, "not available in 2D");
  w.kind = WallKind::Cylinder;
  expect_rejected(w, 2, "not available in 2D");
  w.kind = WallKind::Mesh;
  expect_rejected(w, 2, "not available in 2D");
  WallParams m = segment_params(Vec3(0, 0, 0), Vec3(1, 0, 0));
  m.motion.angular_velocity = Vec3(1, 0, 0);
  expect_rejected(m, 2, "about z");
  m.motion.angular_velocity = Vec3::Zero();
  m.motion.move_start = 2;
  m.motion.move_stop = 1;
  expect_rejected(m, 2, "move_stop");
}

}  // namespace
}  // namespace talus::geometry
