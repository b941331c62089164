#pragma once
// One particle touching a wall: what the contact law sees, and the force and
// torque it gives the particle. Shared by the CPU stepper and the GPU backend
// (dem_gpu/), which call it on their own particle arrays.
#include "talus/dem/contact/kinematics.hpp"
#include "talus/geometry/primitive.hpp"

namespace talus::dem {

template <int D>
struct WallTouch {
  ContactKinematics<D> kin;
  double ci;  // lever arm from the centre to the contact point (middle of the overlap)
};

// Particle i (any container with the Particles field names) at closest wall
// point c; `v_wall` is the wall's velocity there, nullptr for a wall at rest.
template <int D, class P>
TALUS_HOT WallTouch<D> wall_touch(const P& p, int i, const geometry::Closest<D>& c,
                                  const typename Space<D>::Vec* v_wall) {
  WallTouch<D> out;
  auto& kin = out.kin;
  kin.n = c.normal;
  kin.overlap = p.r[i] - c.distance;
  out.ci = p.r[i] - 0.5 * kin.overlap;
  kin.r_eff = p.r[i];
  kin.m_eff = p.m[i];
  kin.inertia_eff = 1.0 / p.inv_I[i] + p.m[i] * p.r[i] * p.r[i];
  typename Space<D>::Vec vrel = p.v[i];
  if (v_wall) vrel -= *v_wall;
  kin.vn = vrel.dot(kin.n);
  kin.vt = vrel - kin.vn * kin.n - Space<D>::cross(out.ci * p.w[i], kin.n);
  kin.w_rel = p.w[i];
  return out;
}

// Adds the law's result to particle i and counts the contact; returns the
// force on the particle (the wall takes its opposite).
template <int D, class P>
TALUS_HOT typename Space<D>::Vec apply_wall_force(P& p, int i, const WallTouch<D>& touch,
                                                  const ContactForce<D>& cf) {
  const typename Space<D>::Vec f = cf.fn * touch.kin.n + cf.ft;
  p.f[i] += f;
  p.t[i] += touch.ci * (-Space<D>::cross(touch.kin.n, cf.ft)) + cf.roll_torque;
  ++p.wall_contacts[i];
  return f;
}

}  // namespace talus::dem
