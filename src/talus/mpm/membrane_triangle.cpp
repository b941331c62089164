#include "talus/mpm/membrane_triangle.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"

namespace talus::mpm {

namespace {

using Mat32 = Eigen::Matrix<double, 3, 2>;

// The principal stretches (ascending) of F and their rest directions V.
struct Principal {
  Mat32 F;
  Eigen::Vector2d stretch;
  Eigen::Matrix2d V;
};

Principal principal(const std::array<Vec3, 3>& x, const TriangleRest& rest) {
  Mat32 ds;
  ds.col(0) = x[1] - x[0];
  ds.col(1) = x[2] - x[0];
  Principal p;
  p.F = ds * rest.inverse;
  // computeDirect: closed form, no iteration, the same bits every time.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig;
  eig.computeDirect(p.F.transpose() * p.F);
  for (int i = 0; i < 2; ++i) p.stretch[i] = std::sqrt(std::max(eig.eigenvalues()[i], 0.0));
  p.V = eig.eigenvectors();
  return p;
}

// Relaxed tensions (dw/de1, dw/de2) and energy density for e1 >= e2.
struct Law {
  double n1 = 0.0, n2 = 0.0, w = 0.0;
};

Law relaxed(double e1, double e2, double J, double nu) {
  const double k = J / (1.0 - nu * nu);
  const double t2 = k * (e2 + nu * e1);
  if (t2 >= 0.0)  // taut (then also k (e1 + nu e2) >= t2 >= 0)
    return {k * (e1 + nu * e2), t2, 0.5 * k * (e1 * e1 + 2.0 * nu * e1 * e2 + e2 * e2)};
  if (e1 > 0.0) return {J * e1, 0.0, 0.5 * J * e1 * e1};  // wrinkled: uniaxial along 1
  return {};                                              // slack
}

}  // namespace

TriangleRest triangle_rest(const Vec3& a, const Vec3& b, const Vec3& c, double scale) {
  const Vec3 u = b - a, w = c - a;
  const Vec3 n = u.cross(w);
  if (!(n.norm() > 1e-12 * u.norm() * w.norm()))
    throw InputError("membrane triangle with coincident or collinear corners");
  const Vec3 t1 = u.normalized(), t2 = n.normalized().cross(t1);
  Eigen::Matrix2d dm;
  dm << u.dot(t1), w.dot(t1), 0.0, w.dot(t2);
  dm *= scale;
  return {dm.inverse(), 0.5 * std::abs(dm.determinant())};
}

namespace {

// Principal strains and tensions of a deformed triangle (no direction yet).
TriangleTension tension_of(const Principal& p, double stiffness, double poisson) {
  TriangleTension t;
  t.e1 = p.stretch[1] - 1.0;
  t.e2 = p.stretch[0] - 1.0;
  const Law law = relaxed(t.e1, t.e2, stiffness, poisson);
  t.n1 = law.n1;
  t.n2 = law.n2;
  return t;
}

}  // namespace

TriangleTension triangle_tension(const std::array<Vec3, 3>& x, const TriangleRest& rest,
                                 double stiffness, double poisson) {
  const Principal p = principal(x, rest);
  TriangleTension t = tension_of(p, stiffness, poisson);
  if (t.n1 > 0.0 && p.stretch[1] > 0.0) t.direction = p.F * p.V.col(1) / p.stretch[1];
  return t;
}

double triangle_energy(const std::array<Vec3, 3>& x, const TriangleRest& rest, double stiffness,
                       double poisson) {
  const Principal p = principal(x, rest);
  return rest.area * relaxed(p.stretch[1] - 1.0, p.stretch[0] - 1.0, stiffness, poisson).w;
}

TriangleTension triangle_forces(const std::array<Vec3, 3>& x, const TriangleRest& rest,
                                double stiffness, double poisson, std::array<Vec3, 3>& f) {
  const Principal p = principal(x, rest);
  TriangleTension t = tension_of(p, stiffness, poisson);
  for (auto& fi : f) fi.setZero();
  if (t.n1 <= 0.0) return t;  // slack (n2 <= n1 always)
  // dw/dF = sum_i n_i u_i v_i^T (d l_i / dF = u_i v_i^T, u_i = F v_i / l_i);
  // dW/dDs = A0 dw/dF Dm^-T; the forces are minus that.
  Mat32 P = Mat32::Zero();
  const double n[2] = {t.n2, t.n1};
  for (int i = 0; i < 2; ++i) {
    if (n[i] == 0.0 || !(p.stretch[i] > 0.0)) continue;
    const Vec3 u = p.F * p.V.col(i) / p.stretch[i];
    P += n[i] * u * p.V.col(i).transpose();
  }
  const Mat32 H = -rest.area * P * rest.inverse.transpose();
  f[1] = H.col(0);
  f[2] = H.col(1);
  f[0] = -(f[1] + f[2]);
  t.direction = p.F * p.V.col(1) / p.stretch[1];
  return t;
}

}  // namespace talus::mpm
