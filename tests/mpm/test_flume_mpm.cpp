// The flume in the MPM (mpm/flume.hpp): the bed as a rigid wall of boundary
// particles with Coulomb friction, the release triangle filled with points,
// and the [flume] keys of an MPM scenario.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "mpm_test_support.hpp"
#include "talus/core/error.hpp"
#include "talus/mpm/flume.hpp"
#include "talus/mpm/scenario.hpp"
#include "talus/scenario/scenario.hpp"
#include "talus/scenario/scenario_mpm.hpp"

namespace talus::mpm {
namespace {

// An elastic block 0.1 x 0.05 m (rho 1000, E 250 kPa, nu 0.3; h = 10 mm, 2x2
// points per cell, GIMP) resting on a straight path_wall inclined at the
// flume's chute angle of 29 deg, basal friction 21.7 deg (flume.md). It
// slides from rest at once (tan 29 > tan 21.7), and its centre-of-mass
// velocity along the wall, fitted by a line over 0.1-0.3 s (the settling waves
// of the stress-free start cross the block in 0.05 m / 18 m/s), rises at
// g (sin 29 - mu cos 29) = 1.342 m/s^2. Tolerance fixed before the first run:
// 5 %, as for the tilting plate (test_rigid_contact.cpp): the Coulomb law is
// applied node by node on a grid that does not follow the wall.
TEST(MpmFlumeWall, BlockSlidesDownInclinedFrictionWallAtCoulombAcceleration) {
  const OneThread one;
  const double g = 9.81, theta = deg2rad(29.0), mu = std::tan(deg2rad(21.7)), h = 0.01;
  const Vec2 p0(0.05, 0.35), t(std::cos(theta), -std::sin(theta)),
      n(std::sin(theta), std::cos(theta));
  std::array<BoundaryKind, 4> faces;
  faces.fill(BoundaryKind::Free);
  MaterialParams m;
  m.model = LinearElastic::name;
  m.density = 1000.0;
  m.youngs_modulus = 2.5e5;
  m.poisson_ratio = 0.3;
  SolverParams params;
  params.gravity = Vec3(0.0, -g, 0.0);
  params.gimp_half_width = 0.25;
  Solver<2> s(Grid<2>(Vec2(0.0, 0.0), Vec2(0.55, 0.45), h, faces), {make_material(m)}, params);
  s.rigid_bodies.push_back(path_wall([&](double u) { return Vec2(p0 + u * t); },
                                     [&](double) { return n; }, 0.0, 0.5, h / 2, 3, mu));
  const double dx = h / 2;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 10; ++j)
      s.particles.add(p0 + (0.1 + (i + 0.5) * dx) * t + (j + 0.5) * dx * n, Vec2::Zero(),
                      m.density * dx * dx, dx * dx, 0, MaterialState{});
  while (s.time < 0.1) s.advance();
  double st = 0, sv = 0, stt = 0, stv = 0;
  int k = 0;
  while (s.time < 0.3) {
    s.advance();
    const double v = centre_of_mass_velocity(s.particles).dot(t);
    st += s.time, sv += v, stt += s.time * s.time, stv += s.time * v;
    ++k;
  }
  const double a = (k * stv - st * sv) / (k * stt - st * st);
  const double expected = g * (std::sin(theta) - mu * std::cos(theta));
  std::printf("block on a 29 deg wall, mu = tan 21.7 deg: %.4f m/s^2, expected %.4f (ratio %.4f)\n",
              a, expected, a / expected);
  EXPECT_NEAR(a, expected, 0.05 * expected);
  // It stays on the wall: no point sank into it or flew off it by a cell.
  for (const auto& x : s.particles.x) {
    EXPECT_GT((x - p0).dot(n), -0.5 * h);
    EXPECT_LT((x - p0).dot(n), 0.05 + h);
  }
}

// The bed of geometry A (33 deg, R = 0.10 m): every boundary particle lies
// its row depth below the bed line, on the arc at R + depth from the centre
// (exact geometry), with the bed normal of its column.
TEST(MpmFlumeWall, BedParticlesLieTheirDepthBelowTheBed) {
  const auto g = geometry::make_flume({deg2rad(33.0), 0.10, {}, {}});
  const double dx = 0.0025;
  const auto bed = flume_bed(g, dx, 3, 0.4);
  ASSERT_EQ(bed.x.size() % 3, 0u);
  const auto columns = bed.x.size() / 3;
  EXPECT_NEAR(columns * dx, g.path_end_s() - g.chute_start_s(), dx);
  int on_arc = 0;
  for (std::size_t c = 0; c < columns; ++c)
    for (int k = 0; k < 3; ++k) {
      const auto& y = bed.x[3 * c + k];
      const double depth = (k + 0.5) * dx;
      EXPECT_NEAR(bed.normal[3 * c + k].norm(), 1.0, 1e-12);
      const double s = g.path_coordinate(y);
      EXPECT_NEAR((g.point_at(s) - y).norm(), depth, 1e-9);
      if (s > g.chute_end_s() + dx && s < g.arc_end_s() - dx) {
        EXPECT_NEAR((y - g.arc_centre).norm(), g.radius + depth, 1e-9);
        ++on_arc;
      }
    }
  // The arc turns by 29 + 33 = 62 deg: R * 1.08 rad / dx = 43 columns.
  EXPECT_GT(on_arc, 3 * 38);  // less the columns within dx of either end
  EXPECT_DOUBLE_EQ(bed.friction, 0.4);
}

// Lattice cells whose centre is inside: n dx^2 differs from the area by less
// than the cells the edges cut, perimeter * dx.
TEST(MpmFlume, ReleaseTriangleFilledToItsArea) {
  const auto g = geometry::make_flume({deg2rad(33.0), 0.10, {}, {}});
  const double dx = 0.0025;
  const auto points = fill_triangle(g.release[0], g.release[1], g.release[2], dx, Vec2(-0.05, 0));
  const double perimeter = (g.release[1] - g.release[0]).norm() +
                           (g.release[2] - g.release[1]).norm() +
                           (g.release[0] - g.release[2]).norm();
  EXPECT_NEAR(points.size() * dx * dx, g.release_area(), perimeter * dx);
  // Above the chute and left of the gate.
  for (const auto& p : points) {
    EXPECT_LE(p.x(), geometry::kFlumeGateX + 1e-12);
    EXPECT_GE(g.path_coordinate(p), g.chute_start_s() - 1e-12);
  }
}

}  // namespace
}  // namespace talus::mpm
