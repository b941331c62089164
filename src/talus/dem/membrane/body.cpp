#include "talus/dem/membrane/body.hpp"

#include <algorithm>
#include <cmath>

namespace talus::dem::membrane {

double pressure_at(const MembraneBody& m, double t) {
  if (!(m.ramp_end > 0) || t >= m.ramp_end) return m.pressure;
  if (t <= m.ramp_start) return 0.0;
  const int n = std::max(1, m.pressure_steps);
  const double u = n * (t - m.ramp_start) / (m.ramp_end - m.ramp_start);  // steps done
  const double k = std::floor(u);
  return m.pressure * (k + std::min(1.0, (u - k) / m.step_rise)) / n;
}

void release_if_due(MembraneBody& m, double t) {
  if (m.released || t < m.release_time || m.held.empty()) return;
  m.released = true;
  auto& b = m.body;
  for (std::size_t i = 0; i < m.held.size(); ++i)
    if (m.held[i]) b.fixed[i] = 0;
  for (std::size_t e = 0; e < m.release_rest.size(); ++e)
    b.rest.length[e] = (1.0 - m.rest_cut) * m.release_rest[e];
}

double kinetic_energy(const MembraneBody& m) {
  double e = 0.0;
  for (std::size_t i = 0; i < m.body.x.size(); ++i)
    e += 0.5 * m.body.mass[i] * m.body.v[i].squaredNorm();
  return e;
}

Vec3 momentum(const MembraneBody& m) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < m.body.x.size(); ++i) p += m.body.mass[i] * m.body.v[i];
  return p;
}

std::vector<double> triangle_tension(const MembraneBody& m) {
  const auto& b = m.body;
  const double k = spring_constant(b.params.youngs_modulus, b.params.thickness);
  std::vector<double> out(b.mesh.num_triangles(), 0.0);
  for (std::size_t t = 0; t < out.size(); ++t) {
    for (int e : b.mesh.triangle_edges[t]) {
      const auto& edge = b.mesh.edges[e];
      out[t] += k * ((b.x[edge.a] - b.x[edge.b]).norm() - b.rest.length[e]) / 3.0;
    }
  }
  return out;
}

}  // namespace talus::dem::membrane
