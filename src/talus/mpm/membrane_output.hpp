#pragma once
// Output files of MPM membranes (membrane.hpp), written next to the run's
// other files by MpmOutputs when a run has membranes:
//  - membranes.csv: time, the largest tension of all membranes, then per
//    membrane its largest and mean (by rest length) tension, N/m;
//  - membranes.pvd + .vtu: the nodes (FE) or points (York) with tension,
//    strain (tension / J) and the membrane's index as "material" (3D
//    surfaces: per node, the mean of its triangles' larger principal
//    tension).
// Also keeps the peak tension and its time for summary.json.
#include <filesystem>
#include <memory>
#include <vector>

#include "talus/io/csv_writer.hpp"
#include "talus/io/vtk_writer.hpp"
#include "talus/mpm/membrane.hpp"

namespace talus::mpm {

template <int D>
class MembraneOutputs {
 public:
  // resume = true continues the files of a run interrupted after its
  // checkpoint at resume_time (dropping what was written later) and takes the
  // peak tension seen so far from membranes.csv.
  MembraneOutputs(const std::filesystem::path& dir, const std::vector<Membrane<D>>& membranes,
                  bool resume = false, double resume_time = 0.0);

  void on_series(double time, const std::vector<Membrane<D>>& membranes);
  void on_snapshot(double time, const std::vector<Membrane<D>>& membranes);
  void flush() { series_->flush(); }

  double peak_tension = 0.0, peak_tension_time = 0.0;

 private:
  std::unique_ptr<io::CsvSeries> series_;
  std::unique_ptr<io::PvdSeries> points_;
};

// Tension at each node: the mean of its cables or triangles (FE) or its own
// (York).
template <int D>
std::vector<double> node_tensions(const Membrane<D>& m);

}  // namespace talus::mpm
