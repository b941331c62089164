#pragma once
// A rigid sphere that moves on a prescribed path and touches membranes: the
// object of the granular gripper (spec/membranes-and-jamming.md, Götz 2024
// §4.2), pushed into the gripper and pulled out again at set speeds. Its
// motion is not integrated: x(t) and v(t) follow from its legs exactly, so
// the force the membranes exert on it is a measurement, not a cause. It
// touches the membranes' triangles with the grain-membrane law (contact.hpp),
// the sphere as the "grain"; it does not touch grains (in the gripper they
// are all inside the membrane).
#include <string>
#include <vector>

#include "talus/dem/membrane/contact.hpp"
#include "talus/dem/membrane/forces.hpp"

namespace talus::dem::membrane {

// Constant velocity from `start` to `stop` (s); at rest outside every leg.
struct SphereLeg {
  double start = 0.0, stop = 0.0;
  Vec3 velocity = Vec3::Zero();
};

struct DrivenSphere {
  std::string name;
  double radius = 0.0;
  int material = 0;                         // index into DemSystem::materials
  Vec3 origin = Vec3::Zero();               // centre at t = 0
  std::vector<SphereLeg> legs;              // in time order, not overlapping
  double active_from = 0.0;                 // s: no contacts before (not yet placed)
  Vec3 x = Vec3::Zero(), v = Vec3::Zero();  // at the time of the last force pass
  // The membranes' contact force on the sphere in the last force pass (the
  // reactions on the membrane particles are its negative), and the contacts.
  Vec3 force = Vec3::Zero();
  int contacts = 0;
  std::vector<ContactMemory> memory;  // friction springs, one per membrane
};

// Centre and velocity at time t: origin + sum of velocity x (time spent in
// each leg up to t). Exact for piecewise-constant velocities.
Vec3 position_at(const DrivenSphere& o, double t);
Vec3 velocity_at(const DrivenSphere& o, double t);

// Contacts of the sphere (at o.x, o.v) with the given triangles of membrane
// m: the force on the sphere is returned and the reactions -w_k F are added
// to m.f. The tangential damping sees the mass of the membrane point alone
// (the sphere is as if infinitely heavy). `memory` needs its begin_step().
GrainForce driven_sphere_forces(const DrivenSphere& o, Membrane& m,
                                std::span<const TriangleContact> contacts,
                                const ContactLaw::Coeffs& coeffs, double dt, ContactMemory& memory);

}  // namespace talus::dem::membrane
