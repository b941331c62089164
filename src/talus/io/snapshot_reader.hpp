#pragma once
// Reads back what a run wrote, for analyses after the run: the .pvd collection of particle
// snapshots and the .vtu files in it (as written by PvdSeries: raw appended binary, this
// machine's byte order), and the particle densities of the resolved scenario.toml.
#include <filesystem>
#include <string>
#include <vector>

#include "talus/io/frame.hpp"

namespace talus::io {

struct SnapshotEntry {
  double time;
  std::filesystem::path file;  // absolute, or relative to the working directory
};

// The DataSet entries of a collection, in file order. Throws InputError naming the file for a
// missing file or an entry without a numeric timestep and a file.
std::vector<SnapshotEntry> read_pvd(const std::filesystem::path& pvd);

// Positions, radius, id, material and velocity of one particle snapshot, and its angular
// velocity and contacts when the file has them (PvdSeries writes both; left empty otherwise;
// extra scalars are not read). Throws InputError naming the file and the array when the file
// is not a particle snapshot of PvdSeries.
ParticleFrame read_particle_vtu(const std::filesystem::path& vtu);

// Density of each [[materials]] entry of a run's resolved scenario.toml, by index (the
// `material` of the snapshots); 0 for a material without density (walls only). Throws
// InputError naming the file.
std::vector<double> read_material_densities(const std::filesystem::path& scenario_toml);

// `dimension` of the [run] table of a run's resolved scenario.toml (2 or 3). Throws InputError
// naming the file when it is missing or not 2 or 3.
int read_run_dimension(const std::filesystem::path& scenario_toml);

}  // namespace talus::io
