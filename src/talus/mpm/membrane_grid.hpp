#pragma once
// The membranes' part of the MPM step (membrane.hpp), as templates over the
// shape function so the solver calls them from its own shape-specific step:
//  - to the grid: mass, momentum, gravity and the membrane's internal force
//    (FE: the cable forces on the nodes, mapped with N_i; York: the tangent
//    stress, -V sigma grad N_i with V sigma = l0 lambda T t (x) t);
//  - clamps: the grid nodes around a fixed York point are held (an FE
//    anchor node is simply left off the grid: its cables pull its neighbours);
//  - from the grid: velocities (the solver's FLIP/PIC blend), positions, and
//    York's velocity gradient, from which its strain follows.
// A York point's domain is its piece of the line, the segment of current
// length l = l0 lambda along its tangent (YorkStencil), not the square of a
// GIMP particle: the weights are the mean of the shape function's values at
// the segment's ends and the tangential gradient their difference,
// (N_i(end) - N_i(start)) / l, as in CPDI (Sadeghirad et al. 2011), whose
// domains are tracked by their corners. Why (docs/validation.md "Membranes in
// MPM", measured): with the square domains, a line at an angle to the grid is
// integrated inconsistently (the squares do not tile it), so a uniformly
// stretched line puts spurious forces on the nodes and the strain it takes
// from the grid does not add up to the line's elongation; the line's points
// drifted apart without their strain seeing it and the line separated under
// load. With the segments, the strain rate of a point is exactly the relative
// velocity of its ends, and a uniform tension telescopes to the line's ends.
// Membranes are few points: these loops are serial.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <vector>

#include "talus/core/error.hpp"
#include "talus/mpm/field_contact.hpp"
#include "talus/mpm/grid.hpp"
#include "talus/mpm/membrane.hpp"
#include "talus/mpm/water.hpp"

namespace talus::mpm {

namespace membrane_detail {

[[noreturn]] inline void left_grid(double time, const std::string& name, std::size_t i) {
  throw RunError(fmt::format(
      "t = {:.6g} s: point {} of membrane '{}' left the grid or has a non-finite position; "
      "enlarge [grid]",
      time, i + 1, name));
}

// FE anchors are off the grid; everything else is on it.
template <int D>
bool on_grid(const Membrane<D>& m, std::size_t i) {
  return m.model == MembraneModel::York || !m.fixed[i];
}

// Weights and tangential gradients of a York point whose domain is the
// segment x -+ (l / 2) t: w_i = (N_i(a) + N_i(b)) / 2 and t . grad N_i =
// (N_i(b) - N_i(a)) / l, at the ends a, b (the two stencils side by side; a
// node may appear twice). The ends take the plain shape function (GIMP's hat:
// half width 0), the segment being the particle's domain.
template <int D, class Shape>
struct YorkStencil {
  using Vec = typename Space<D>::Vec;
  static constexpr int count = 2 * Stencil<D, Shape>::count;
  std::array<std::int64_t, count> node;
  std::array<double, count> w;
  std::array<double, count> g;  // t . grad N_i, 1/m

  bool compute(const Grid<D>& grid, const Membrane<D>& m, std::size_t i) {
    const double l = m.rest_length[i] * m.stretch[i];
    const Vec half = 0.5 * l * m.tangent[i];
    Stencil<D, Shape> st;
    for (int e = 0; e < 2; ++e) {
      if (!st.compute(grid, e == 0 ? (m.x[i] - half).eval() : (m.x[i] + half).eval(), 0.0))
        return false;
      const double sign = e == 0 ? -1.0 : 1.0;
      for (int k = 0; k < st.count; ++k) {
        node[e * st.count + k] = st.node[k];
        w[e * st.count + k] = 0.5 * st.w[k];
        g[e * st.count + k] = l > 0.0 ? sign * st.w[k] / l : 0.0;
      }
    }
    return true;
  }
};

}  // namespace membrane_detail

// Largest node mass of all membranes (for the solver's empty-node floor).
template <int D>
double membrane_max_mass(const std::vector<Membrane<D>>& ms) {
  double m = 0.0;
  for (const auto& mb : ms)
    for (double mi : mb.mass) m = std::max(m, mi);
  return m;
}

// Largest sqrt(J / mu) + |v| over the membranes (for the CFL step).
template <int D>
double membrane_max_speed(const std::vector<Membrane<D>>& ms) {
  double s = 0.0;
  for (const auto& mb : ms) {
    double v = 0.0;
    for (const auto& vi : mb.v) v = std::max(v, vi.norm());
    s = std::max(s, mb.wave_speed() + v);
  }
  return s;
}

// Adds mass and momentum (and with forces, gravity and internal forces) of
// membrane m to the grid's arrays, before the ghost nodes are folded. With
// on_nodes (an FE membrane in the membranes' own field), also what its
// contact with the soil needs (field_contact.hpp).
template <int D, class Shape>
void membrane_to_grid(Membrane<D>& m, Grid<D>& grid, const typename Space<D>::Vec& gravity,
                      double half_width, bool forces, double time,
                      MembraneNodes<D>* on_nodes = nullptr) {
  using Vec = typename Space<D>::Vec;
  Stencil<D, Shape> st;
  membrane_detail::YorkStencil<D, Shape> ys;
  std::vector<Vec> cable, unit;
  const bool fe = m.model == MembraneModel::FiniteElement;
  if (forces && fe) {
    cable.assign(m.size(), Vec::Zero());
    m.add_cable_forces(cable);
  }
  if (on_nodes) m.node_normals(unit);
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (!membrane_detail::on_grid(m, i)) continue;
    const Vec mv = m.mass[i] * m.v[i];
    Vec f = m.mass[i] * gravity;
    if (fe) {
      if (!st.compute(grid, m.x[i], half_width)) membrane_detail::left_grid(time, m.name, i);
      if (forces) f += cable[i];
      for (int k = 0; k < st.count; ++k) {
        const auto a = st.node[k];
        grid.mass[a] += st.w[k] * m.mass[i];
        grid.momentum[a] += st.w[k] * mv;
        if (forces) grid.force[a] += st.w[k] * f;
        if (on_nodes) on_nodes->add(a, st.w[k] * m.mass[i], unit[i], -st.dx[k], m.soil_friction);
      }
      continue;
    }
    if (!ys.compute(grid, m, i)) membrane_detail::left_grid(time, m.name, i);
    // York: V sigma = l0 lambda T t (x) t, with T = J max(eps, 0).
    const double vs = forces ? m.rest_length[i] * m.stretch[i] * m.tension(i) : 0.0;
    for (int k = 0; k < ys.count; ++k) {
      const auto a = ys.node[k];
      grid.mass[a] += ys.w[k] * m.mass[i];
      grid.momentum[a] += ys.w[k] * mv;
      if (forces) grid.force[a] += ys.w[k] * f - (vs * ys.g[k]) * m.tangent[i];
    }
  }
}

// membrane_to_grid for every membrane, all on one grid.
template <int D, class Shape>
void membranes_to_grid(std::vector<Membrane<D>>& ms, Grid<D>& grid,
                       const typename Space<D>::Vec& gravity, double half_width, bool forces,
                       double time) {
  for (auto& m : ms) membrane_to_grid<D, Shape>(m, grid, gravity, half_width, forces, time);
}

// The water's drag on membrane m (water.hpp), after the grid update: each
// submerged node's drag, from the updated grid velocity at the node, changes
// the velocities of its stencil's nodes by dt N_i F / m_i (the momentum
// dt F in all, unless a node's normal velocity would reverse: it stops). The grid's field, not the
// node's own FLIP velocity: a node's FLIP velocity gathers the large changes of the light nodes
// only the membrane reaches and lags the body it wraps; with it the bag of tests/mpm/test_water.cpp
// sank 4 % faster than its terminal velocity (measured; with PIC throughout, 1 %).
template <int D, class Shape>
void membrane_drag(const Membrane<D>& m, Grid<D>& grid, const WaterParams& water, double dt,
                   double half_width, double mass_floor) {
  using Vec = typename Space<D>::Vec;
  if (m.model != MembraneModel::FiniteElement) return;
  std::vector<Vec> unit;
  m.node_normals(unit);
  Stencil<D, Shape> st;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (!membrane_detail::on_grid(m, i) || !(m.x[i][D - 1] < water.level)) continue;
    st.compute(grid, m.x[i], half_width);  // checked in membrane_to_grid
    Vec v = Vec::Zero();
    for (int k = 0; k < st.count; ++k) v += st.w[k] * grid.velocity[st.node[k]];
    // The drag lies along n: it changes each node's normal velocity, and never
    // reverses it (a light node only the membrane reaches could overshoot).
    const Vec& n = unit[i];
    const double f = water_drag<D>(water, m, i, v, n).dot(n);
    if (f == 0.0) continue;
    for (int k = 0; k < st.count; ++k) {
      const auto a = st.node[k];
      if (grid.mass[a] <= mass_floor) continue;
      const double un = grid.velocity[a].dot(n);
      double du = dt * st.w[k] / grid.mass[a] * f;
      if (un * (un + du) < 0.0) du = -un;
      grid.velocity[a] += du * n;
    }
  }
}

// Zeroes `field` on the nodes that carry a fixed York point of m.
template <int D, class Shape>
void clamp_membrane_nodes(const Membrane<D>& m, const Grid<D>& grid,
                          std::vector<typename Space<D>::Vec>& field, double half_width) {
  if (m.model != MembraneModel::York) return;
  Stencil<D, Shape> st;
  membrane_detail::YorkStencil<D, Shape> ys;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (!m.fixed[i]) continue;
    // The nodes around the point, and those its segment reaches.
    if (st.compute(grid, m.x[i], half_width))
      for (int k = 0; k < st.count; ++k)
        if (st.w[k] > 0.0) field[st.node[k]].setZero();
    if (ys.compute(grid, m, i))
      for (int k = 0; k < ys.count; ++k)
        if (ys.w[k] > 0.0) field[ys.node[k]].setZero();
  }
}

// Step 3 of the solver for membrane m: the new velocities, the FLIP share
// `flip` of the increment plus the PIC rest, from grid.velocity and
// grid.velocity_old.
template <int D, class Shape>
void membrane_velocities(Membrane<D>& m, const Grid<D>& grid, double flip, double half_width) {
  using Vec = typename Space<D>::Vec;
  Stencil<D, Shape> st;
  membrane_detail::YorkStencil<D, Shape> ys;
  const bool york = m.model == MembraneModel::York;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m.fixed[i]) {
      m.v[i].setZero();
      continue;
    }
    Vec dv = Vec::Zero(), v_pic = Vec::Zero();
    auto add = [&](const auto& s) {  // checked in membrane_to_grid
      for (int k = 0; k < s.count; ++k) {
        dv += s.w[k] * (grid.velocity[s.node[k]] - grid.velocity_old[s.node[k]]);
        v_pic += s.w[k] * grid.velocity[s.node[k]];
      }
    };
    if (york) {
      ys.compute(grid, m, i);
      add(ys);
    } else {
      st.compute(grid, m.x[i], half_width);
      add(st);
    }
    m.v[i] = flip * (m.v[i] + dv) + (1.0 - flip) * v_pic;
  }
}

// Moves the free points with grid.velocity; York's tangents and stretches
// follow the gradient of that same field along the point's segment, so that a
// point's line element stretches exactly as the field carries its ends, with
// USL and MUSL alike. (MUSL's re-mapped field carries the FLIP noise of the
// points' velocities; with it, the York line of
// tests/mpm/test_mpm_membrane_dynamics rang and separated within 0.45 s at
// flip 0.99, measured.)
template <int D, class Shape>
void membrane_move(Membrane<D>& m, const Grid<D>& grid, double dt, double half_width) {
  using Vec = typename Space<D>::Vec;
  Stencil<D, Shape> st;
  membrane_detail::YorkStencil<D, Shape> ys;
  const bool york = m.model == MembraneModel::York;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m.fixed[i] && !york) continue;
    Vec v_move = Vec::Zero();
    if (!york) {
      st.compute(grid, m.x[i], half_width);
      for (int k = 0; k < st.count; ++k) v_move += st.w[k] * grid.velocity[st.node[k]];
      m.x[i] += dt * v_move;
      continue;
    }
    // York: L t = (v(b) - v(a)) / l, all a material line element along t
    // needs; stored as the rank-one L t (x) t, which maps t to it.
    ys.compute(grid, m, i);
    Vec lt = Vec::Zero();
    for (int k = 0; k < ys.count; ++k) {
      v_move += ys.w[k] * grid.velocity[ys.node[k]];
      lt += ys.g[k] * grid.velocity[ys.node[k]];
    }
    m.velocity_gradient[i] = lt * m.tangent[i].transpose();
    if (!m.fixed[i]) m.x[i] += dt * v_move;
  }
  if (york) m.update_york_strain(dt);
}

// membrane_move for every membrane, all on one grid.
template <int D, class Shape>
void membranes_move(std::vector<Membrane<D>>& ms, const Grid<D>& grid, double dt,
                    double half_width) {
  for (auto& m : ms) membrane_move<D, Shape>(m, grid, dt, half_width);
}

}  // namespace talus::mpm
