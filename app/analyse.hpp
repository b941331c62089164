#pragma once
// talus analyse: analyses of a finished run's output folder.
#include <string>
#include <vector>

namespace talus::app {

struct CoarseGrainOptions {
  std::string run_dir, out;
  std::vector<int> cells;    // nx, ny, nz
  std::vector<double> box;   // xmin, ymin, zmin, xmax, ymax, zmax; empty: around the grains
  double from = 0.0;         // first interval starts at the first snapshot at or after this time
  double to = -1.0;          // last interval ends at or before this time (< 0: the last snapshot)
  double period = 0.0;       // interval length (one vibration period)
  double axis_width = 3e-3;  // side of the square column around the axis (Götz §6.3.2: 3 mm)
  bool plot = false;         // run plots/plot_coarse_grain.py on the results
  bool quiet = false;
};

// Coarse-grained mass and momentum densities over intervals of one period between the run's
// particle snapshots (Götz 2024, appendix C) into <out> (default <run>/coarse_grain):
// field.csv, field.vti, rz.csv (azimuthal average) and coarse_grain.json.
int coarse_grain_command(const CoarseGrainOptions& options);

}  // namespace talus::app
