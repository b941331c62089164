#pragma once
// Turns the state of a DEM run into the files of its output folder: the time
// series (series.csv), ParaView snapshots (particles.pvd, walls.pvd) and
// checkpoints. The solver knows nothing of files; the io writers know nothing
// of physics; this observer sits between them.
#include <filesystem>
#include <functional>
#include <memory>

#include "talus/dem/builder.hpp"
#include "talus/io/csv_reader.hpp"
#include "talus/io/csv_writer.hpp"
#include "talus/io/frame.hpp"
#include "talus/io/vtk_writer.hpp"

namespace talus::dem {

template <int D>
class DemOutputs final {
 public:
  // resume = true continues the files of an interrupted run, dropping what was
  // written after the checkpoint at `resume_time`.
  DemOutputs(std::filesystem::path dir, const DemSystem<D>& system, bool resume,
             double resume_time);

  void on_series(const DemRun<D>& run);
  void on_snapshot(const DemRun<D>& run);
  void on_checkpoint(const DemRun<D>& run);
  // Flushes the files a user may follow during the run.
  void flush();

  // Adds fields of an analysis (e.g. the flume's initial layer) to each particle snapshot.
  std::function<void(const DemSystem<D>&, io::ParticleFrame&)> decorate;

  // Peaks seen in the series, for the summary.
  std::vector<double> peak_wall_force;  // |F| per wall
  double peak_kinetic_energy = 0.0;
  double peak_kinetic_energy_time = 0.0;

  static std::filesystem::path checkpoint_path(const std::filesystem::path& dir) {
    return dir / "checkpoint.bin";
  }

 private:
  // A resumed run starts its peaks from the rows kept in series.csv.
  void replay_peaks(const io::CsvTable& table, const DemSystem<D>& s);

  std::filesystem::path dir_;
  std::unique_ptr<io::CsvSeries> series_;
  std::unique_ptr<io::PvdSeries> particles_, walls_;
  std::vector<std::unique_ptr<io::PvdSeries>> membranes_;  // membrane_<name>.pvd each
};

// Wall geometry as drawable lines and triangles at time t (planes as squares of
// side `extent` around their point, arcs and cylinders as polylines/strips),
// and the driven spheres (DemSystem::objects) as triangulated spheres whose
// wall number follows the walls' (walls.size() + k for object k).
template <int D>
io::WallFrame wall_frame(const DemSystem<D>& system, double extent);

// A membrane's triangles at its current positions, with point data velocity
// and fixed (1 pinned, 0 free) and cell data tension (triangle_tension, N).
io::MeshFrame membrane_frame(const membrane::MembraneBody& m);

}  // namespace talus::dem
