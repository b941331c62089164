// Particle-steps per second of the hybrid method's particles
// (docs/performance.md): the seed's weak clay block (0.3 x 0.25 x 0.2 m,
// c = 18.3 kPa) on a 5 deg plane at 1.25 m/s, 4 particles per cell, with
// the cohesion loss averaged over 2 cm; `steps` steps after 20 warm-up
// steps, for 1 and 2 threads side by side in one run.
// Usage: bench_hybrid [cell=0.005] [steps=200] [threads (default: 1, then 2)]
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "talus/hybrid/seeding.hpp"
#include "talus/hybrid/solver.hpp"

using namespace talus;

int main(int argc, char** argv) {
  const double cell = argc > 1 ? std::atof(argv[1]) : 0.005;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 200;
  std::vector<int> teams = {1, 2};
  if (argc > 3) teams = {std::atoi(argv[3])};
  const auto nx = static_cast<std::size_t>(std::lround(0.9 / cell));
  const auto ny = static_cast<std::size_t>(std::lround(0.7 / cell));
  runout::GridShape g{nx, ny, cell, cell};
  std::vector<double> bed(g.cells()), depth(g.cells(), 0.0);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = (i + 0.5) * cell, y = (j + 0.5) * cell;
      bed[g.index(i, j)] = -std::tan(5 * M_PI / 180) * x;
      if (x > 0.14 && x < 0.44 && y > 0.23 && y < 0.48) depth[g.index(i, j)] = 0.2;
    }
  hybrid::HybridParams params;
  params.smoothing_length = cell;
  params.material.name = "clay";
  params.material.model = "drucker_prager";
  params.material.density = 2400;
  params.material.youngs_modulus = 21.6e6;
  params.material.poisson_ratio = 0.2391;
  params.material.friction_angle = 27 * M_PI / 180;
  params.material.cohesion = 18.3e3;
  params.material.critical_volume_strain = 0.01;
  params.material.nonlocal_length = 0.02;
  params.tan_basal_friction = 0.4;
  for (int threads : teams) {
    omp_set_num_threads(threads);
    hybrid::Seeded s = hybrid::seed_particles(g, depth, 0.2 * cell * cell / 4, 2400, 1.25, 0);
    hybrid::HybridSolver solver(runout::Terrain(g, bed), params, s.particles, s.spacing);
    const double dt = solver.stable_time_step();
    for (int k = 0; k < 20; ++k) solver.step(dt);
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) solver.step(dt);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double n = static_cast<double>(solver.particles().size());
    std::printf(
        "hybrid: %zu particles, %d thread(s): %.3g particle-steps/s (%.3f s for %d steps)\n",
        solver.particles().size(), threads, n * steps / wall, wall, steps);
  }
}
