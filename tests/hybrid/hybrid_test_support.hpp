#pragma once
// Helpers the hybrid-method tests share: planar terrains, the clay material
// of van den Bout et al. (2021) §3, a rectangular block of particles, and the
// closest pair of particles (the tensile instability's symptom).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "talus/hybrid/seeding.hpp"
#include "talus/hybrid/solver.hpp"

namespace talus::hybrid::testing {

inline double deg(double d) { return d * std::numbers::pi / 180.0; }

// A plane falling along +x at angle theta: b = -tan(theta) x.
inline runout::Terrain plane(std::size_t nx, std::size_t ny, double cell, double theta) {
  runout::GridShape g{nx, ny, cell, cell};
  std::vector<double> b(g.cells());
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i)
      b[g.index(i, j)] = -std::tan(theta) * (static_cast<double>(i) + 0.5) * cell;
  return runout::Terrain(g, b);
}

// The weaker clay of the seed's §3 (E = 21.6 MPa, K = 13.8 MPa: nu =
// 0.2391, rho 2400 kg/m^3, phi 27 deg, psi 0) with the cohesion given.
inline mpm::MaterialParams clay(double cohesion) {
  mpm::MaterialParams m;
  m.name = "clay";
  m.model = mpm::DruckerPrager::name;
  m.density = 2400.0;
  m.youngs_modulus = 21.6e6;
  m.poisson_ratio = 0.2391;
  m.friction_angle = deg(27.0);
  m.cohesion = cohesion;
  return m;
}

// depth over cells [i0, i1) x [j0, j1), 0 elsewhere.
inline std::vector<double> block_depth(const runout::GridShape& g, std::size_t i0, std::size_t i1,
                                       std::size_t j0, std::size_t j1, double depth) {
  std::vector<double> d(g.cells(), 0.0);
  for (std::size_t j = j0; j < j1; ++j)
    for (std::size_t i = i0; i < i1; ++i) d[g.index(i, j)] = depth;
  return d;
}

inline double closest_pair(const Particles& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < p.size(); ++a)
    for (std::size_t b = a + 1; b < p.size(); ++b)
      best = std::min(best, std::hypot(p.x[a] - p.x[b], p.y[a] - p.y[b]));
  return best;
}

inline double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// Runs to time t with the solver's stable step.
inline void run_to(HybridSolver& s, double t) {
  while (s.time() < t - 1e-12) s.step(std::min(s.stable_time_step(), t - s.time()));
}

}  // namespace talus::hybrid::testing
