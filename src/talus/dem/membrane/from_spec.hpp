#pragma once
// A run's membrane from its validated scenario parameters: the mesh
// generated (or read) and placed, the material set, the pinned particles chosen.
#include "talus/dem/membrane/body.hpp"
#include "talus/dem/params.hpp"
#include "talus/geometry/wall.hpp"

namespace talus::dem::membrane {

// Throws InputError when `fixed` selects no particle of this mesh (e.g.
// "edge" on a closed STL surface).
MembraneBody make_membrane_body(const MembraneSpec& spec, int material);

// Makes the pinned end rings of a cylinder follow the walls the spec names
// (bottom_ring_wall, top_ring_wall): their particles' `follows` and `anchor`
// (position less the wall's displacement at t = 0). Throws InputError for a
// name that is not one of `walls`.
void attach_rings(MembraneBody& body, const MembraneSpec& spec,
                  const std::vector<geometry::Wall>& walls);

// The spec and the built body of the membrane `name` (the protocols' set-up
// after the builder made the membranes). Throws InputError naming `section`
// when either is missing.
struct NamedMembrane {
  const MembraneSpec& spec;
  MembraneBody& body;
};
NamedMembrane named_membrane(const std::vector<MembraneSpec>& specs,
                             std::vector<MembraneBody>& bodies, const std::string& name,
                             const std::string& section);

}  // namespace talus::dem::membrane
