#pragma once
// A membrane as part of a DEM run: the mass-spring membrane, the material its
// contacts with grains use, their friction springs, and what the outputs report.
#include <optional>
#include <string>

#include "talus/dem/membrane/beam_rig.hpp"
#include "talus/dem/membrane/contact.hpp"
#include "talus/dem/membrane/forces.hpp"
#include "talus/dem/params.hpp"

namespace talus::dem::membrane {

struct MembraneBody {
  std::string name;
  Membrane body;
  int material = 0;  // index into DemSystem::materials, for grain-membrane contacts
  ContactMemory memory;
  // Force the supports exert on the fixed particles in the last force pass:
  // -sum over fixed i of (f_i + m_i g). At rest it carries the weight of
  // everything the membrane holds.
  Vec3 reaction = Vec3::Zero();
  int contacts = 0;  // grain-membrane contacts in the last force pass
  // A ramped pressure (ramp_end > 0): 0 before ramp_start, `pressure` from
  // ramp_end on, linear in between. MembraneStep then sets body.params.pressure
  // from it before each force pass, so a resumed run needs no state for it;
  // without a ramp body.params.pressure holds at all times.
  double pressure = 0.0, ramp_start = 0.0, ramp_end = 0.0;
  // A stepped ramp (the gripper's vacuum "applied stepwise"): the ramp's
  // interval is cut into pressure_steps equal steps; in each the pressure
  // rises by pressure / pressure_steps during the first step_rise fraction of
  // the step and then holds. 1 step with step_rise 1 is the linear ramp.
  int pressure_steps = 1;
  double step_rise = 1.0;
  // Held particles (the gripper's filling, Götz 2024 §4.2): pinned (fixed)
  // until release_time; then free, and every rest length becomes
  // (1 - rest_cut) x release_rest (pre-tension). Applying it twice changes
  // nothing, so a resumed run (released = false again) may apply it again.
  std::vector<char> held;
  double release_time = kNever, rest_cut = 0.0;
  bool released = false;
  std::vector<double> release_rest;  // rest lengths before the cut
  // A rigid core (core_radius > 0) that the particles rest on: MembraneStep
  // keeps them at |x - core_centre| >= core_radius and lets the core take the
  // inward part of the force on a particle that sits on it (on_core).
  double core_radius = 0.0;
  Vec3 core_centre = Vec3::Zero();
  bool on_core(const Vec3& x) const {
    return core_radius > 0 && (x - core_centre).norm() <= core_radius * (1.0 + 1e-9);
  }
  // Contacts of its particles with its own triangles (self_contact.hpp): off
  // unless the scenario asks, since most membranes never fold onto themselves.
  bool self_contact = false;
  ContactMemory self_memory;  // their friction springs, keyed by membrane particle
  int self_contacts = 0;      // in the last force pass
  // The granular beam's mould, supports and load ([beam] runs only).
  std::optional<BeamRig> rig;
};

double pressure_at(const MembraneBody& m, double t);
// Frees the held particles and cuts the rest lengths (see held) once t >=
// release_time; nothing before, nothing new after.
void release_if_due(MembraneBody& m, double t);
double kinetic_energy(const MembraneBody& m);
Vec3 momentum(const MembraneBody& m);
// Mean spring force k_sp (r - r0) of each triangle's three edges (N, > 0 stretched).
std::vector<double> triangle_tension(const MembraneBody& m);

}  // namespace talus::dem::membrane
