// Throughput of the peer column (../shared/peers/README.md §1, scaled to
// nx x ny x nz grains) on the CPU stepper or the GPU backend, DEM layers only
// (the GPU machine has no GDAL): bench/gpu_peer.sh runs it.
// Usage: bench_gpu_peer NX NY NZ WARMUP STEPS cpu|gpu|emulated [THREADS [SKIN]]
// SKIN (m, default the peer case's 0.2 mm) moves the neighbour rebuilds and so
// the order of the force sums, not the physics: a way to sample how far
// round-off alone spreads a chaotic collapse (docs/performance.md).
// Prints one line: the backend, grains, the timed steps' wall time and
// particle-steps per second, then kinetic energy and front at the end.
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "dem/peer_case.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem_gpu/backend.hpp"

using namespace talus;
using namespace talus::dem;

int main(int argc, char** argv) {
  if (argc < 7) {
    std::fprintf(stderr, "usage: %s NX NY NZ WARMUP STEPS cpu|gpu|emulated [THREADS [SKIN]]\n",
                 argv[0]);
    return 2;
  }
  const int nx = std::atoi(argv[1]), ny = std::atoi(argv[2]), nz = std::atoi(argv[3]);
  const long warmup = std::atol(argv[4]), steps = std::atol(argv[5]);
  const std::string backend = argv[6];
  const int threads = argc > 7 ? std::atoi(argv[7]) : 1;
  DemScenario sc = cases::peer_column(nx, ny, nz);
  if (argc > 8) sc.run.skin = std::atof(argv[8]);
  auto run = build_dem<3>(sc, {threads, false, true});
  run->system.threads = threads;
  if (backend == "gpu") run->stepper = gpu::make_stepper<3>(run->system);
  if (backend == "emulated") run->stepper = gpu::make_emulated_stepper<3>(run->system);
  const auto t0 = std::chrono::steady_clock::now();
  run->stepper->prime();
  if (warmup > 0) run->stepper->advance(warmup);
  const auto t1 = std::chrono::steady_clock::now();
  run->stepper->advance(steps);
  const auto t2 = std::chrono::steady_clock::now();
  const double setup = std::chrono::duration<double>(t1 - t0).count();
  const double secs = std::chrono::duration<double>(t2 - t1).count();
  const auto& s = run->system;
  const double n = static_cast<double>(s.particles.size());
  std::printf(
      "backend=%s threads=%d grains=%.0f warmup=%ld steps=%ld warmup_s=%.3f timed_s=%.3f "
      "particle_steps_per_s=%.4e ke=%.10e front=%.10e pair_contacts=%lld builds=%d removed=%lld\n",
      backend.c_str(), backend == "cpu" ? threads : 0, n, warmup, steps, setup, secs,
      n * static_cast<double>(steps) / secs, kinetic_energy(s.particles), front_x(s.particles),
      static_cast<long long>(s.pair_contacts), s.neighbours.builds,
      static_cast<long long>(s.removed));
  return 0;
}
