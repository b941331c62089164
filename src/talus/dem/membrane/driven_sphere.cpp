#include "talus/dem/membrane/driven_sphere.hpp"

#include <algorithm>

namespace talus::dem::membrane {

Vec3 position_at(const DrivenSphere& o, double t) {
  Vec3 x = o.origin;
  for (const SphereLeg& l : o.legs)
    if (t > l.start) x += (std::min(t, l.stop) - l.start) * l.velocity;
  return x;
}

Vec3 velocity_at(const DrivenSphere& o, double t) {
  for (const SphereLeg& l : o.legs)
    if (t >= l.start && t < l.stop) return l.velocity;
  return Vec3::Zero();
}

GrainForce driven_sphere_forces(const DrivenSphere& o, Membrane& m,
                                std::span<const TriangleContact> contacts,
                                const ContactLaw::Coeffs& coeffs, double dt,
                                ContactMemory& memory) {
  // The sphere does not spin; its mass plays no part (rigid_sphere_forces).
  const Grain g{o.x, o.v, Vec3::Zero(), o.radius, 0.0};
  return rigid_sphere_forces(m.mesh, m.x, m.v, m.mass, m.f, 0, g, contacts, coeffs, dt, memory);
}

}  // namespace talus::dem::membrane
