#pragma once
// What a contact law sees of one contact, and what it keeps between steps.
#include "talus/core/space.hpp"

namespace talus::dem {

template <int D>
struct ContactKinematics {
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;
  Vec n;               // unit normal from j (or the wall) to i
  double overlap;      // > 0 while touching
  double r_eff;        // R_i R_j / (R_i + R_j); R_i for a wall
  double m_eff;        // m_i m_j / (m_i + m_j); m_i for a wall
  double inertia_eff;  // rotational inertia about the contact point, in series (rolling damping)
  double vn;           // n . (v_i - v_j), negative while approaching
  Vec vt;              // tangential relative velocity of the contact points
  Rot w_rel;           // omega_i - omega_j (rolling)
};

// Per-contact memory kept in the pair table: the tangential spring (a
// displacement or a force, as the law defines it) and the rolling spring torque.
template <int D>
struct ContactHistory {
  typename Space<D>::Vec shear = zero_of<typename Space<D>::Vec>();
  typename Space<D>::Rot roll = Space<D>::rot_zero();
};

// Result on particle i; particle j (if any) gets the opposite force.
// The tangential force acts at the contact point, the rolling torque is a pure couple.
template <int D>
struct ContactForce {
  double fn = 0.0;  // along n
  double kn = 0.0;  // current normal stiffness (scales the rolling spring)
  typename Space<D>::Vec ft = zero_of<typename Space<D>::Vec>();  // tangential force
  typename Space<D>::Rot roll_torque = Space<D>::rot_zero();
};

// Removes the component of a tangential spring along the new normal, keeping its
// length (the contact plane rotates with the particles).
template <int D>
TALUS_HOT typename Space<D>::Vec rotate_into_plane(const typename Space<D>::Vec& s,
                                                   const typename Space<D>::Vec& n) {
  const double len2 = s.squaredNorm();
  if (len2 == 0.0) return s;
  typename Space<D>::Vec p = s - s.dot(n) * n;
  const double p2 = p.squaredNorm();
  return p2 > 0.0 ? (p * std::sqrt(len2 / p2)).eval() : p;
}

}  // namespace talus::dem
