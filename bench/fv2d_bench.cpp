// Cell updates per second of the 2D runout solvers (docs/performance.md):
// a 1000 x 1000 grid of 1 m cells, a bumpy 20 deg slope, a release covering
// the upper half, 20 steps after 5 warm-up steps, for 1 and 2 threads; fv2d
// (single phase, Voellmy) and the two-phase solver (the same release as 60 %
// solid, 40 % fluid) side by side in one run.
// Usage: bench_fv2d [n=1000] [steps=20] [threads (default: 1, then 2)]
//                   [both | fv2d | two-phase (default: both)]
// (the last two to profile one solver on one team).
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "talus/runout/grid/fv2d.hpp"
#include "talus/runout/grid/two_phase.hpp"

using namespace talus::runout;

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 20;
  std::vector<int> teams = {1, 2};
  if (argc > 3) teams = {std::atoi(argv[3])};
  const std::string which = argc > 4 ? argv[4] : "both";
  GridShape g{n, n, 1.0, 1.0};
  std::vector<double> bed(g.cells()), depth(g.cells());
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double x = i + 0.5, y = j + 0.5;
      bed[g.index(i, j)] =
          -std::tan(20 * M_PI / 180) * x + 3.0 * std::sin(0.05 * x) * std::cos(0.04 * y);
      depth[g.index(i, j)] = i < n / 2 ? 2.0 + 0.5 * std::sin(0.1 * y) : 0.0;
    }
  Fv2dParams p;
  p.rheology.law = RheologyLaws::index_of(VoellmyRheology::name);
  p.rheology.tan_friction = 0.2, p.rheology.turbulence = 500;
  p.pressure.phi_internal = 35 * M_PI / 180, p.pressure.tan_phi_basal = 0.2;
  TwoPhaseParams tp;
  tp.tan_basal_friction = 0.2, tp.manning = 0.05, tp.viscosity_alpha = 0.01;
  tp.viscosity_beta = 10.0;
  tp.pressure.phi_internal = 35 * M_PI / 180, tp.pressure.tan_phi_basal = 0.2;
  std::vector<double> solid(g.cells()), fluid(g.cells());
  for (std::size_t c = 0; c < g.cells(); ++c) solid[c] = 0.6 * depth[c], fluid[c] = 0.4 * depth[c];
  const Terrain terrain(g, bed);
  // Times `steps` steps after 5 warm-up steps.
  auto timed = [steps](auto& solver) {
    for (int k = 0; k < 5; ++k) solver.step(solver.stable_time_step());
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) solver.step(solver.stable_time_step());
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  for (int threads : teams) {
    omp_set_num_threads(threads);
    std::vector<std::pair<const char*, double>> walls;
    if (which != "two-phase") {
      Fv2dSolver single(terrain, p, depth);
      walls.emplace_back("fv2d", timed(single));
    }
    if (which != "fv2d") {
      TwoPhaseSolver two(terrain, tp, solid, fluid);
      walls.emplace_back("two-phase", timed(two));
    }
    for (auto [name, wall] : walls)
      std::printf("%-9s threads %d  grid %zu x %zu  steps %d  wall %.3f s  cell-updates/s %.3e\n",
                  name, threads, n, n, steps, wall, static_cast<double>(g.cells()) * steps / wall);
  }
  return 0;
}
