#include "talus/mpm/membrane.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"

namespace talus::mpm {

namespace {

// Triangle k of a 3D surface (surfaces exist only for D == 3).
template <int D>
std::array<Vec3, 3> triangle_nodes(const Membrane<D>& m, std::size_t k) {
  if constexpr (D == 3) {
    const auto& t = m.triangles[k];
    return {m.x[t[0]], m.x[t[1]], m.x[t[2]]};
  } else {
    return {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  }
}

template <int D>
TriangleTension triangle_state(const Membrane<D>& m, std::size_t k) {
  return triangle_tension(triangle_nodes(m, k), {m.rest_inverse[k], m.rest_area[k]}, m.stiffness,
                          m.poisson_ratio);
}

}  // namespace

template <int D>
std::size_t Membrane<D>::carriers() const {
  if (surface()) return triangles.size();
  if (model == MembraneModel::York) return x.size();
  if (x.size() < 2) return 0;
  return closed ? x.size() : x.size() - 1;
}

template <int D>
double Membrane<D>::strain(std::size_t k) const {
  if (surface()) return triangle_state(*this, k).e1;
  if (model == MembraneModel::York) return stretch[k] - 1.0;
  const std::size_t b = k + 1 == x.size() ? 0 : k + 1;
  return (x[b] - x[k]).norm() / rest_length[k] - 1.0;
}

template <int D>
double Membrane<D>::tension(std::size_t k) const {
  if (surface()) return triangle_state(*this, k).n1;
  return stiffness * std::max(strain(k), 0.0);
}

template <int D>
double Membrane<D>::max_tension() const {
  double t = 0.0;
  for (std::size_t k = 0; k < carriers(); ++k) t = std::max(t, tension(k));
  return t;
}

template <int D>
double Membrane<D>::mean_tension() const {
  double sum = 0.0, length = 0.0;
  const auto& measure = surface() ? rest_area : rest_length;
  for (std::size_t k = 0; k < carriers(); ++k) {
    sum += tension(k) * measure[k];
    length += measure[k];
  }
  return length > 0.0 ? sum / length : 0.0;
}

template <int D>
void Membrane<D>::add_cable_forces(std::vector<Vec>& f) const {
  if constexpr (D == 3) {
    if (surface()) {
      std::array<Vec3, 3> ft;
      for (std::size_t k = 0; k < triangles.size(); ++k) {
        triangle_forces(triangle_nodes(*this, k), {rest_inverse[k], rest_area[k]}, stiffness,
                        poisson_ratio, ft);
        for (int a = 0; a < 3; ++a) f[triangles[k][a]] += ft[a];
      }
      return;
    }
  }
  for (std::size_t k = 0; k < carriers(); ++k) {
    const std::size_t b = k + 1 == x.size() ? 0 : k + 1;
    const Vec d = x[b] - x[k];
    const double l = d.norm();
    const double eps = l / rest_length[k] - 1.0;
    if (eps <= 0.0 || l == 0.0) continue;  // slack: no compression
    const Vec pull = (stiffness * eps / l) * d;
    f[k] += pull;
    f[b] -= pull;
  }
}

template <int D>
void Membrane<D>::update_york_strain(double dt) {
  for (std::size_t p = 0; p < x.size(); ++p) {
    // A material line element along t: d(dl)/dt = L dl.
    const Vec a = tangent[p] + dt * (velocity_gradient[p] * tangent[p]);
    const double n = a.norm();
    if (!(n > 0.0)) continue;
    stretch[p] *= n;
    tangent[p] = a / n;
  }
}

template <int D>
double Membrane<D>::wave_speed() const {
  if (!(areal_mass > 0.0)) return 0.0;
  const double nu2 = surface() ? poisson_ratio * poisson_ratio : 0.0;
  return std::sqrt(stiffness / ((1.0 - nu2) * areal_mass));
}

template <int D>
double Membrane<D>::total_mass() const {
  double m = 0.0;
  for (double mi : mass) m += mi;
  return m;
}

template <int D>
void Membrane<D>::node_normals(std::vector<Vec>& n) const {
  n.assign(size(), Vec::Zero());
  double orientation = 0.0;  // > 0: the normals as computed point outward
  if constexpr (D == 2) {
    const std::size_t count = size();
    for (std::size_t i = 0; i < count; ++i) {
      const Vec ahead = closed || i + 1 < count ? x[(i + 1) % count] : x[i];
      const Vec behind = closed || i > 0 ? x[(i + count - 1) % count] : x[i];
      const Vec t = ahead - behind;
      n[i] = Vec(t.y(), -t.x());
      // Twice the signed area: > 0 for a counter-clockwise line, whose
      // right-hand normals point out.
      if (closed) orientation += x[i].x() * ahead.y() - ahead.x() * x[i].y();
    }
  } else {
    Vec centre = Vec::Zero();
    for (const Vec& xi : x) centre += xi / static_cast<double>(size());
    for (const auto& t : triangles) {
      const Vec nt = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
      for (uint32_t i : t) n[i] += nt;
      if (closed) orientation += ((x[t[0]] + x[t[1]] + x[t[2]]) / 3.0 - centre).dot(nt);
    }
  }
  const double sign = orientation < 0.0 ? -1.0 : 1.0;
  for (Vec& ni : n) {
    const double len = ni.norm();
    if (len > 0.0) ni *= sign / len;
  }
}

namespace {

template <int D>
bool in_box(const typename Space<D>::Vec& y, const MembraneParams& p) {
  for (int d = 0; d < D; ++d)
    if (y[d] < p.slack_min[d] || y[d] > p.slack_max[d]) return false;
  return true;
}

}  // namespace

template <int D>
Membrane<D> build_membrane(const MembraneParams& p, double cell_size) {
  using Vec = typename Space<D>::Vec;
  if constexpr (D == 3) {
    if (p.shape != MembraneShape::Polyline) return build_surface_membrane(p, cell_size);
  }
  if (p.shape != MembraneShape::Polyline)
    throw InputError(fmt::format("membrane '{}': sheets, boxes and spheres are 3D only", p.name));
  Membrane<D> m;
  m.name = p.name;
  m.model = p.model;
  m.closed = p.closed;
  m.stiffness = p.stiffness;
  m.areal_mass = p.areal_mass;
  const double spacing = p.spacing > 0.0 ? p.spacing : 0.5 * cell_size;
  std::vector<Vec> corners;
  for (const Vec3& c : p.points) corners.push_back(Space<D>::from3(c));
  if (p.closed && corners.size() > 2 && (corners.front() - corners.back()).norm() == 0.0)
    corners.pop_back();
  const std::size_t edges = p.closed ? corners.size() : corners.size() - 1;
  for (std::size_t e = 0; e < edges; ++e) {
    const Vec a = corners[e], b = corners[(e + 1) % corners.size()];
    const double length = (b - a).norm();
    if (length == 0.0)
      throw InputError(fmt::format("membrane '{}': points {} and {} coincide", p.name, e + 1,
                                   (e + 1) % corners.size() + 1));
    const int pieces = std::max(1, static_cast<int>(std::round(length / spacing)));
    for (int k = 0; k < pieces; ++k) m.x.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
  }
  if (!p.closed) m.x.push_back(corners.back());
  const std::size_t n = m.x.size();
  const std::size_t cables = p.closed ? n : n - 1;
  // Rest length of each cable with the slack, and its length as drawn.
  std::vector<double> rest(cables), drawn(cables);
  for (std::size_t k = 0; k < cables; ++k) {
    const Vec& a = m.x[k];
    const Vec& b = m.x[(k + 1) % n];
    drawn[k] = (b - a).norm();
    const bool slack = p.slack > 0.0 && (p.slack_everywhere || in_box<D>(0.5 * (a + b), p));
    rest[k] = drawn[k] * (slack ? 1.0 + p.slack : 1.0);
  }
  // Half of each neighbouring cable belongs to a node.
  auto half_sum = [&](const std::vector<double>& len, std::size_t i) {
    double s = 0.0;
    if (p.closed || i > 0) s += 0.5 * len[(i + cables - 1) % cables];
    if (p.closed || i + 1 < n) s += 0.5 * len[i % cables];
    return s;
  };
  m.v.assign(n, Space<D>::from3(p.velocity));
  m.fixed.assign(n, 0);
  if (!p.closed && (p.fixed == MembraneFixed::First || p.fixed == MembraneFixed::Both))
    m.fixed.front() = 1;
  if (!p.closed && (p.fixed == MembraneFixed::Last || p.fixed == MembraneFixed::Both))
    m.fixed.back() = 1;
  for (std::size_t i = 0; i < n; ++i) m.mass.push_back(p.areal_mass * half_sum(rest, i));
  if (p.model == MembraneModel::FiniteElement) {
    m.rest_length = rest;
    return m;
  }
  // York: each point stands for half of each neighbouring cable; its stretch
  // starts below 1 where there is slack.
  for (std::size_t i = 0; i < n; ++i) {
    const double r = half_sum(rest, i);
    m.rest_length.push_back(r);
    m.stretch.push_back(half_sum(drawn, i) / r);
    const Vec ahead = p.closed || i + 1 < n ? m.x[(i + 1) % n] : m.x[i];
    const Vec behind = p.closed || i > 0 ? m.x[(i + n - 1) % n] : m.x[i];
    m.tangent.push_back((ahead - behind).normalized());
  }
  m.velocity_gradient.assign(n, Membrane<D>::Mat::Zero());
  return m;
}

template struct Membrane<2>;
template struct Membrane<3>;
template Membrane<2> build_membrane<2>(const MembraneParams&, double);
template Membrane<3> build_membrane<3>(const MembraneParams&, double);

}  // namespace talus::mpm
