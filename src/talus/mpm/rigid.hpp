#pragma once
// Rigid bodies with prescribed motion, given by boundary particles (Hamad et
// al., eq. 10; mpm.md "Boundaries and contact"): massless points that carry a
// weight (their volume) and move with a prescribed translation plus a rotation
// about a hinge. Each step their velocities are mapped to the nodes of their
// stencils, v_i = sum w_p N_ip v_p / sum w_p N_ip, and the nodes shared with
// the material are corrected by Bardenhagen et al.'s (2000) friction contact,
// with the rigid body's nodal velocity in place of the centre-of-mass velocity.
// Contact normals: each boundary particle carries the outward normal of the
// body's surface nearest to it, and the nodal normal is their weighted mean,
// n_i = -sum w_p N_ip n_p / |.| (into the body). Nairn's volume-gradient
// normals, sum w_p grad N_i(x_p), scatter by up to 10 degrees around a plate
// that is not aligned with the grid (measured, docs/design.md "MPM"); a normal
// off by d turns a sliding speed u into a spurious approach u sin d at every
// step, which Coulomb friction then brakes, and the block locked on a 26.7
// degree plate with mu = 0.3.
#include <cstdint>
#include <limits>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::mpm {

// Translation plus rotation about a hinge that travels with the translation,
// active for start <= t < stop (at rest outside).
struct RigidMotion {
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();  // rad/s; 2D uses z
  Vec3 hinge = Vec3::Zero();             // at t = 0
  double start = 0.0;
  double stop = std::numeric_limits<double>::infinity();
};

// How a rigid body acts on the material at the nodes it shares with it.
enum class RigidContact {
  Friction,  // Bardenhagen: no penetration, Coulomb friction mu, free to separate
  Stick      // Hamad eq. 10: the nodes take the prescribed velocity
};

template <int D>
struct RigidBody {
  using Vec = typename Space<D>::Vec;

  std::vector<Vec> x;
  std::vector<double> weight;  // volume of each boundary particle
  std::vector<Vec> normal;     // outward unit normal of the nearest surface
  RigidMotion motion;
  Vec hinge = Vec::Zero();  // current position of the hinge
  RigidContact contact = RigidContact::Friction;
  double friction = 0.0;  // Coulomb coefficient mu

  // Rotation angle since t = 0 (2D: angle about z).
  double angle = 0.0;
  // Work its contact has done on the material (J; J/m in 2D): per step and
  // node, the momentum the contact gave, m (v_after - v_before), times the
  // body's velocity there. Zero for a body at rest; the energy check counts it.
  double work = 0.0;

  // Time in [t0, t1] during which the motion is active.
  double active_time(double t0, double t1) const;
  // Prescribed velocity at point y for a step starting at t of length dt
  // (the mean over the step: exact for a rigid motion that starts or stops
  // inside it).
  Vec velocity_at(const Vec& y, double t, double dt) const;
  // Moves the points by the exact rotation and translation over [t, t + dt].
  void advance(double t, double dt);
  // Largest prescribed speed of a point at time t (for the time step).
  double max_speed(double t) const;
};

// Nodal fields of one rigid body for one step, kept sparse: only the nodes in
// the stencils of its points are touched.
template <int D>
struct RigidNodes {
  using Vec = typename Space<D>::Vec;
  std::vector<double> weight;  // sum w_p N_ip, per grid node
  std::vector<Vec> momentum;   // sum w_p N_ip v_p
  std::vector<Vec> normal;     // sum w_p N_ip n_p, points out of the body
  std::vector<std::int64_t> touched;

  void reset(std::int64_t nodes);
};

// The Bardenhagen correction of one material node velocity v against a rigid
// node of velocity vr and unit normal n (into the rigid body). Approaching
// (relative normal velocity into the rigid body) nodes lose the normal
// relative velocity; the tangential one is removed if mu times the normal
// correction suffices (stick) or reduced by it (slip).
template <class Vec>
Vec friction_contact(const Vec& v, const Vec& vr, const Vec& n, double mu) {
  const Vec dv = v - vr;
  const double dn = dv.dot(n);
  if (dn <= 0.0) return v;  // separating or sliding along
  const Vec dt = dv - dn * n;
  const double t = dt.norm();
  if (t <= mu * dn) return vr;
  return v - dn * n - (mu * dn / t) * dt;
}

}  // namespace talus::mpm
