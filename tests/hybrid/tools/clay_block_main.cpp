// The clay block against an obstacle with the hybrid particles, the full
// study of docs/validation/hybrid.md (the suite runs a shorter case,
// test_clay_block.cpp): writes <out>.csv (each particle's start and end
// position, depth, c / c0, plastic strain) and prints the crack measures.
// Usage: hybrid_clay_block <cell m> <weak|strong> <duration s> <out prefix>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "hybrid/clay_block_setup.hpp"

using namespace talus::hybrid;
using namespace talus::hybrid::testing;

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s <cell m> <weak|strong> <duration s> <out prefix>\n", argv[0]);
    return 2;
  }
  const double cell = std::atof(argv[1]), duration = std::atof(argv[3]);
  const bool strong = std::string(argv[2]) == "strong";
  ClayBlock b = clay_block_on_obstacle(cell, strong);
  HybridSolver solver(b.terrain, b.params, b.seeded.particles, b.seeded.spacing);
  const Particles start = b.seeded.particles;
  std::printf("%s block, %g m cells: %zu particles\n", argv[2], cell, start.size());
  for (double t = 0.05; t < duration + 1e-9; t += 0.05) {
    run_to(solver, std::min(t, duration));
    const CrackMeasures m = measure_crack(solver, start);
    std::printf(
        "t = %.2f s: corner-line crack %.3f of the length, %zu broken (%.0f %% in the "
        "front third), max speed %.3f m/s\n",
        solver.time(), m.corner_crack, m.broken, 100 * m.broken_in_front_third,
        solver.totals().max_speed);
    std::fflush(stdout);
  }
  const std::string path = std::string(argv[4]) + ".csv";
  FILE* f = std::fopen(path.c_str(), "w");
  std::fprintf(f, "x0,y0,x,y,depth,strength_fraction,plastic_strain\n");
  const Particles& p = solver.particles();
  for (std::size_t k = 0; k < p.size(); ++k)
    std::fprintf(f, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", start.x[k], start.y[k], p.x[k], p.y[k],
                 p.depth[k], solver.strength_fraction(k), p.state[k].plastic_strain);
  std::fclose(f);
}
