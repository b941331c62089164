#pragma once
// Membrane self-contact (spec/membranes-and-jamming.md §3.2.3, "membrane
// self-contact: membrane particles against triangles"): each particle of a
// membrane, as a sphere of radius d (its thickness, self_contact_radius),
// against the triangles of the same membrane, with the grain-membrane
// contact's law, priority rule and barycentric distribution (contact.hpp), so
// a fold cannot pass through itself.
//
// A particle never touches the triangles around it (distance 0), and it must
// not touch their neighbours either: on a bent or crumpled patch those come
// within d of it with no fold at all. So each particle skips every triangle
// with a corner in its closed one-ring (the particle and its edge neighbours):
// 24 triangles inside a flat triangular lattice. On a flat sheet the nearest
// triangle left is sqrt(3) spacings away, far beyond d.
//
// Opt-in per membrane ([[membranes]] self_contact = true): membrane_step.cpp
// calls it once per force pass, on one thread, with the triangle grid the
// grain contacts use.
#include <span>
#include <vector>

#include "talus/dem/membrane/contact.hpp"
#include "talus/dem/membrane/forces.hpp"

namespace talus::dem::membrane {

// The triangles each vertex skips (CSR, sorted per vertex).
struct SelfExclusion {
  std::vector<int> start, list;
  bool excluded(int vertex, int triangle) const;
  std::size_t count(int vertex) const { return start[vertex + 1] - start[vertex]; }
};
SelfExclusion self_contact_exclusion(const Mesh& mesh);

// Two sheets of thickness d touch when their mid-surfaces are d apart: that is
// where a particle of one (on its mid-surface) starts to overlap a triangle of
// the other as a sphere of radius d.
inline double self_contact_radius(const Membrane& m) { return m.params.thickness; }

// Reused buffers of add_self_contact_forces.
struct SelfContactScratch {
  std::vector<int> candidates, kept;
  std::vector<TriangleContact> selected, touched;
  TriangleGrid::Scratch grid;
};

// Adds the self-contact forces of membrane m at its positions x and
// velocities v to m.f: on each particle i the force F of its contacts, on the
// corners of each touched triangle -w_k F (momentum conserved to round-off).
// `grid` holds m's triangles at x; `memory` the springs (call its
// begin_step() before). Particles in increasing order, so the sums do not
// depend on the thread count. Returns the number of contacts.
int add_self_contact_forces(Membrane& m, const TriangleGrid& grid, const SelfExclusion& exclusion,
                            double radius, const ContactLaw::Coeffs& coeffs, double dt,
                            ContactMemory& memory, SelfContactScratch& scratch);

}  // namespace talus::dem::membrane
