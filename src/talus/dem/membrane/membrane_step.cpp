#include "talus/dem/membrane/membrane_step.hpp"

#include <algorithm>

#include "talus/dem/contact/pair_coefficients.hpp"

namespace talus::dem::membrane {

MembraneStep::MembraneStep(const DemSystem<3>& s) {
  const auto& mats = s.materials;
  for (const auto& grain : mats)
    for (const auto& m : s.membranes) {
      const auto& wall = mats[m.material];
      coeffs_.push_back(
          ContactLaw::make(s.contact, grain, wall, pair_coefficients(s.contact, grain, wall)));
    }
  for (const auto& m : s.membranes) {
    const auto& wall = mats[m.material];
    self_coeffs_.push_back(
        ContactLaw::make(s.contact, wall, wall, pair_coefficients(s.contact, wall, wall)));
    self_exclusion_.push_back(m.self_contact ? self_contact_exclusion(m.body.mesh)
                                             : SelfExclusion{});
  }
  grids_.resize(s.membranes.size());
  edge_forces_.resize(s.membranes.size());
}

namespace {

// The force that moves particle i: on a rigid core the core takes the inward
// radial part (a frictionless unilateral contact); m.f keeps the whole force,
// so the core's load is what analysis reads from it.
Vec3 free_force(const MembraneBody& mb, std::size_t i) {
  const Vec3& f = mb.body.f[i];
  if (!mb.on_core(mb.body.x[i])) return f;
  const Vec3 e = (mb.body.x[i] - mb.core_centre).normalized();
  const double fr = f.dot(e);
  return fr < 0 ? Vec3(f - fr * e) : f;
}

// Back onto the core a particle that drifted into it, without its inward speed.
void keep_off_core(const MembraneBody& mb, Vec3& x, Vec3& v) {
  const Vec3 d = x - mb.core_centre;
  const double r = d.norm();
  if (!(r < mb.core_radius) || !(r > 0)) return;
  const Vec3 e = d / r;
  x = mb.core_centre + mb.core_radius * e;
  const double vr = v.dot(e);
  if (vr < 0) v -= vr * e;
}

}  // namespace

void MembraneStep::kick(DemSystem<3>& s, double h) const {
  for (auto& mb : s.membranes) {
    auto& m = mb.body;
    for (std::size_t i = 0; i < m.x.size(); ++i)
      if (!m.fixed[i]) m.v[i] += (h / m.mass[i]) * free_force(mb, i) + h * s.gravity;
  }
}

void MembraneStep::step(DemSystem<3>& s) {
  const double dt = s.dt;
  // The beam rig's damping, split off the step: every velocity (the grains'
  // at t + dt/2) falls by the exact decay of dv/dt = -damping v over dt.
  double decay = 1.0;
  for (const auto& mb : s.membranes)
    if (mb.rig) decay = std::min(decay, damping_factor(*mb.rig, s.time, dt));
  if (decay < 1.0) {
    auto& p = s.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.v[i] *= decay;
      p.w[i] *= decay;
    }
    for (auto& mb : s.membranes)
      for (auto& v : mb.body.v) v *= decay;
  }
  kick(s, 0.5 * dt);
  for (auto& mb : s.membranes) {
    auto& m = mb.body;
    for (std::size_t i = 0; i < m.x.size(); ++i) {
      if (!m.fixed[i]) {
        m.x[i] += dt * m.v[i];
        if (mb.core_radius > 0) keep_off_core(mb, m.x[i], m.v[i]);
      } else if (m.follows[i] >= 0) {  // the walls are already at the new time
        const auto& w = s.walls[m.follows[i]];
        m.x[i] = m.anchor[i] + w.displacement(s.time);
        m.v[i] = w.velocity_at(m.x[i], s.time);
      }
    }
    if (mb.rig) {
      hold_in_mould(*mb.rig, m, s.time);
      move_rods(*mb.rig, m, s.time);
    }
  }
  compute_forces(s);
  kick(s, 0.5 * dt);
}

void MembraneStep::contact_lane(DemSystem<3>& s, int k, int lane, std::size_t begin,
                                std::size_t end, const Vec3& lo, const Vec3& hi) {
  auto& p = s.particles;
  auto& mb = s.membranes[k];
  auto& m = mb.body;
  Lane& L = lanes_[lane];
  for (std::size_t i = begin; i < end; ++i) {
    const Vec3& c = p.x[i];
    if ((c.array() < lo.array()).any() || (c.array() > hi.array()).any()) continue;
    grids_[k].query(c, p.r[i], L.candidates, L.scratch);
    if (L.candidates.empty()) continue;
    select_contacts(m.mesh, m.x, c, p.r[i], L.candidates, L.selected, L.touched);
    if (L.selected.empty()) continue;
    const Grain g{c, p.v[i], p.w[i], p.r[i], p.m[i]};
    const GrainForce gf =
        grain_membrane_forces(m.mesh, m.x, m.v, L.reactions, p.id[i], g, L.selected,
                              coeffs(p.material[i], k), s.dt, mb.memory, lane);
    force_[i] += gf.force;
    if (!s.contact.lock_rotation) torque_[i] += gf.torque;
    contacts_[i] += gf.contacts;
    L.contacts += gf.contacts;
  }
}

void MembraneStep::compute_forces(DemSystem<3>& s) {
  auto& p = s.particles;
  const std::size_t n = p.size();
  force_.assign(n, Vec3::Zero());
  torque_.assign(n, Vec3::Zero());
  contacts_.assign(n, 0);
  double r_max = 0.0;
  for (double r : p.r) r_max = std::max(r_max, r);
  for (auto& mb : s.membranes) {
    release_if_due(mb, s.time);
    if (mb.rig) pin_supports_if_due(*mb.rig, mb.body, s.time);
  }
  for (auto& o : s.objects) {
    o.x = position_at(o, s.time);
    o.v = velocity_at(o, s.time);
    o.force.setZero();
    o.contacts = 0;
  }
  for (int k = 0; k < num_membranes(); ++k) {
    auto& mb = s.membranes[k];
    auto& m = mb.body;
    std::fill(m.f.begin(), m.f.end(), Vec3::Zero());
    if (mb.ramp_end > 0) m.params.pressure = pressure_at(mb, s.time);
    add_internal_forces_tasks(m, edge_forces_[k]);
    mb.memory.begin_step(kLanes);
    // The triangles' bounding box, grown by the largest grain radius: grains
    // outside it cannot touch (most grains, most steps).
    Vec3 lo = Vec3::Constant(1e300), hi = -lo;
    for (const Vec3& x : m.x) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    lo.array() -= r_max;
    hi.array() += r_max;
    // Rebuilt every step: one pass over the triangles, cheaper than the
    // internal forces, and never stale. Self-contact queries the same grid
    // with the radius d: the cell must suit that too when there are no
    // grains (r_max = 0 would make it tiny).
    const double self_radius = self_contact_radius(m);
    double cell = mb.self_contact ? std::max(2.0 * r_max, 2.0 * self_radius) : 2.0 * r_max;
    // Without grains a driven sphere still needs cells of some size.
    if (!(cell > 0) && !s.objects.empty()) cell = s.objects.front().radius;
    grids_[k].build(m.mesh, m.x, cell);
    if (mb.self_contact) {
      mb.self_memory.begin_step(1);
      mb.self_contacts =
          add_self_contact_forces(m, grids_[k], self_exclusion_[k], self_radius, self_coeffs_[k],
                                  s.dt, mb.self_memory, self_scratch_);
    }
    // Tasks for the team's other threads (they wait at the end of the
    // caller's omp single); outside a parallel region the loop runs here.
#pragma omp taskloop num_tasks(kLanes) default(shared)
    for (int lane = 0; lane < kLanes; ++lane) {
      lanes_[lane].reactions.clear();
      lanes_[lane].contacts = 0;
      contact_lane(s, k, lane, n * lane / kLanes, n * (lane + 1) / kLanes, lo, hi);
    }
    mb.contacts = 0;
    for (const Lane& L : lanes_) {
      for (const auto& [v, f] : L.reactions) m.f[v] += f;
      mb.contacts += L.contacts;
    }
    object_contacts(s, k);
    if (mb.rig) {
      add_load(*mb.rig, m, s.time);
      mb.rig->rod_force = rods_push(*mb.rig, m, s.gravity);
      mb.rig->rod_impulse += mb.rig->rod_force * s.dt;
    }
    mb.reaction.setZero();
    for (std::size_t i = 0; i < m.x.size(); ++i)
      if (m.fixed[i]) mb.reaction -= m.f[i] + m.mass[i] * s.gravity;
  }
}

void MembraneStep::object_contacts(DemSystem<3>& s, int k) {
  auto& m = s.membranes[k].body;
  Lane& L = lanes_[0];
  for (auto& o : s.objects) {
    auto& memory = o.memory[k];
    memory.begin_step(1);
    if (s.time < o.active_from) continue;
    grids_[k].query(o.x, o.radius, L.candidates, L.scratch);
    if (L.candidates.empty()) continue;
    select_contacts(m.mesh, m.x, o.x, o.radius, L.candidates, L.selected, L.touched);
    const GrainForce gf =
        driven_sphere_forces(o, m, L.selected, coeffs(o.material, k), s.dt, memory);
    o.force += gf.force;
    o.contacts += gf.contacts;
  }
}

double MembraneStep::internal_time_step(const DemSystem<3>& s) const {
  double best = 1e300;
  for (const auto& mb : s.membranes) best = std::min(best, membrane::critical_time_step(mb.body));
  return best;
}

double MembraneStep::contact_time_step(const DemSystem<3>& s, std::span<const double> m_min,
                                       std::span<const double> r_min, double v_ref) const {
  double best = 1e300;
  for (int k = 0; k < num_membranes(); ++k) {
    const auto& m = s.membranes[k].body;
    double mv = 1e300;
    for (std::size_t i = 0; i < m.x.size(); ++i)
      if (!m.fixed[i]) mv = std::min(mv, m.mass[i]);
    // A membrane with every particle fixed (a rigid body) is infinitely
    // heavy: the grain's own mass is the reduced mass.
    for (std::size_t a = 0; a < m_min.size(); ++a) {
      if (m_min[a] >= 1e300) continue;
      const double me = mv >= 1e300 ? m_min[a] : m_min[a] * mv / (m_min[a] + mv);
      best = std::min(best, ContactLaw::critical_time_step(coeffs(static_cast<int>(a), k), me,
                                                           r_min[a], v_ref));
    }
    // A driven sphere yields nothing: the membrane particle's mass alone.
    if (mv < 1e300)
      for (const auto& o : s.objects)
        best = std::min(best,
                        ContactLaw::critical_time_step(coeffs(o.material, k), mv, o.radius, v_ref));
    // Two particles of mass mv: the least reduced mass a self-contact can
    // have (the contact point's mass is at least mv).
    if (s.membranes[k].self_contact && mv < 1e300)
      best = std::min(best, ContactLaw::critical_time_step(self_coeffs_[k], 0.5 * mv,
                                                           self_contact_radius(m), v_ref));
  }
  return best;
}

}  // namespace talus::dem::membrane
