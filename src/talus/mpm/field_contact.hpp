#pragma once
// Contact between the soil and the membranes that move in a velocity field of
// their own (`[[membranes]] friction = mu`; Bardenhagen et al. 2000, mpm.md
// "Boundaries and contact"), so sand can slip along the fabric.
//
// Each step both fields are updated, then taken together as one body (mass
// m_s + m_m, the centre-of-mass velocity v_c) on which the walls act: rigid
// bodies, clamps and grid faces. Then each node that carries both is split
// again: where the soil moves toward the membrane relative to v_c, the soil's
// normal relative velocity goes and its tangential one loses Coulomb's mu
// times that (or it sticks to v_c), and the membrane takes the rest of the
// momentum (m_s + m_m) v_c; where the soil moves away both keep their own
// velocities. A node that carries one field takes v_c. Why the walls come
// first: a membrane is light, and a sheet lying on a floor under a block
// passes the floor's reaction to the block. Taken the other way round (the
// contact on the fields' own velocities, then the floor on each), v_c moves
// with the heavy block, the block hardly approaches it, friction has little
// to act on, and the floor holds the block by itself, frictionless. (The
// first version did that and its block slid at g sin(theta), but it also had
// the normal's sign wrong; the order is chosen by this reasoning.)
//
// The normal: its direction is the membranes' own (their nodes' normals mapped
// with their mass, as a rigid body's are: normals from mass gradients scatter
// by up to 10 degrees around a sheet not aligned with the grid, and a wrong
// normal turns sliding into spurious approach that friction brakes, see
// rigid.hpp). Its sign says where the membrane lies from the soil: the
// membranes' mass centre seen from the node minus the soil's. (The soil's
// mass gradient alone, sum m_p grad N_i, has no reliable direction a cell
// inside the soil, where a sheet under a block may still reach: its sign was
// seen to flip there.) Where the membranes' normals cancel (a fold a cell
// wide) that difference of mass centres gives the direction as well. All
// membranes with a friction share one field: two bags in contact do not slip
// on each other.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "talus/mpm/grid.hpp"
#include "talus/mpm/rigid.hpp"

namespace talus::mpm {

// What the membranes of the own field put on the nodes besides mass and
// momentum (none of it folded from ghost nodes): sums over their nodes k of
// N_i m_k times the unit normal n_k, the offset x_k - x_i, 1, and mu_k.
template <int D>
struct MembraneNodes {
  using Vec = typename Space<D>::Vec;
  std::vector<Vec> normal, offset;
  std::vector<double> mass, friction;

  void reset(std::int64_t nodes) {
    normal.assign(nodes, Vec::Zero());
    offset.assign(nodes, Vec::Zero());
    mass.assign(nodes, 0.0);
    friction.assign(nodes, 0.0);
  }
  void add(std::int64_t a, double wm, const Vec& n, const Vec& dx, double mu) {
    normal[a] += wm * n;
    offset[a] += wm * dx;
    mass[a] += wm;
    friction[a] += wm * mu;
  }
};

// One node: the soil (mass ms, velocity vs) and the membranes (mm, vm) after
// the walls acted on their centre-of-mass velocity vc; n the unit normal out
// of the soil toward the membranes. (ms vs + mm vm = (ms + mm) vc after.)
// old_n: the FLIP share of the soil's normal velocity relative to the
// centre of mass before the update, flip (vs_old - vc_old) . n. Friction takes mu times the normal
// velocity change the soil's points feel, (vs - vc) . n - old_n, as at a
// friction face (Grid::constrain_velocity): the whole relative normal
// velocity carries the FLIP noise of the points next to the sheet, and with
// it friction braked the block of tests/mpm/test_field_contact.cpp to a
// steady creep at a slope 10 degrees steeper than atan(mu) (measured).
template <class Vec>
void split_at_node(double ms, Vec& vs, double mm, Vec& vm, const Vec& vc, const Vec& n, double mu,
                   double old_n = 0.0) {
  const Vec dv = vs - vc;
  const double into = dv.dot(n);
  if (into > 0.0) {  // approaching; else separating, the soil keeps vs
    const double felt = std::max(0.0, into - old_n);
    const Vec tangential = dv - into * n;
    const double t = tangential.norm();
    vs = t <= mu * felt ? vc : (vs - into * n - (mu * felt / t) * tangential).eval();
  }
  vm = vc + (ms / mm) * (vc - vs);
}

// split_at_node at every node of `combined` (velocities after the walls)
// that carries more than mass_floor of both; the others take vc. flip: the
// FLIP share of the points' velocity update (0 with APIC); the soil's
// velocity_old as the update left it (no wall applied yet).
// soil_offset: sum of N_i m_p (x_p - x_i) over the soil's points.
template <int D>
void split_contact(const Grid<D>& combined, Grid<D>& soil, Grid<D>& membranes,
                   const std::vector<typename Space<D>::Vec>& soil_offset,
                   const MembraneNodes<D>& on_nodes, double flip, double mass_floor) {
  using Vec = typename Space<D>::Vec;
  const std::int64_t nodes = soil.nodes();
#pragma omp parallel for schedule(static)
  for (std::int64_t a = 0; a < nodes; ++a) {
    const Vec& vc = combined.velocity[a];
    const double ms = soil.mass[a], mm = membranes.mass[a];
    if (ms <= mass_floor || mm <= mass_floor || on_nodes.mass[a] <= 0.0) {
      soil.velocity[a] = ms <= mass_floor ? Vec::Zero().eval() : vc;
      membranes.velocity[a] = mm <= mass_floor ? Vec::Zero().eval() : vc;
      continue;
    }
    // From the soil's mass centre to the membranes' (both seen from the node).
    const Vec apart = on_nodes.offset[a] / on_nodes.mass[a] - soil_offset[a] / ms;
    Vec n = on_nodes.normal[a];
    if (n.squaredNorm() == 0.0) n = apart;
    const double len = n.norm();
    if (len == 0.0) {  // no direction at all: the node moves as one
      soil.velocity[a] = membranes.velocity[a] = vc;
      continue;
    }
    n /= len;
    if (n.dot(apart) < 0.0) n = -n;
    // The soil's velocity before the update as its points carry it, against
    // the centre of mass's as the walls left it (velocity_old of `combined`).
    const double old_n = flip * (soil.velocity_old[a] - combined.velocity_old[a]).dot(n);
    split_at_node<Vec>(ms, soil.velocity[a], mm, membranes.velocity[a], vc, n,
                       on_nodes.friction[a] / on_nodes.mass[a], old_n);
  }
}

}  // namespace talus::mpm
