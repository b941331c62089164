#include "talus/mpm/grid.hpp"

#include <algorithm>
#include <cmath>

namespace talus::mpm {

template <int D>
Grid<D>::Grid(const Vec& lo_, const Vec& hi_, double h_, const std::array<BoundaryKind, 2 * D>& f,
              const std::array<double, 2 * D>& mu)
    : lo(lo_), h(h_), faces(f), friction(mu) {
  std::array<int, D> cells;
  for (int d = 0; d < D; ++d) {
    cells[d] = std::max(1, static_cast<int>(std::ceil((hi_[d] - lo_[d]) / h - 1e-9)));
    hi[d] = lo[d] + cells[d] * h;
    origin[d] = lo[d] - kPad * h;
    n[d] = cells[d] + 2 * kPad + 1;
  }
  mass.assign(nodes(), 0.0);
  momentum.assign(nodes(), Vec::Zero());
  force.assign(nodes(), Vec::Zero());
  velocity.assign(nodes(), Vec::Zero());
  velocity_old.assign(nodes(), Vec::Zero());

  // Nodes on a face take the face's constraint; ghost nodes beyond it mirror.
  std::array<int, D> i{};
  for (std::int64_t a = 0; a < nodes(); ++a) {
    std::int64_t rest = a;
    for (int d = 0; d < D; ++d) {
      i[d] = static_cast<int>(rest % n[d]);
      rest /= n[d];
    }
    unsigned mask = 0;
    for (int d = 0; d < D; ++d) {
      for (int side = 0; side < 2; ++side) {
        const bool on = side == 0 ? i[d] == kPad : i[d] == n[d] - 1 - kPad;
        if (!on) continue;
        const BoundaryKind k = faces[2 * d + side];
        if (k == BoundaryKind::Fixed) mask |= (1u << D) - 1u;
        if (k == BoundaryKind::Roller) mask |= 1u << d;
        if (k == BoundaryKind::Friction)
          friction_nodes.push_back({a, d, side == 0 ? -1.0 : 1.0, friction[2 * d + side]});
      }
    }
    if (mask) constrained.emplace_back(a, mask);
  }
  in_contact.assign(friction_nodes.size(), 0);
  for (int d = 0; d < D; ++d) {
    for (int side = 0; side < 2; ++side) {
      const BoundaryKind k = faces[2 * d + side];
      if (k == BoundaryKind::Free) continue;
      // Roller and friction faces: odd in the normal component, even in the
      // tangential ones (a sliding layer has no shear imposed beyond the wall).
      Vec sign = Vec::Constant(k == BoundaryKind::Fixed ? -1.0 : 1.0);
      sign[d] = -1.0;
      const int wall = side == 0 ? kPad : n[d] - 1 - kPad;
      for (std::int64_t a = 0; a < nodes(); ++a) {
        std::int64_t rest = a;
        for (int e = 0; e < D; ++e) {
          i[e] = static_cast<int>(rest % n[e]);
          rest /= n[e];
        }
        if (side == 0 ? i[d] >= wall : i[d] <= wall) continue;
        std::array<int, D> m = i;
        m[d] = 2 * wall - i[d];
        ghosts.push_back({a, index(m), sign});
      }
    }
  }
}

template <int D>
std::int64_t Grid<D>::nodes() const {
  std::int64_t c = 1;
  for (int d = 0; d < D; ++d) c *= n[d];
  return c;
}

template <int D>
std::int64_t Grid<D>::index(const std::array<int, D>& i) const {
  std::int64_t a = i[D - 1];
  for (int d = D - 2; d >= 0; --d) a = a * n[d] + i[d];
  return a;
}

template <int D>
typename Grid<D>::Vec Grid<D>::node_position(const std::array<int, D>& i) const {
  Vec x;
  for (int d = 0; d < D; ++d) x[d] = origin[d] + i[d] * h;
  return x;
}

template <int D>
void Grid<D>::clear() {
  std::fill(mass.begin(), mass.end(), 0.0);
  std::fill(momentum.begin(), momentum.end(), Vec::Zero());
  std::fill(force.begin(), force.end(), Vec::Zero());
}

template <int D>
void Grid<D>::constrain(std::vector<Vec>& field, bool friction_contacts) const {
  for (const auto& [a, mask] : constrained)
    for (int d = 0; d < D; ++d)
      if (mask & (1u << d)) field[a][d] = 0.0;
  for (std::size_t k = 0; k < friction_nodes.size(); ++k)
    if (friction_contacts && in_contact[k])
      field[friction_nodes[k].node][friction_nodes[k].axis] = 0.0;
  for (const auto& g : ghosts) field[g.ghost] = g.sign.cwiseProduct(field[g.mirror]);
}

template <int D>
void Grid<D>::constrain_velocity(std::vector<Vec>& velocity, const std::vector<Vec>* old,
                                 double flip, bool with_friction) {
  if (friction_nodes.empty()) return constrain(velocity);
  // The masks first: a roller or fixed face through the same node (a corner)
  // takes its components before the friction sees the tangential velocity.
  for (const auto& [a, mask] : constrained)
    for (int d = 0; d < D; ++d)
      if (mask & (1u << d)) velocity[a][d] = 0.0;
  for (std::size_t k = 0; k < friction_nodes.size(); ++k) {
    const FrictionNode& f = friction_nodes[k];
    Vec& v = velocity[f.node];
    const double into = v[f.axis] * f.into;  // speed into the wall
    in_contact[k] = into > 0.0;
    if (!in_contact[k]) continue;
    if (!with_friction) {
      v[f.axis] = 0.0;
      continue;
    }
    // The normal velocity change the particles feel: all of it through the
    // PIC share; through FLIP's, v_new - v_old with v_old's normal component
    // zeroed as well (constrain), i.e. only the part the forces added.
    const double dn = old ? std::max(0.0, into - flip * (*old)[f.node][f.axis] * f.into) : into;
    v[f.axis] = 0.0;
    const double t = v.norm();  // the tangential speed, now that v_n is gone
    // Stick, or lose mu dn of the tangential speed; mu = 0 leaves v_t as it
    // is (the roller's velocity, bit for bit).
    if (t <= f.mu * dn)
      v.setZero();
    else
      v *= 1.0 - f.mu * dn / t;
  }
  for (const auto& g : ghosts) velocity[g.ghost] = g.sign.cwiseProduct(velocity[g.mirror]);
}

template <int D>
void Grid<D>::fold(std::vector<double>& m, std::vector<Vec>& momentum, std::vector<Vec>* f) const {
  for (const auto& g : ghosts) {
    m[g.mirror] += m[g.ghost];
    momentum[g.mirror] += g.sign.cwiseProduct(momentum[g.ghost]);
    if (f) (*f)[g.mirror] += g.sign.cwiseProduct((*f)[g.ghost]);
  }
}

template struct Grid<2>;
template struct Grid<3>;

}  // namespace talus::mpm
