#pragma once
// The scalar pair path's geometry: what a contact law sees of two touching
// particles, and the force and torques it gives them. Used by the stepper's
// pair loop and, as the reference, by the tests of the vectorised block loops
// (dem/hertz_pairs, dem/linear_pairs), which must give the same bits.
#include <cmath>

#include "talus/dem/contact/kinematics.hpp"
#include "talus/dem/particles.hpp"

namespace talus::dem {

// The kinematics of particles i and j at distance vector d = x_i - x_j with
// |d|^2 = d2 < (r_i + r_j)^2, and the lever arms ci, cj from their centres to
// the contact point (the middle of the overlap). `with_inertia`: fill
// inertia_eff (laws with rolling damping need it), else 0.
template <int D>
struct PairKinematics {
  ContactKinematics<D> kin;
  double ci, cj;
};
// `p` is a Particles<D> or any view with its field names (the GPU backend's).
template <int D, bool with_inertia, class P>
TALUS_HOT PairKinematics<D> pair_kinematics(const P& p, int i, int j,
                                            const typename Space<D>::Vec& d, double d2) {
  PairKinematics<D> out;
  auto& kin = out.kin;
  const double dist = std::sqrt(d2);
  kin.n = d * (1.0 / dist);
  kin.overlap = (p.r[i] + p.r[j]) - dist;
  out.ci = p.r[i] - 0.5 * kin.overlap;
  out.cj = p.r[j] - 0.5 * kin.overlap;
  kin.r_eff = p.r[i] * p.r[j] / (p.r[i] + p.r[j]);
  kin.m_eff = p.m[i] * p.m[j] / (p.m[i] + p.m[j]);
  if constexpr (with_inertia) {
    const double ia = 1.0 / p.inv_I[i] + p.m[i] * p.r[i] * p.r[i];
    const double ib = 1.0 / p.inv_I[j] + p.m[j] * p.r[j] * p.r[j];
    kin.inertia_eff = ia * ib / (ia + ib);
  } else {
    kin.inertia_eff = 0.0;
  }
  const typename Space<D>::Vec vrel = p.v[i] - p.v[j];
  kin.vn = vrel.dot(kin.n);
  const typename Space<D>::Rot warm = out.ci * p.w[i] + out.cj * p.w[j];
  kin.vt = vrel - kin.vn * kin.n - Space<D>::cross(warm, kin.n);
  kin.w_rel = p.w[i] - p.w[j];
  return out;
}

// Force on i (j gets the opposite) and the torques on i and j of one pair.
template <int D>
struct PairResult {
  typename Space<D>::Vec f;
  typename Space<D>::Rot ti, tj;
};
template <int D>
TALUS_HOT PairResult<D> pair_result(const PairKinematics<D>& pk, const ContactForce<D>& cf) {
  const typename Space<D>::Rot tq = -Space<D>::cross(pk.kin.n, cf.ft);
  return {cf.fn * pk.kin.n + cf.ft, pk.ci * tq + cf.roll_torque, pk.cj * tq - cf.roll_torque};
}

}  // namespace talus::dem
