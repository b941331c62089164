#include "talus/dem/membrane/forces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "talus/core/error.hpp"

namespace talus::dem::membrane {

std::vector<double> vertex_masses(const Mesh& mesh, double density, double thickness) {
  std::vector<double> m = mesh.vertex_areas();
  for (double& a : m) a *= density * thickness;
  return m;
}

RestShape rest_shape(const Mesh& mesh, std::span<const Vec3> x) {
  RestShape r;
  r.length.resize(mesh.edges.size());
  r.sin_half_angle.assign(mesh.edges.size(), 0.0);
  for (std::size_t k = 0; k < mesh.edges.size(); ++k) {
    const Edge& e = mesh.edges[k];
    r.length[k] = (x[e.a] - x[e.b]).norm();
    BendingElement b;
    if (e.interior() && bending_element(x[e.opp0], x[e.opp1], x[e.a], x[e.b], b))
      r.sin_half_angle[k] = b.sin_half;
  }
  return r;
}

namespace {

// Force on edge k's first particle (the second gets its negative); zero for
// coincident particles, which have no direction.
inline Vec3 stretching_force(const Edge& e, double rest_length, double stiffness,
                             double damping_ratio, std::span<const Vec3> x, std::span<const Vec3> v,
                             std::span<const double> mass) {
  const int i = e.a, j = e.b;
  const Vec3 d = x[i] - x[j];
  const double r = d.norm();
  if (!(r > 0)) return Vec3::Zero();
  const Vec3 n = d / r;
  const double m_eff = mass[i] * mass[j] / (mass[i] + mass[j]);
  const double damp = 2.0 * damping_ratio * std::sqrt(stiffness * m_eff);
  return -(stiffness * (r - rest_length) + damp * n.dot(v[i] - v[j])) * n;
}

}  // namespace

void add_stretching_forces(std::span<const Edge> edges, std::span<const double> rest_length,
                           double stiffness, double damping_ratio, std::span<const Vec3> x,
                           std::span<const Vec3> v, std::span<const double> mass,
                           std::span<Vec3> f) {
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const Vec3 fi =
        stretching_force(edges[k], rest_length[k], stiffness, damping_ratio, x, v, mass);
    f[edges[k].a] += fi;
    f[edges[k].b] -= fi;
  }
}

bool bending_element(const Vec3& r1, const Vec3& r2, const Vec3& r3, const Vec3& r4,
                     BendingElement& out) {
  const Vec3 e = r4 - r3;
  const Vec3 n1 = (r1 - r3).cross(r1 - r4);
  const Vec3 n2 = (r2 - r4).cross(r2 - r3);
  const double n1_2 = n1.squaredNorm(), n2_2 = n2.squaredNorm(), e_len = e.norm();
  if (!(n1_2 > 0) || !(n2_2 > 0) || !(e_len > 0)) return false;
  const Vec3 a1 = n1 / n1_2, a2 = n2 / n2_2;  // n / |n|^2
  const Vec3 e_hat = e / e_len;
  out.u[0] = e_len * a1;
  out.u[1] = e_len * a2;
  out.u[2] = (r1 - r4).dot(e_hat) * a1 + (r2 - r4).dot(e_hat) * a2;
  out.u[3] = -(r1 - r3).dot(e_hat) * a1 - (r2 - r3).dot(e_hat) * a2;
  const double len1 = std::sqrt(n1_2), len2 = std::sqrt(n2_2);
  const Vec3 h1 = n1 / len1, h2 = n2 / len2;
  // Bridson's sign: positive when (n1 x n2) . e > 0. atan2 keeps full precision
  // near theta = 0, where sqrt((1 - cos)/2) would lose half the digits.
  out.theta = std::atan2(h1.cross(h2).dot(e_hat), h1.dot(h2));
  out.sin_half = std::sin(0.5 * out.theta);
  out.edge_length = e_len;
  out.shape_factor = e_len * e_len / (len1 + len2);
  return true;
}

namespace {

// The bending forces of interior edge e on (opp0, opp1, a, b); false when the
// element gives none (a boundary edge, or a triangle without area).
inline bool bending_forces(const Edge& e, double rest_sin_half, double k_elastic,
                           double k_dissipative, std::span<const Vec3> x, std::span<const Vec3> v,
                           std::array<Vec3, 4>& out) {
  if (!e.interior()) return false;
  const int id[4] = {e.opp0, e.opp1, e.a, e.b};
  BendingElement b;
  if (!bending_element(x[id[0]], x[id[1]], x[id[2]], x[id[3]], b)) return false;
  double rate = 0.0;  // sum u_i . v_i (= -d theta / dt)
  for (int c = 0; c < 4; ++c) rate += b.u[c].dot(v[id[c]]);
  const double scale = k_elastic * b.shape_factor * (b.sin_half - rest_sin_half) -
                       k_dissipative * b.edge_length * rate;
  for (int c = 0; c < 4; ++c) out[c] = scale * b.u[c];
  return true;
}

}  // namespace

void add_bending_forces(std::span<const Edge> edges, std::span<const double> rest_sin_half,
                        double k_elastic, double k_dissipative, std::span<const Vec3> x,
                        std::span<const Vec3> v, std::span<Vec3> f) {
  std::array<Vec3, 4> fb;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const Edge& e = edges[k];
    if (!bending_forces(e, rest_sin_half[k], k_elastic, k_dissipative, x, v, fb)) continue;
    f[e.opp0] += fb[0];
    f[e.opp1] += fb[1];
    f[e.a] += fb[2];
    f[e.b] += fb[3];
  }
}

void add_pressure_forces(std::span<const std::array<int, 3>> triangles, double pressure,
                         std::span<const Vec3> x, std::span<Vec3> f) {
  // A n = (b - a) x (c - a) / 2, a third to each vertex.
  const double s = pressure / 6.0;
  for (const auto& t : triangles) {
    const Vec3 share = s * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
    f[t[0]] += share;
    f[t[1]] += share;
    f[t[2]] += share;
  }
}

double critical_time_step(std::span<const Edge> edges, std::span<const double> mass,
                          std::span<const Vec3> x, double stiffness, double damping_ratio,
                          double k_elastic, double k_dissipative) {
  std::vector<double> K(mass.size(), 0.0), C(mass.size(), 0.0);
  for (const Edge& e : edges) {
    const double m_eff = mass[e.a] * mass[e.b] / (mass[e.a] + mass[e.b]);
    const double c = 2.0 * damping_ratio * std::sqrt(stiffness * m_eff);
    for (int i : {e.a, e.b}) {
      K[i] += stiffness;
      C[i] += c;
    }
    BendingElement b;
    if (!e.interior() || !bending_element(x[e.opp0], x[e.opp1], x[e.a], x[e.b], b)) continue;
    const int id[4] = {e.opp0, e.opp1, e.a, e.b};
    for (int k = 0; k < 4; ++k) {
      const double u2 = b.u[k].squaredNorm();
      K[id[k]] += 0.5 * k_elastic * b.shape_factor * u2;
      C[id[k]] += k_dissipative * b.edge_length * u2;
    }
  }
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < mass.size(); ++i) {
    if (K[i] > 0) dt = std::min(dt, 2.0 / std::sqrt(2.0 * K[i] / mass[i]));
    if (C[i] > 0) dt = std::min(dt, mass[i] / C[i]);
  }
  return dt;
}

double critical_time_step(const Membrane& m) {
  const auto& p = m.params;
  return critical_time_step(m.mesh.edges, m.mass, m.x,
                            spring_constant(p.youngs_modulus, p.thickness), p.spring_damping,
                            p.bending_elastic, p.bending_dissipative);
}

Membrane make_membrane(Mesh mesh, const MembraneParams& params) {
  if (!(params.thickness > 0) || !(params.density > 0) || !(params.youngs_modulus > 0))
    throw InputError("membrane: youngs_modulus, thickness and density must be > 0");
  if (mesh.edges.empty()) mesh.build_topology();
  Membrane m;
  m.params = params;
  m.x = mesh.vertices;
  m.v.assign(m.x.size(), Vec3::Zero());
  m.f.assign(m.x.size(), Vec3::Zero());
  m.fixed.assign(m.x.size(), 0);
  m.follows.assign(m.x.size(), -1);
  m.anchor = m.x;
  m.rest = rest_shape(mesh, m.x);
  m.mass = vertex_masses(mesh, params.density, params.thickness);
  m.mesh = std::move(mesh);
  return m;
}

void add_internal_forces_tasks(Membrane& m, EdgeForces& buffer) {
  const auto& p = m.params;
  const auto& edges = m.mesh.edges;
  const int ne = static_cast<int>(edges.size());
  const double k = spring_constant(p.youngs_modulus, p.thickness);
  const bool bend = p.bending_elastic != 0 || p.bending_dissipative != 0;
  buffer.stretch.resize(ne);
  buffer.bend.resize(ne);
  buffer.has_bend.resize(ne);
  const std::span<const Vec3> x = m.x, v = m.v;
#pragma omp taskloop num_tasks(8) default(shared)
  for (int e = 0; e < ne; ++e) {
    buffer.stretch[e] =
        stretching_force(edges[e], m.rest.length[e], k, p.spring_damping, x, v, m.mass);
    buffer.has_bend[e] =
        bend && bending_forces(edges[e], m.rest.sin_half_angle[e], p.bending_elastic,
                               p.bending_dissipative, x, v, buffer.bend[e]);
  }
  // In add_internal_forces' order: the same bits.
  for (int e = 0; e < ne; ++e) {
    m.f[edges[e].a] += buffer.stretch[e];
    m.f[edges[e].b] -= buffer.stretch[e];
  }
  for (int e = 0; e < ne; ++e) {
    if (!buffer.has_bend[e]) continue;
    m.f[edges[e].opp0] += buffer.bend[e][0];
    m.f[edges[e].opp1] += buffer.bend[e][1];
    m.f[edges[e].a] += buffer.bend[e][2];
    m.f[edges[e].b] += buffer.bend[e][3];
  }
  if (p.pressure != 0) add_pressure_forces(m.mesh.triangles, p.pressure, m.x, m.f);
}

void add_internal_forces(Membrane& m) {
  const auto& p = m.params;
  add_stretching_forces(m.mesh.edges, m.rest.length, spring_constant(p.youngs_modulus, p.thickness),
                        p.spring_damping, m.x, m.v, m.mass, m.f);
  if (p.bending_elastic != 0 || p.bending_dissipative != 0)
    add_bending_forces(m.mesh.edges, m.rest.sin_half_angle, p.bending_elastic,
                       p.bending_dissipative, m.x, m.v, m.f);
  if (p.pressure != 0) add_pressure_forces(m.mesh.triangles, p.pressure, m.x, m.f);
}

}  // namespace talus::dem::membrane
