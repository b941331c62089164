#pragma once
// The background grid: a regular lattice of nodes of spacing h covering the
// domain plus `kPad` ghost cells on every side, so that the widest stencil
// (cubic B-spline, two cells each side) of any particle inside the domain lies
// on existing nodes and the partition of unity holds everywhere. Node values
// are reset every step.
#include <array>
#include <cstdint>
#include <vector>

#include "talus/core/space.hpp"
#include "talus/mpm/shape.hpp"

namespace talus::mpm {

// What a face of the domain does to the nodes on and beyond it.
enum class BoundaryKind {
  Free,     // nothing
  Roller,   // normal velocity zero, tangential free (frictionless wall)
  Fixed,    // all velocity components zero (rough, no-slip wall)
  Friction  // Coulomb wall: see Grid::constrain_velocity
};

template <int D>
struct Grid {
  using Vec = typename Space<D>::Vec;
  static constexpr int kPad = 2;

  Vec lo, hi;                               // the domain
  double h = 0.0;                           // cell size
  Vec origin;                               // position of node 0 (lo - kPad h)
  std::array<int, D> n{};                   // nodes per axis
  std::array<BoundaryKind, 2 * D> faces{};  // xmin, xmax, ymin, ymax, (zmin, zmax)
  std::array<double, 2 * D> friction{};     // Coulomb mu of the Friction faces

  std::vector<double> mass;
  std::vector<Vec> momentum, force, velocity, velocity_old;

  // Nodes on a constrained face with the components they lose (bit d set:
  // component d is zeroed).
  std::vector<std::pair<std::int64_t, unsigned>> constrained;
  // Ghost nodes beyond a constrained face and their mirror images inside,
  // ordered by axis. A wall is a plane of symmetry: the velocity field beyond
  // it is the reflection of the one inside, odd in the components the wall
  // stops (all for "fixed", the normal one for "roller"). What the particles
  // put on a ghost node belongs to its mirror node (their mirror images would
  // put it there), so it is folded in before the update and the ghost takes
  // the reflected velocity after it. Only the wide stencils (B-spline) reach
  // ghost nodes; without this they pin the particles near a wall.
  struct GhostPair {
    std::int64_t ghost, mirror;
    Vec sign;  // -1 for the components the wall stops, +1 for the others
  };
  std::vector<GhostPair> ghosts;
  // Nodes on a Friction face (a node on two such faces is listed twice). A
  // friction face is decided node by node and step by step: where the updated
  // velocity points into the wall the node is in contact and the face acts as
  // a roller plus Coulomb friction on the tangential velocity; elsewhere the
  // node is free to leave the wall. Its ghosts mirror as a roller's.
  struct FrictionNode {
    std::int64_t node;
    int axis;     // the face normal's axis
    double into;  // +1 on a max face, -1 on a min face (v[axis] * into > 0: into the wall)
    double mu;
  };
  std::vector<FrictionNode> friction_nodes;
  // Per friction node: in contact at the last constrain_velocity.
  std::vector<unsigned char> in_contact;

  Grid() = default;
  // The domain is extended to a whole number of cells of size h. friction:
  // the Coulomb mu of the faces that are BoundaryKind::Friction.
  Grid(const Vec& lo, const Vec& hi, double h, const std::array<BoundaryKind, 2 * D>& faces,
       const std::array<double, 2 * D>& friction = {});

  std::int64_t nodes() const;
  std::int64_t index(const std::array<int, D>& i) const;
  Vec node_position(const std::array<int, D>& i) const;
  // Zeroes mass, momentum and force.
  void clear();
  // Applies the face constraints to a node velocity field: zeroes the stopped
  // components on the faces and reflects the field onto the ghost nodes. On a
  // friction face it zeroes the normal component at the nodes in contact at
  // the last constrain_velocity (the velocities before the update and the
  // remapped ones of MUSL). friction_contacts = false: not that last (the
  // roller and fixed faces and the ghosts only).
  void constrain(std::vector<Vec>& field, bool friction_contacts = true) const;
  // constrain for the updated velocity; first decides the contacts of the
  // friction faces (Bardenhagen et al. 2000 against a wall at rest, mpm.md
  // "Boundaries and contact"): at a node whose velocity points into the wall
  // the normal component v_n goes, and the tangential one v_t loses
  // min(|v_t|, mu |v_n|) (sticks when |v_t| <= mu |v_n|); a node moving
  // away is left free.
  // old, flip: the unconstrained velocities before the update and the FLIP
  // share of the particle update; with them |v_n| above is the normal
  // velocity change the particles feel, v_n - flip v_old,n.
  // with_friction = false: the friction faces only stop what moves into them.
  void constrain_velocity(std::vector<Vec>& velocity, const std::vector<Vec>* old = nullptr,
                          double flip = 0.0, bool with_friction = true);
  // Adds what the particles put on ghost nodes to the mirror nodes.
  void fold(std::vector<double>& m, std::vector<Vec>& momentum, std::vector<Vec>* force) const;
};

// Weights and gradients of one particle on the nodes of its stencil.
template <int D, class Shape>
struct Stencil {
  using Vec = typename Space<D>::Vec;
  static constexpr int count =
      D == 2 ? Shape::support * Shape::support : Shape::support * Shape::support * Shape::support;
  std::array<std::int64_t, count> node;
  std::array<double, count> w;
  std::array<Vec, count> grad;
  std::array<Vec, count> dx;  // node position minus particle position (APIC)

  // half_width: particle half-width over h (GIMP). Returns false when the
  // stencil would leave the grid (the particle left the domain).
  bool compute(const Grid<D>& g, const Vec& x, double half_width) {
    constexpr int S = Shape::support;
    std::array<int, D> first;
    std::array<std::array<double, S>, D> w1, dw1, off;
    for (int d = 0; d < D; ++d) {
      const double xn = (x[d] - g.origin[d]) / g.h;
      if (!(xn >= 0.0) || xn >= g.n[d]) return false;
      first[d] = Shape::first(xn);
      if (first[d] < 0 || first[d] + S > g.n[d]) return false;
      for (int k = 0; k < S; ++k) {
        Shape::eval(xn - (first[d] + k), half_width, w1[d][k], dw1[d][k]);
        off[d][k] = (first[d] + k - xn) * g.h;
      }
    }
    const double inv_h = 1.0 / g.h;
    int c = 0;
    if constexpr (D == 2) {
      for (int j = 0; j < S; ++j)
        for (int i = 0; i < S; ++i, ++c) {
          node[c] = g.index({first[0] + i, first[1] + j});
          w[c] = w1[0][i] * w1[1][j];
          grad[c] = Vec(dw1[0][i] * w1[1][j], w1[0][i] * dw1[1][j]) * inv_h;
          dx[c] = Vec(off[0][i], off[1][j]);
        }
    } else {
      for (int k = 0; k < S; ++k)
        for (int j = 0; j < S; ++j)
          for (int i = 0; i < S; ++i, ++c) {
            node[c] = g.index({first[0] + i, first[1] + j, first[2] + k});
            w[c] = w1[0][i] * w1[1][j] * w1[2][k];
            grad[c] = Vec(dw1[0][i] * w1[1][j] * w1[2][k], w1[0][i] * dw1[1][j] * w1[2][k],
                          w1[0][i] * w1[1][j] * dw1[2][k]) *
                      inv_h;
            dx[c] = Vec(off[0][i], off[1][j], off[2][k]);
          }
    }
    return true;
  }
};

}  // namespace talus::mpm
