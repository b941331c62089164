#pragma once
// The clay block against an obstacle (van den Bout et al. 2021 §3) for the
// hybrid particles, in plan view as scenarios/mpm/mpm_clay_block_plan.toml
// sets it up for the MPM (see that file for the choices), in the hybrid's
// horizontal coordinates: a 5 deg plane falling along +x; the block 0.3 x
// 0.25 m, 0.2 m deep, x in [0.14, 0.44], y in [0.23, 0.48], moving at
// 1.25 m/s; the obstacle 0.2 x 0.2 m, x in [0.45, 0.65], y in [0.38, 0.58]
// (no-data cells: its face 1 cm ahead of the block, covering two fifths of
// the block's width on the +y side, the corner line at y = 0.38); the flume's
// smooth side walls at y = 0 and 0.7; basal and obstacle friction 0.4;
// Drucker-Prager clay (E 21.6 MPa, nu 0.2391, rho 2400, phi 27 deg for the
// weak and 28 deg for the strong clay) with cohesion loss eps_c = 0.01
// averaged over 2 cm. 4 particles per cell of the given size.
#include <cmath>
#include <vector>

#include "hybrid/hybrid_test_support.hpp"

namespace talus::hybrid::testing {

struct ClayBlock {
  runout::Terrain terrain;
  Seeded seeded;
  HybridParams params;
};

inline ClayBlock clay_block_on_obstacle(double cell, bool strong) {
  const auto nx = static_cast<std::size_t>(std::lround(0.9 / cell));
  const auto ny = static_cast<std::size_t>(std::lround(0.7 / cell));
  runout::GridShape g{nx, ny, cell, cell};
  std::vector<double> bed(g.cells()), depth(g.cells(), 0.0);
  std::vector<unsigned char> inside(g.cells(), 1);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = (static_cast<double>(i) + 0.5) * cell;
      const double y = (static_cast<double>(j) + 0.5) * cell;
      bed[g.index(i, j)] = -std::tan(deg(5.0)) * x;
      if (x > 0.45 && x < 0.65 && y > 0.38 && y < 0.58) inside[g.index(i, j)] = 0;
      if (x > 0.14 && x < 0.44 && y > 0.23 && y < 0.48) depth[g.index(i, j)] = 0.2;
    }
  HybridParams params;
  params.smoothing_length = cell;
  params.material = clay(strong ? 26.7e3 : 18.3e3);
  if (strong) params.material.friction_angle = deg(28.0);
  params.material.critical_volume_strain = 0.01;
  params.material.nonlocal_length = 0.02;
  params.tan_basal_friction = 0.4;
  params.wall_friction = 0.4;
  return {runout::Terrain(g, bed, inside),
          seed_particles(g, depth, 0.2 * cell * cell / 4, 2400.0, 1.25, 0.0), params};
}

// The seed's measures of the crack, as the plan-view MPM test takes them
// (tests/app/test_clay_block_plan_run.py), on the particles' start shape:
// along the corner line (start y within 1 cm of 0.38) in bins of 1 cm from
// the front back, the crack runs while every bin holds a broken particle
// (c / c0 < 0.1); as a fraction of the block's 0.3 m length. And the share
// of the broken particles that started in the front third.
struct CrackMeasures {
  double corner_crack = 0.0;
  double broken_in_front_third = 0.0;
  std::size_t broken = 0;
};

inline CrackMeasures measure_crack(const HybridSolver& s, const Particles& start) {
  std::vector<double> lowest(30, 1.0);
  std::vector<bool> seen(30, false);
  CrackMeasures m;
  std::size_t front = 0;
  for (std::size_t k = 0; k < start.size(); ++k) {
    const double f = s.strength_fraction(k);
    if (f < 0.1) {
      ++m.broken;
      if (start.x[k] > 0.34) ++front;
    }
    if (std::abs(start.y[k] - 0.38) >= 0.01) continue;
    const auto bin = static_cast<std::size_t>((0.44 - start.x[k]) / 0.01);
    if (bin >= lowest.size()) continue;
    lowest[bin] = std::min(lowest[bin], f);
    seen[bin] = true;
  }
  std::size_t n = 0;
  while (n < lowest.size() && seen[n] && lowest[n] < 0.1) ++n;
  m.corner_crack = static_cast<double>(n) * 0.01 / 0.3;
  m.broken_in_front_third =
      m.broken > 0 ? static_cast<double>(front) / static_cast<double>(m.broken) : 0.0;
  return m;
}

}  // namespace talus::hybrid::testing
