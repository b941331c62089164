#pragma once
// Files of a 2D runout run: series.csv during the run, and at the end the
// result rasters as GeoTIFF on the terrain's grid (max_height, max_speed,
// max_pressure, arrival_time, deposit, plus the bed elevation for hillshades),
// each also as .npy for the plot script (plots/plot_runout2d.py).
// Snapshots at the output times (when asked for): snapshots/height_NNNNNN.tif
// and speed_NNNNNN.tif (for QGIS; snapshots/times.csv lists their times), and
// snapshots/flow.pvd, the terrain surface as triangles with the flow height
// and speed per cell (for ParaView).
#include <filesystem>
#include <functional>
#include <memory>

#include "talus/io/csv_writer.hpp"
#include "talus/runout/grid/fv2d_maxima.hpp"
#include "talus/runout/grid/grid_maps.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::runout {

class Fv2dOutputs final {
 public:
  // resume = true continues series.csv of a run interrupted after its
  // checkpoint at resume_time (dropping the rows written after it).
  // snapshots: write the snapshot files (on_snapshot); without, it is not called.
  Fv2dOutputs(std::filesystem::path dir, const GridSpec& grid, bool resume = false,
              double resume_time = 0.0, bool snapshots = false);
  void on_series(const Fv2dSolver& solver);
  void on_snapshot(const Fv2dSolver& solver);
  // Flushes the files a user may follow during the run.
  void flush();
  void write_results(const Fv2dSolver& solver, const Fv2dMaxima& maxima) const;

 private:
  std::filesystem::path dir_;
  const GridSpec& grid_;
  std::unique_ptr<io::CsvSeries> series_;
  std::unique_ptr<GridSnapshots> snapshots_;  // when asked for
};

}  // namespace talus::runout
