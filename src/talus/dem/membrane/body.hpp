#pragma once
// A membrane as part of a DEM run: the mass-spring membrane, the material its
// contacts with grains use, their friction springs, and what the outputs report.
#include <string>

#include "talus/dem/membrane/contact.hpp"
#include "talus/dem/membrane/forces.hpp"

namespace talus::dem::membrane {

struct MembraneBody {
  std::string name;
  Membrane body;
  int material = 0;  // index into DemSystem::materials, for grain-membrane contacts
  // Pressure p reached at t = pressure_ramp after a linear rise from 0 (the
  // source applies a vacuum gradually: a sudden one would throw the membrane
  // onto the grains); ramp 0: body.params.pressure is left as it is.
  double pressure = 0.0, pressure_ramp = 0.0;
  ContactMemory memory;
  // Force the supports exert on the fixed particles in the last force pass:
  // -sum over fixed i of (f_i + m_i g). At rest it carries the weight of
  // everything the membrane holds.
  Vec3 reaction = Vec3::Zero();
  int contacts = 0;  // grain-membrane contacts in the last force pass
  // Contacts of its particles with its own triangles (self_contact.hpp): off
  // unless the scenario asks, since most membranes never fold onto themselves.
  bool self_contact = false;
  ContactMemory self_memory;  // their friction springs, keyed by membrane particle
  int self_contacts = 0;      // in the last force pass
};

double kinetic_energy(const MembraneBody& m);
Vec3 momentum(const MembraneBody& m);
// Mean spring force k_sp (r - r0) of each triangle's three edges (N, > 0 stretched).
std::vector<double> triangle_tension(const MembraneBody& m);

}  // namespace talus::dem::membrane
