#pragma once
// Small tensor helpers for the material point method. Stresses and strains are
// always 3x3 (plane strain in 2D: the out-of-plane components are kept so that
// the 2D and 3D constitutive models are one code path). Sign convention:
// tension positive, as in Bui et al. (2008).
#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>

#include "talus/core/space.hpp"

namespace talus::mpm {

using Mat3 = Eigen::Matrix3d;

inline Mat3 sym(const Mat3& a) { return 0.5 * (a + a.transpose()); }
inline Mat3 skew(const Mat3& a) { return 0.5 * (a - a.transpose()); }
inline Mat3 deviator(const Mat3& a) { return a - a.trace() / 3.0 * Mat3::Identity(); }
// Second invariant of the deviator, J2 = s:s / 2.
inline double j2(const Mat3& stress) {
  const Mat3 s = deviator(stress);
  return 0.5 * (s.array() * s.array()).sum();
}
// Von Mises equivalent stress q = sqrt(3 J2).
inline double von_mises(const Mat3& stress) { return std::sqrt(3.0 * j2(stress)); }

// A D x D velocity gradient as a 3x3 one (zero out-of-plane rows in 2D).
template <class M>
Mat3 embed(const M& a) {
  Mat3 out = Mat3::Zero();
  out.template topLeftCorner<M::RowsAtCompileTime, M::ColsAtCompileTime>() = a;
  return out;
}

// Objective rotation of a stress over one step with spin increment w (skew):
// Q = (I - w/2)^-1 (I + w/2) is exactly orthogonal (Hughes & Winget 1980), so a
// rigid rotation never changes the invariants, and Q sigma Q^T agrees with the
// Jaumann rate sigma w^T + w sigma to second order in the step.
inline Mat3 rotate_stress(const Mat3& stress, const Mat3& w) {
  const Mat3 i = Mat3::Identity();
  const Mat3 q = (i - 0.5 * w).inverse() * (i + 0.5 * w);
  return q * stress * q.transpose();
}

}  // namespace talus::mpm
