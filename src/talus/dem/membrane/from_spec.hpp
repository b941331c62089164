#pragma once
// A run's membrane from its validated scenario parameters: the mesh
// generated (or read) and placed, the material set, the pinned particles chosen.
#include "talus/dem/membrane/body.hpp"
#include "talus/dem/params.hpp"

namespace talus::dem::membrane {

// Throws InputError when `fixed` selects no particle of this mesh (e.g.
// "edge" on a closed STL surface).
MembraneBody make_membrane_body(const MembraneSpec& spec, int material);

}  // namespace talus::dem::membrane
