// One tension-only membrane triangle of the 3D coupled FE membrane
// (membrane_triangle.hpp; mpm.md "Membranes in MPM"), on its own: a uniaxial
// stretch in a tilted plane gives T = J eps along the stretch; compression
// gives nothing; a rigid motion rotates the forces, which balance in force
// and moment; the forces are the gradient of the element's energy in the
// taut, wrinkled and slack states.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "talus/mpm/membrane_triangle.hpp"

namespace talus::mpm {
namespace {

constexpr double kJ = 2000.0;  // N/m

using Tri = std::array<Vec3, 3>;

// A plane rotated 30 degrees about z, then tilted 40 degrees about its own
// first axis: nothing in it lines up with x, y or z.
Eigen::Matrix3d tilted_frame() {
  return (Eigen::AngleAxisd(30.0 * M_PI / 180.0, Vec3::UnitZ()) *
          Eigen::AngleAxisd(40.0 * M_PI / 180.0, Vec3::UnitX()))
      .toRotationMatrix();
}

// A scalene triangle in the plane of `frame` (its first two columns).
Tri rest_triangle(const Eigen::Matrix3d& frame) {
  const Vec3 o(0.3, -0.2, 0.5);
  return {o, o + frame * Vec3(0.11, 0.02, 0.0), o + frame * Vec3(0.03, 0.09, 0.0)};
}

// x -> x + stretch t (t . (x - o)) + squeeze s (s . (x - o)).
Tri deform(const Tri& x, const Vec3& t, double stretch, const Vec3& s, double squeeze) {
  Tri y = x;
  for (auto& p : y) {
    const Vec3 r = p - x[0];
    p += stretch * t * t.dot(r) + squeeze * s * s.dot(r);
  }
  return y;
}

// Uniaxial stretch lambda = 1.1 along a direction 25 degrees from the first
// edge, in the tilted plane, nu = 0: principal strains (0.1, 0) exactly, so
// n1 = J eps = 200 N/m along t and n2 = 0. The forces' virial sum x (x) f is
// -A0 F P^T = -A0 lambda T t (x) t (the element's forces are -dW/dx of a
// homogeneous W(F)). Tolerances: round-off.
TEST(MpmMembraneTriangle, UniaxialStretchAtAnAngleGivesJTimesStrain) {
  const Eigen::Matrix3d frame = tilted_frame();
  const Tri x0 = rest_triangle(frame);
  const TriangleRest rest = triangle_rest(x0[0], x0[1], x0[2]);
  EXPECT_NEAR(rest.area, 0.5 * (0.11 * 0.09 - 0.02 * 0.03), 1e-16);
  const double a = 25.0 * M_PI / 180.0, eps = 0.1;
  const Vec3 t = frame * Vec3(std::cos(a), std::sin(a), 0.0);
  const Vec3 s = frame * Vec3(-std::sin(a), std::cos(a), 0.0);
  const Tri x = deform(x0, t, eps, s, 0.0);
  Tri f;
  const TriangleTension tt = triangle_forces(x, rest, kJ, 0.0, f);
  EXPECT_NEAR(tt.e1, eps, 1e-13);
  EXPECT_NEAR(tt.e2, 0.0, 1e-13);
  EXPECT_NEAR(tt.n1 / (kJ * eps), 1.0, 1e-12);
  EXPECT_NEAR(tt.n2, 0.0, 1e-9);
  EXPECT_NEAR(std::abs(tt.direction.dot(t)), 1.0, 1e-12);
  Eigen::Matrix3d virial = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) virial += x[i] * f[i].transpose();
  const Eigen::Matrix3d exact = -rest.area * (1.0 + eps) * kJ * eps * t * t.transpose();
  EXPECT_NEAR((virial - exact).norm(), 0.0, 1e-12 * exact.norm());
  EXPECT_NEAR((f[0] + f[1] + f[2]).norm(), 0.0, 1e-12 * f[1].norm());
  // With slack 10 % the same stretch only takes up the slack: 1.1 / 1.1 - 1 = 0.
  const TriangleRest loose = triangle_rest(x0[0], x0[1], x0[2], 1.1);
  EXPECT_NEAR(loose.area / rest.area, 1.21, 1e-14);
  EXPECT_NEAR(triangle_tension(x, loose, kJ, 0.0).e1, 0.0, 1e-13);
}

// Biaxial compression (both principal strains < 0): slack, no force at all,
// for nu = 0 and 0.3. Exact zeros.
TEST(MpmMembraneTriangle, BiaxialCompressionGivesNoForce) {
  const Eigen::Matrix3d frame = tilted_frame();
  const Tri x0 = rest_triangle(frame);
  const TriangleRest rest = triangle_rest(x0[0], x0[1], x0[2]);
  const Vec3 t = frame.col(0), s = frame.col(1);
  for (double nu : {0.0, 0.3}) {
    Tri f;
    const TriangleTension tt = triangle_forces(deform(x0, t, -0.05, s, -0.02), rest, kJ, nu, f);
    EXPECT_LT(tt.e1, 0.0);
    EXPECT_EQ(tt.n1, 0.0);
    EXPECT_EQ(tt.n2, 0.0);
    for (const auto& fi : f) EXPECT_EQ(fi.norm(), 0.0);
  }
}

// Tension (+8 %) along t, compression (-5 %) across it: the compressed
// direction wrinkles and carries nothing; the tension is J e1 along t for
// nu = 0 (plain clipping) and for nu = 0.3 (tension field theory: the
// wrinkled state is uniaxial, n1 = J e1, whatever nu). The virial is
// -A0 lambda1 n1 t (x) t: no force across t. Tolerances: round-off.
TEST(MpmMembraneTriangle, CompressionAcrossTensionCarriesTensionOnlyAlongIt) {
  const Eigen::Matrix3d frame = tilted_frame();
  const Tri x0 = rest_triangle(frame);
  const TriangleRest rest = triangle_rest(x0[0], x0[1], x0[2]);
  const double a = -50.0 * M_PI / 180.0;
  const Vec3 t = frame * Vec3(std::cos(a), std::sin(a), 0.0);
  const Vec3 s = frame * Vec3(-std::sin(a), std::cos(a), 0.0);
  const Tri x = deform(x0, t, 0.08, s, -0.05);
  for (double nu : {0.0, 0.3}) {
    Tri f;
    const TriangleTension tt = triangle_forces(x, rest, kJ, nu, f);
    EXPECT_NEAR(tt.e1, 0.08, 1e-13);
    EXPECT_NEAR(tt.e2, -0.05, 1e-13);
    EXPECT_NEAR(tt.n1 / (kJ * 0.08), 1.0, 1e-12) << nu;
    EXPECT_EQ(tt.n2, 0.0);
    EXPECT_NEAR(std::abs(tt.direction.dot(t)), 1.0, 1e-12);
    Eigen::Matrix3d virial = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 3; ++i) virial += x[i] * f[i].transpose();
    const Eigen::Matrix3d exact = -rest.area * 1.08 * kJ * 0.08 * t * t.transpose();
    EXPECT_NEAR((virial - exact).norm(), 0.0, 1e-12 * exact.norm()) << nu;
  }
  // Taut for comparison (nu = 0.3, both stretched): plane stress,
  // n = J / (1 - nu^2) (e1 + nu e2, e2 + nu e1).
  const TriangleTension taut = triangle_tension(deform(x0, t, 0.08, s, 0.02), rest, kJ, 0.3);
  EXPECT_NEAR(taut.n1, kJ / 0.91 * (0.08 + 0.3 * 0.02), 1e-9);
  EXPECT_NEAR(taut.n2, kJ / 0.91 * (0.02 + 0.3 * 0.08), 1e-9);
}

// A rigid rotation (and translation) of a deformed element rotates its forces
// with it, f(Rx + c) = R f(x); they sum to zero and have no moment (momentum
// and angular momentum are conserved). Tolerances: round-off relative to the
// largest nodal force (times the element size for the moment).
TEST(MpmMembraneTriangle, RigidRotationRotatesForcesThatBalance) {
  const Eigen::Matrix3d frame = tilted_frame();
  const Tri x0 = rest_triangle(frame);
  const TriangleRest rest = triangle_rest(x0[0], x0[1], x0[2]);
  const Tri x = deform(x0, frame.col(0), 0.07, frame.col(1), 0.03);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.234, Vec3(0.3, -0.8, 0.5).normalized()).toRotationMatrix();
  const Vec3 c(-1.0, 2.0, 0.25);
  Tri y;
  for (int i = 0; i < 3; ++i) y[i] = R * x[i] + c;
  for (double nu : {0.0, 0.3}) {
    Tri f, g;
    triangle_forces(x, rest, kJ, nu, f);
    triangle_forces(y, rest, kJ, nu, g);
    const double scale = std::max({f[0].norm(), f[1].norm(), f[2].norm()});
    ASSERT_GT(scale, 0.0);
    Vec3 sum = Vec3::Zero(), moment = Vec3::Zero();
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR((g[i] - R * f[i]).norm(), 0.0, 1e-12 * scale) << "node " << i;
      sum += g[i];
      moment += y[i].cross(g[i]);
    }
    EXPECT_NEAR(sum.norm(), 0.0, 1e-12 * scale);
    EXPECT_NEAR(moment.norm(), 0.0, 1e-12 * scale * (y[1] - y[0]).norm() * 10.0);
  }
}

// The forces are -dW/dx: central differences of triangle_energy with a step
// of 1e-6 of the element size, in the taut (nu = 0.3, both stretched),
// wrinkled and slack states. Tolerance 1e-6 of the largest force: the
// difference's truncation error is ~ (1e-6)^2 relative and its round-off
// ~ 1e-16 W / 1e-7 m, both far below.
TEST(MpmMembraneTriangle, ForcesAreTheEnergyGradient) {
  const Eigen::Matrix3d frame = tilted_frame();
  const Tri x0 = rest_triangle(frame);
  const TriangleRest rest = triangle_rest(x0[0], x0[1], x0[2]);
  const Vec3 t = frame.col(0), s = (frame.col(1) + 0.3 * frame.col(2)).normalized();
  struct Case {
    double stretch, squeeze, nu;
  };
  for (const Case c : {Case{0.06, 0.03, 0.3}, Case{0.06, -0.04, 0.3}, Case{0.06, -0.04, 0.0},
                       Case{-0.03, -0.02, 0.3}}) {
    Tri x = deform(x0, t, c.stretch, s, c.squeeze);
    x[2] += 0.004 * frame.col(2);  // out of the rest plane as well
    Tri f;
    triangle_forces(x, rest, kJ, c.nu, f);
    const double scale = std::max({f[0].norm(), f[1].norm(), f[2].norm(), 1e-3});
    const double h = 1e-6 * 0.1;
    for (int i = 0; i < 3; ++i)
      for (int d = 0; d < 3; ++d) {
        Tri p = x, m = x;
        p[i][d] += h;
        m[i][d] -= h;
        const double grad =
            (triangle_energy(p, rest, kJ, c.nu) - triangle_energy(m, rest, kJ, c.nu)) / (2.0 * h);
        EXPECT_NEAR(f[i][d], -grad, 1e-6 * scale)
            << "node " << i << " dir " << d << " case " << c.stretch << ", " << c.squeeze;
      }
  }
}

}  // namespace
}  // namespace talus::mpm
