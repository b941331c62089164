#pragma once
// The membranes' part of a DEM step (3D): velocity Verlet of the membrane
// particles, their internal and pressure forces, and the grain-membrane
// contacts, whose forces on the grains are kept per grain until the stepper
// adds them before the grains' second half kick. The stepper calls it inside
// its serial section (omp single), after the grains have drifted. The
// grain-membrane contacts, most of the work, run as OpenMP tasks that the
// waiting threads of the team pick up: the grains are cut into kLanes fixed
// index ranges, each with its own reaction list and contact-memory lane, and
// the reactions are added to the membrane in lane order, so the result is the
// same for any number of threads. The internal forces' per-edge terms run as
// tasks too, and are added to the membrane particles in edge order on one thread.
#include <span>
#include <vector>

#include "talus/dem/contact/hertz_mindlin.hpp"
#include "talus/dem/membrane/body.hpp"
#include "talus/dem/membrane/self_contact.hpp"
#include "talus/dem/system.hpp"

namespace talus::dem::membrane {

class MembraneStep {
 public:
  // Contact coefficients per (grain material, membrane) from the system's
  // contact rules (ContactLaw, contact.hpp).
  explicit MembraneStep(const DemSystem<3>& s);

  // Forces of the current state on membrane particles and grains; no motion.
  void compute_forces(DemSystem<3>& s);
  // One step of the membrane particles, called once the grains have drifted
  // to t + dt (their velocities at t + dt/2): half kick with the old forces,
  // drift, forces, half kick with the new ones. Fixed particles stay.
  void step(DemSystem<3>& s);

  // The membrane contact force and torque on grain i (and its contact count),
  // to add before the grain's half kick.
  void add_to_grain(Particles<3>& p, int i) const {
    p.f[i] += force_[i];
    p.t[i] += torque_[i];
    p.wall_contacts[i] += contacts_[i];
  }

  // The membranes' contact force on grain i from the last compute_forces.
  const Vec3& grain_force(int i) const { return force_[i]; }

  // The two bounds of the run's stable step (Stepper::critical_time_step) that
  // the membranes add. Internal: min over membranes of
  // membrane::critical_time_step. Contact: min over membranes and grain
  // materials a of the single Hertz contact at v_ref of the lightest grain of
  // a (mass m_min[a], radius r_min[a], the stepper's per-material minima, 1e300
  // for none) with the lightest free membrane particle, and for a membrane
  // with self-contact that of two of its lightest free particles (radius
  // self_contact_radius); the stepper divides it by the same packing factor
  // as the grains' contacts. A driven sphere against a membrane adds the
  // contact of the sphere with the lightest free particle alone.
  double internal_time_step(const DemSystem<3>& s) const;
  double contact_time_step(const DemSystem<3>& s, std::span<const double> m_min,
                           std::span<const double> r_min, double v_ref) const;

 private:
  void kick(DemSystem<3>& s, double h) const;
  const ContactLaw::Coeffs& coeffs(int grain_material, int membrane) const {
    return coeffs_[static_cast<std::size_t>(grain_material) * grids_.size() + membrane];
  }
  int num_membranes() const { return static_cast<int>(grids_.size()); }

  // The driven spheres (DemSystem::objects) against membrane k, after the
  // grains' lanes, on the calling thread.
  void object_contacts(DemSystem<3>& s, int k);
  // Grains [begin, end) against membrane k in lane `lane`.
  void contact_lane(DemSystem<3>& s, int k, int lane, std::size_t begin, std::size_t end,
                    const Vec3& lo, const Vec3& hi);

  // Fixed, not the thread count: the order of the sums depends on it only.
  static constexpr int kLanes = 16;
  struct Lane {
    std::vector<int> candidates;
    std::vector<TriangleContact> selected, touched;  // select_contacts' out and scratch
    std::vector<std::pair<int, Vec3>> reactions;     // (membrane particle, force)
    TriangleGrid::Scratch scratch;
    int contacts = 0;
  };

  std::vector<ContactLaw::Coeffs> coeffs_;
  // Self-contact (membranes with self_contact only): the membrane's material
  // against itself, the triangles each particle skips, buffers.
  std::vector<ContactLaw::Coeffs> self_coeffs_;
  std::vector<SelfExclusion> self_exclusion_;
  SelfContactScratch self_scratch_;
  std::vector<TriangleGrid> grids_;
  std::vector<EdgeForces> edge_forces_;
  std::vector<Vec3> force_, torque_;
  std::vector<int> contacts_;
  std::vector<Lane> lanes_ = std::vector<Lane>(kLanes);
};

}  // namespace talus::dem::membrane
