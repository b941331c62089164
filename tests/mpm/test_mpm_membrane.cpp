// Membranes in MPM (mpm.md "Membranes in MPM"), the pieces on a prescribed
// grid velocity field: building the nodes with slack, the kinematics of both
// models (FE nodes carried by the grid, York's tangent and stretch from the
// velocity gradient), T = J eps for a strip stretched at 0, 30 and 45 degrees
// to the grid, T = 0 in compression, and the forces both models put on the
// grid.
#include <gtest/gtest.h>

#include <cmath>

#include "talus/mpm/membrane_grid.hpp"

namespace talus::mpm {
namespace {

using V2 = Eigen::Vector2d;
constexpr double kJ = 1000.0, kMu = 0.5, kH = 0.1;

MembraneParams strip(MembraneModel model, double angle_deg, double length = 1.0) {
  MembraneParams p;
  p.name = "strip";
  p.model = model;
  const double a = angle_deg * M_PI / 180.0;
  const Vec3 c(1.0, 1.0, 0.0), t(std::cos(a), std::sin(a), 0.0);
  p.points = {c - 0.5 * length * t, c + 0.5 * length * t};
  p.spacing = 0.5 * kH;
  p.stiffness = kJ;
  p.areal_mass = kMu;
  return p;
}

Grid<2> free_grid() {
  std::array<BoundaryKind, 4> faces;
  faces.fill(BoundaryKind::Free);
  return Grid<2>(V2(0.0, 0.0), V2(2.0, 2.0), kH, faces);
}

// Sets both grid velocity fields to v(x) = rate t (t . (x - c)): a uniaxial
// stretch (rate > 0) or compression along t, homogeneous, at any angle.
void uniaxial_field(Grid<2>& g, const V2& t, double rate) {
  for (int j = 0; j < g.n[1]; ++j)
    for (int i = 0; i < g.n[0]; ++i) {
      const V2 x = g.node_position({i, j});
      const auto a = g.index({i, j});
      g.velocity[a] = rate * t * t.dot(x - V2(1.0, 1.0));
      g.velocity_old[a] = g.velocity[a];
    }
}

TEST(MpmMembrane, BuildsNodesMassesAndSlack) {
  MembraneParams p = strip(MembraneModel::FiniteElement, 0.0);
  p.points = {Vec3(0.5, 1.0, 0.0), Vec3(1.5, 1.0, 0.0), Vec3(1.5, 1.4, 0.0)};
  p.slack = 0.1;
  p.slack_everywhere = false;
  // Around the first half of the bottom edge only (the closing edge of the
  // closed variant below starts at (0.5, 1.0) and rises 0.4 over 1 m).
  p.slack_min = Vec3(0.4, 0.995, 0.0);
  p.slack_max = Vec3(1.0, 1.005, 0.0);
  p.fixed = MembraneFixed::First;
  const auto m = build_membrane<2>(p, kH);
  // 1 m / 0.05 = 20 cables, 0.4 m / 0.05 = 8: 29 nodes.
  ASSERT_EQ(m.size(), 29u);
  EXPECT_EQ(m.carriers(), 28u);
  EXPECT_TRUE(m.fixed.front());
  EXPECT_FALSE(m.fixed.back());
  // Slack on the 10 cables with midpoints at x < 1: rest 1.1 x drawn.
  EXPECT_NEAR(m.rest_length[0], 0.055, 1e-15);
  EXPECT_NEAR(m.rest_length[10], 0.05, 1e-15);
  EXPECT_NEAR(m.strain(0), 1.0 / 1.1 - 1.0, 1e-14);
  EXPECT_EQ(m.tension(0), 0.0);
  // The mass is mu times the rest length, slack included.
  EXPECT_NEAR(m.total_mass(), kMu * (1.1 * 0.5 + 0.5 + 0.4), 1e-13);
  EXPECT_NEAR(m.wave_speed(), std::sqrt(kJ / kMu), 1e-12);

  p.model = MembraneModel::York;
  p.closed = true;
  p.fixed = MembraneFixed::None;
  const auto y = build_membrane<2>(p, kH);
  // The closing edge (0.4^2 + 1^2)^0.5 = 1.077 m in 22 pieces.
  EXPECT_EQ(y.size(), 20u + 8u + 22u);
  EXPECT_EQ(y.carriers(), y.size());
  // Point 5, inside the slack box: stretch 1/1.1; its tangent along +x.
  EXPECT_NEAR(y.stretch[5], 1.0 / 1.1, 1e-14);
  EXPECT_NEAR((y.tangent[5] - V2(1.0, 0.0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(y.total_mass(), kMu * (1.1 * 0.5 + 0.5 + 0.4 + std::hypot(1.0, 0.4)), 1e-12);
}

// A strip carried by a homogeneous stretching field, 100 steps of 1e-3 s at
// 0.5 /s: both models must give the exact stretch lambda = (1 + rate dt)^n
// of forward-Euler positions (every shape function here reproduces linear
// fields exactly: mpm.md, and tests/mpm/test_shape.cpp), hence
// T = J (lambda - 1) at any angle to the grid; the virial of the grid forces,
// sum_a x_a (x) f_a, equals -T l t (x) t for a uniform strip of current
// length l (FE: the cables' end forces; York: -V sigma summed), and the net
// force is zero. Tolerances are round-off.
template <class Shape>
void check_stretch(MembraneModel model, double angle_deg, double rate) {
  const double a = angle_deg * M_PI / 180.0, dt = 1e-3;
  const V2 t(std::cos(a), std::sin(a));
  std::vector<Membrane<2>> ms{build_membrane<2>(strip(model, angle_deg), kH)};
  Grid<2> g = free_grid();
  uniaxial_field(g, t, rate);
  const int steps = 100;
  for (int s = 0; s < steps; ++s) membranes_move<2, Shape>(ms, g, dt, 0.25);
  const double lambda = std::pow(1.0 + rate * dt, steps);
  const double expected = kJ * std::max(lambda - 1.0, 0.0);
  const auto& m = ms[0];
  for (std::size_t k = 0; k < m.carriers(); ++k) {
    // Two end points of York's strip stand for a quarter of a cable each.
    EXPECT_NEAR(m.tension(k), expected, 1e-9 * kJ) << "carrier " << k << " at " << angle_deg;
  }
  if (model == MembraneModel::York) {
    for (const auto& tk : m.tangent) EXPECT_NEAR((tk - t).norm(), 0.0, 1e-12);
  }
  g.clear();
  membranes_to_grid<2, Shape>(ms, g, V2::Zero(), 0.25, true, 0.0);
  V2 net = V2::Zero();
  Eigen::Matrix2d virial = Eigen::Matrix2d::Zero();
  for (int j = 0; j < g.n[1]; ++j)
    for (int i = 0; i < g.n[0]; ++i) {
      const auto node = g.index({i, j});
      net += g.force[node];
      virial += g.node_position({i, j}) * g.force[node].transpose();
    }
  const double length = lambda * 1.0;  // the strip's rest length is 1 m
  const Eigen::Matrix2d exact = -expected * length * t * t.transpose();
  EXPECT_NEAR(net.norm(), 0.0, 1e-9 * kJ);
  EXPECT_NEAR((virial - exact).norm(), 0.0, 1e-9 * kJ) << "at " << angle_deg << " deg";
}

TEST(MpmMembrane, StripStretchedAtAnyAngleCarriesJTimesStrain) {
  for (double angle : {0.0, 30.0, 45.0}) {
    check_stretch<GimpShape>(MembraneModel::FiniteElement, angle, 0.5);
    check_stretch<GimpShape>(MembraneModel::York, angle, 0.5);
    check_stretch<CubicBSplineShape>(MembraneModel::FiniteElement, angle, 0.5);
    check_stretch<CubicBSplineShape>(MembraneModel::York, angle, 0.5);
  }
}

TEST(MpmMembrane, CompressedStripCarriesNoTension) {
  for (double angle : {0.0, 30.0, 45.0}) {
    check_stretch<GimpShape>(MembraneModel::FiniteElement, angle, -0.5);
    check_stretch<GimpShape>(MembraneModel::York, angle, -0.5);
  }
}

// A rigid rotation changes neither York's stretch nor any cable's length
// beyond the forward-Euler growth sqrt(1 + (w dt)^2) per step: after 500
// steps of w dt = pi/1000, lambda = (1 + (w dt)^2)^(n/2) for both models, and
// York's tangent has turned by n atan(w dt) (forward Euler's angle per step).
TEST(MpmMembrane, RigidRotationTurnsTheTangent) {
  const double w = 2.0, dt = M_PI / 2.0 / w / 500.0;
  for (auto model : {MembraneModel::FiniteElement, MembraneModel::York}) {
    std::vector<Membrane<2>> ms{build_membrane<2>(strip(model, 0.0, 0.6), kH)};
    Grid<2> g = free_grid();
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const V2 r = g.node_position({i, j}) - V2(1.0, 1.0);
        g.velocity[g.index({i, j})] = w * V2(-r.y(), r.x());
      }
    for (int s = 0; s < 500; ++s) membranes_move<2, GimpShape>(ms, g, dt, 0.25);
    const double lambda = std::pow(1.0 + w * w * dt * dt, 250.0);
    const auto& m = ms[0];
    for (std::size_t k = 0; k < m.carriers(); ++k) EXPECT_NEAR(m.strain(k), lambda - 1.0, 1e-9);
    const double turned = 500.0 * std::atan(w * dt);
    if (model == MembraneModel::York) {
      EXPECT_NEAR((m.tangent[3] - V2(std::cos(turned), std::sin(turned))).norm(), 0.0, 1e-12);
    }
  }
}

}  // namespace
}  // namespace talus::mpm
