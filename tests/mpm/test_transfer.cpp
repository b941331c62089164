// Transfer options of the MPM step: APIC (Jiang et al. 2015; mpm/apic.hpp)
// against the FLIP/PIC blend, and the volumetric strain smoothing of Jassim
// (2011; mpm/smoothing.hpp) against volumetric locking.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "mpm_test_support.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::mpm {
namespace {

using V2 = Eigen::Vector2d;
using M2 = Eigen::Matrix2d;

MaterialParams elastic(double e, double nu, double rho) {
  MaterialParams m;
  m.name = "solid";
  m.model = LinearElastic::name;
  m.density = rho;
  m.youngs_modulus = e;
  m.poisson_ratio = nu;
  return m;
}

// A disk of radius 0.05 m centred at (0.15, 0.15) on a free 0.3 m grid
// (h = 10 mm, 2x2 points per cell: the cells' points inside the disk).
Solver<2> disk(ShapeKind shape, Transfer transfer, double flip) {
  SolverParams p;
  p.shape = shape;
  p.transfer = transfer;
  p.flip = flip;
  p.gimp_half_width = 0.25;
  std::array<BoundaryKind, 4> faces;
  faces.fill(BoundaryKind::Free);
  Solver<2> s(Grid<2>(V2(0, 0), V2(0.3, 0.3), 0.01, faces),
              {make_material(elastic(1e5, 0.3, 1000.0))}, p);
  const double dx = 0.005;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) {
      const V2 x((i + 0.5) * dx, (j + 0.5) * dx);
      if ((x - V2(0.15, 0.15)).norm() < 0.05)
        s.particles.add(x, V2::Zero(), 1000.0 * dx * dx, dx * dx, 0, MaterialState{});
    }
  return s;
}

template <class Shape>
M2 inertia(const Grid<2>& g, const V2& x, double half_width) {
  Stencil<2, Shape> st;
  st.compute(g, x, half_width);
  M2 d = M2::Zero();
  for (int k = 0; k < st.count; ++k) d += st.w[k] * st.dx[k] * st.dx[k].transpose();
  return d;
}

// An affine velocity field v = a + A x (rotation, stretch and shear) given to
// the points, with B_p = A D_p for APIC. One step of length 0 maps it to the
// grid and back. APIC returns it exactly (Jiang et al. 2015, sec. 5.3: both
// transfers are exact for affine fields) for GIMP and the cubic B-spline: to
// round-off, 1e-12 of the largest speed. PIC (flip = 0) smooths it at the
// edge of the body, where the points do not surround their nodes: there it
// errs by a fraction of |A| h (asserted > 1 % of |A| h, to show the check can fail).
TEST(MpmApic, ReproducesAnAffineVelocityFieldExactly) {
  const OneThread one;
  const V2 a(0.3, -0.2);
  M2 A;
  A << 0.5, -2.0, 1.5, -0.25;
  for (ShapeKind shape : {ShapeKind::Gimp, ShapeKind::CubicBSpline}) {
    for (Transfer transfer : {Transfer::Apic, Transfer::FlipPic}) {
      Solver<2> s = disk(shape, transfer, 0.0);
      for (std::size_t i = 0; i < s.particles.size(); ++i) {
        s.particles.v[i] = a + A * s.particles.x[i];
        const M2 d = shape == ShapeKind::Gimp
                         ? inertia<GimpShape>(s.grid, s.particles.x[i], 0.25)
                         : inertia<CubicBSplineShape>(s.grid, s.particles.x[i], 0.25);
        if (transfer == Transfer::Apic) s.particles.affine[i] = A * d;
      }
      s.step(0.0);
      double err = 0.0, err_b = 0.0, speed = 0.0;
      for (std::size_t i = 0; i < s.particles.size(); ++i) {
        const V2 exact = a + A * s.particles.x[i];
        speed = std::max(speed, exact.norm());
        err = std::max(err, (s.particles.v[i] - exact).norm());
        const M2 d = shape == ShapeKind::Gimp
                         ? inertia<GimpShape>(s.grid, s.particles.x[i], 0.25)
                         : inertia<CubicBSplineShape>(s.grid, s.particles.x[i], 0.25);
        err_b = std::max(err_b, (s.particles.affine[i] - A * d).norm() / (A.norm() * d.norm()));
      }
      std::printf("shape %d, %s: largest velocity error %.3e m/s (|A| h = %.3e)\n",
                  static_cast<int>(shape), transfer == Transfer::Apic ? "APIC" : "PIC", err,
                  A.norm() * 0.01);
      if (transfer == Transfer::Apic) {
        EXPECT_LT(err, 1e-12 * speed);
        EXPECT_LT(err_b, 1e-12);
      } else {
        EXPECT_GT(err, 0.01 * A.norm() * 0.01);
      }
    }
  }
}

// Angular momentum about the disk's centre of what the points put on the grid
// (after the step's re-mapping, MUSL): sum_i (x_i - c) x m_i v_i.
double grid_angular_momentum(const Solver<2>& s) {
  double l = 0.0;
  for (int j = 0; j < s.grid.n[1]; ++j)
    for (int i = 0; i < s.grid.n[0]; ++i) {
      const auto a = s.grid.index({i, j});
      const V2 r = s.grid.node_position({i, j}) - V2(0.15, 0.15);
      l += r.x() * s.grid.momentum[a].y() - r.y() * s.grid.momentum[a].x();
    }
  return l;
}

// The elastic disk (E = 100 kPa, rho = 1000) spun at 10 rad/s, no gravity,
// for 0.2 s (two radians; the centrifugal load sets it ringing). APIC
// conserves angular momentum exactly in exact arithmetic (Jiang et al. 2015,
// sec. 5.2; symmetric stresses exert no torque on the grid): relative change
// below 1e-9. PIC (flip = 0) is known to damp rotation: it must lose more than
// 0.1 %, and the default blend (flip = 0.99) must do worse than APIC.
// Thresholds fixed before the first run.
TEST(MpmApic, ConservesAngularMomentumOfASpinningDisk) {
  const OneThread one;
  std::map<std::string, double> change;
  for (auto [name, transfer, flip] :
       {std::tuple{"apic", Transfer::Apic, 0.0}, std::tuple{"pic", Transfer::FlipPic, 0.0},
        std::tuple{"flip0.99", Transfer::FlipPic, 0.99}}) {
    Solver<2> s = disk(ShapeKind::Gimp, transfer, flip);
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const V2 r = s.particles.x[i] - V2(0.15, 0.15);
      s.particles.v[i] = 10.0 * V2(-r.y(), r.x());
      // B_p = A D_p with A the rotation rate: the rigid rotation is affine.
      if (transfer == Transfer::Apic) {
        M2 w;
        w << 0.0, -10.0, 10.0, 0.0;
        s.particles.affine[i] = w * inertia<GimpShape>(s.grid, s.particles.x[i], 0.25);
      }
    }
    s.step(0.0);
    const double l0 = grid_angular_momentum(s);
    while (s.time < 0.2) s.advance();
    change[name] = std::abs(grid_angular_momentum(s) / l0 - 1.0);
    std::printf("%s: relative change of angular momentum over 0.2 s: %.3e (%lld steps)\n", name,
                change[name], static_cast<long long>(s.steps));
  }
  EXPECT_LT(change["apic"], 1e-9);
  EXPECT_GT(change["pic"], 1e-3);
  EXPECT_LT(change["apic"], change["flip0.99"]);
}

// A nearly incompressible elastic block (nu = 0.49, E = 1 MPa, rho = 2000;
// 0.1 x 0.1 m, h = 10 mm, 2x2 points per cell, GIMP) settles under gravity
// (g = 10) from zero stress on a rough base, free at the sides so that it
// bulges (a 2D deformation: in a 1D column between rollers every point of a
// cell has the same strain rate and nothing locks), with local damping 0.3,
// for 0.12 s (about a hundred P-wave crossings). Without smoothing the four
// points of a cell take pressures that alternate from point to point
// (volumetric locking); Jassim's smoothing gives them one volumetric strain
// rate. Measure: the mean over the cells of the spread (max - min) of the
// points' pressures in the cell, over rho g H. Thresholds fixed before the
// first run: the unsmoothed spread is above 1 % (there is a checkerboard to
// remove), the smoothed one below half of it; and the smoothed vertical
// stress of the bottom row of points, averaged over the row, within 10 % of
// rho g (H - y) (the weight of the block, which the rough base carries).
double settle_column(bool smoothing, double* bottom_ratio) {
  SolverParams p;
  p.gravity = Vec3(0.0, -10.0, 0.0);
  p.gimp_half_width = 0.25;
  p.local_damping = 0.3;
  p.volumetric_smoothing = smoothing;
  std::array<BoundaryKind, 4> faces = {BoundaryKind::Free, BoundaryKind::Free, BoundaryKind::Fixed,
                                       BoundaryKind::Free};
  Solver<2> s(Grid<2>(V2(-0.05, 0), V2(0.15, 0.15), 0.01, faces),
              {make_material(elastic(1e6, 0.49, 2000.0))}, p);
  const double dx = 0.005, height = 0.1;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      s.particles.add(V2((i + 0.5) * dx, (j + 0.5) * dx), V2::Zero(), 2000.0 * dx * dx, dx * dx, 0,
                      MaterialState{});
  while (s.time < 0.12) s.advance();
  std::map<std::pair<int, int>, std::pair<double, double>> range;  // cell -> (min, max)
  double bottom = 0.0;
  int bottom_count = 0;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const Mat3& st = s.particles.state[i].stress;
    const double pressure = -st.trace() / 3.0;
    const int ci = static_cast<int>(i / 20) / 2, cj = static_cast<int>(i % 20) / 2;  // initial cell
    auto [it, fresh] = range.try_emplace({ci, cj}, pressure, pressure);
    it->second.first = std::min(it->second.first, pressure);
    it->second.second = std::max(it->second.second, pressure);
    if (i % 20 == 0) {
      bottom += -st(1, 1) / (2000.0 * 10.0 * (height - 0.5 * dx));
      ++bottom_count;
    }
  }
  double spread = 0.0;
  for (const auto& [cell, mm] : range) spread += mm.second - mm.first;
  spread /= static_cast<double>(range.size()) * 2000.0 * 10.0 * height;
  *bottom_ratio = bottom / bottom_count;
  return spread;
}

TEST(MpmVolumetricSmoothing, RemovesCheckerboardPressureInNearlyIncompressibleColumn) {
  const OneThread one;
  double bottom_plain = 0.0, bottom_smooth = 0.0;
  const double plain = settle_column(false, &bottom_plain);
  const double smooth = settle_column(true, &bottom_smooth);
  std::printf(
      "mean in-cell pressure spread / (rho g H): %.4f unsmoothed, %.4f smoothed; bottom "
      "sigma_yy / rho g depth: %.3f unsmoothed, %.3f smoothed\n",
      plain, smooth, bottom_plain, bottom_smooth);
  EXPECT_GT(plain, 0.01);
  EXPECT_LT(smooth, 0.5 * plain);
  EXPECT_NEAR(bottom_smooth, 1.0, 0.1);
}

}  // namespace
}  // namespace talus::mpm
