#pragma once
// Turns the state of an MPM run into the files of its output folder: the time
// series (series.csv) and ParaView snapshots of the material points
// (particles.pvd) with stress, plastic strain and c/c0, and the boundary
// particles of the rigid bodies (boundary.pvd). The solver knows
// nothing of files and the io writers nothing of physics; this sits between.
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "talus/io/csv_writer.hpp"
#include "talus/io/vtk_writer.hpp"
#include "talus/mpm/membrane_output.hpp"
#include "talus/mpm/metrics.hpp"

namespace talus::mpm {

template <int D>
class MpmOutputs final {
 public:
  // initial_cohesion: c0 per material, for c/c0. resume = true continues the
  // files of a run interrupted after its checkpoint at resume_time (dropping
  // what was written later) and takes the headline values seen so far from
  // series.csv, so that the summary covers the whole run.
  MpmOutputs(std::filesystem::path dir, std::vector<double> initial_cohesion, bool resume = false,
             double resume_time = 0.0);

  void on_series(const Solver<D>& s);
  void on_snapshot(const Solver<D>& s);
  // Flushes the series, then writes checkpoint.bin.
  void on_checkpoint(const Solver<D>& s);
  // Flushes the files a user may follow during the run.
  void flush();

  // Headline values seen in the series, for the summary.
  double peak_kinetic_energy = 0.0, peak_kinetic_energy_time = 0.0;
  double initial_front_x = 0.0, initial_top = 0.0;
  // membranes.csv and membranes.pvd, once a run with membranes is seen.
  const MembraneOutputs<D>* membrane_outputs() const { return membranes_.get(); }

  static std::filesystem::path checkpoint_path(const std::filesystem::path& dir) {
    return dir / "checkpoint.bin";
  }

 private:
  double c_ratio(const Solver<D>& s, std::size_t p) const;

  std::filesystem::path dir_;
  std::vector<double> c0_;
  std::unique_ptr<io::CsvSeries> series_;
  std::unique_ptr<io::PvdSeries> particles_;
  std::unique_ptr<io::PvdSeries> boundary_;  // boundary particles of rigid bodies, if any
  bool first_ = true;
  std::unique_ptr<MembraneOutputs<D>> membranes_;
  MembraneOutputs<D>* membranes(const Solver<D>& s);
  bool resume_ = false;
  double resume_time_ = 0.0;
};

}  // namespace talus::mpm
