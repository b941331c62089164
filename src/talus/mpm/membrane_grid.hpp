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
// Membranes are few points: these loops are serial.
#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "talus/core/error.hpp"
#include "talus/mpm/grid.hpp"
#include "talus/mpm/membrane.hpp"

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

// Adds mass and momentum (and with forces, gravity and internal forces) of the
// membranes to the grid's arrays, before the ghost nodes are folded.
template <int D, class Shape>
void membranes_to_grid(std::vector<Membrane<D>>& ms, Grid<D>& grid,
                       const typename Space<D>::Vec& gravity, double half_width, bool forces,
                       double time) {
  using Vec = typename Space<D>::Vec;
  Stencil<D, Shape> st;
  std::vector<Vec> cable;
  for (auto& m : ms) {
    const bool fe = m.model == MembraneModel::FiniteElement;
    if (forces && fe) {
      cable.assign(m.size(), Vec::Zero());
      m.add_cable_forces(cable);
    }
    for (std::size_t i = 0; i < m.size(); ++i) {
      if (!membrane_detail::on_grid(m, i)) continue;
      if (!st.compute(grid, m.x[i], half_width)) membrane_detail::left_grid(time, m.name, i);
      const Vec mv = m.mass[i] * m.v[i];
      Vec f = m.mass[i] * gravity;
      if (forces && fe) f += cable[i];
      // York: V sigma = l0 lambda T t (x) t, with T = J max(eps, 0).
      const double vs = !fe && forces ? m.rest_length[i] * m.stretch[i] * m.tension(i) : 0.0;
      for (int k = 0; k < st.count; ++k) {
        const auto a = st.node[k];
        grid.mass[a] += st.w[k] * m.mass[i];
        grid.momentum[a] += st.w[k] * mv;
        if (!forces) continue;
        grid.force[a] += st.w[k] * f;
        if (!fe) grid.force[a] -= vs * m.tangent[i].dot(st.grad[k]) * m.tangent[i];
      }
    }
  }
}

// Zeroes `field` on the nodes that carry a fixed York point.
template <int D, class Shape>
void clamp_membrane_nodes(const std::vector<Membrane<D>>& ms, const Grid<D>& grid,
                          std::vector<typename Space<D>::Vec>& field, double half_width) {
  Stencil<D, Shape> st;
  for (const auto& m : ms) {
    if (m.model != MembraneModel::York) continue;
    for (std::size_t i = 0; i < m.size(); ++i) {
      if (!m.fixed[i] || !st.compute(grid, m.x[i], half_width)) continue;
      for (int k = 0; k < st.count; ++k)
        if (st.w[k] > 0.0) field[st.node[k]].setZero();
    }
  }
}

// Step 3 of the solver for the membranes: the new velocities, the FLIP share
// `flip` of the increment plus the PIC rest, from grid.velocity and
// grid.velocity_old.
template <int D, class Shape>
void membranes_velocities(std::vector<Membrane<D>>& ms, const Grid<D>& grid, double flip,
                          double half_width) {
  using Vec = typename Space<D>::Vec;
  Stencil<D, Shape> st;
  for (auto& m : ms) {
    for (std::size_t i = 0; i < m.size(); ++i) {
      if (m.fixed[i]) {
        m.v[i].setZero();
        continue;
      }
      st.compute(grid, m.x[i], half_width);  // checked in membranes_to_grid
      Vec dv = Vec::Zero(), v_pic = Vec::Zero();
      for (int k = 0; k < st.count; ++k) {
        dv += st.w[k] * (grid.velocity[st.node[k]] - grid.velocity_old[st.node[k]]);
        v_pic += st.w[k] * grid.velocity[st.node[k]];
      }
      m.v[i] = flip * (m.v[i] + dv) + (1.0 - flip) * v_pic;
    }
  }
}

// Moves the free points with grid.velocity; York's tangents and stretches
// follow the gradient of that same field, so that a point's line element
// stretches exactly as the field carries its neighbours, with USL and MUSL
// alike. (MUSL's re-mapped field carries the FLIP noise of the points'
// velocities; with it, the York line of tests/mpm/test_mpm_membrane_dynamics
// rang and separated within 0.45 s at flip 0.99, measured.) Known limit,
// measured (docs/validation.md "Membranes in MPM"): a York line at an angle to
// the grid separates under load, since -V sigma grad N_i gives nodes that a
// point barely reaches (N_i -> 0) forces out of proportion to their mass; the
// FE cables map nodal forces with N_i and do not have this problem.
template <int D, class Shape>
void membranes_move(std::vector<Membrane<D>>& ms, const Grid<D>& grid, double dt,
                    double half_width) {
  using Vec = typename Space<D>::Vec;
  using Mat = typename Membrane<D>::Mat;
  Stencil<D, Shape> st;
  for (auto& m : ms) {
    const bool york = m.model == MembraneModel::York;
    for (std::size_t i = 0; i < m.size(); ++i) {
      if (m.fixed[i] && !york) continue;
      st.compute(grid, m.x[i], half_width);
      Vec v_move = Vec::Zero();
      Mat grad = Mat::Zero();
      for (int k = 0; k < st.count; ++k) {
        v_move += st.w[k] * grid.velocity[st.node[k]];
        if (york) grad += grid.velocity[st.node[k]] * st.grad[k].transpose();
      }
      if (york) m.velocity_gradient[i] = grad;
      if (!m.fixed[i]) m.x[i] += dt * v_move;
    }
    if (york) m.update_york_strain(dt);
  }
}

}  // namespace talus::mpm
