#pragma once
// Files of a 2D runout run: series.csv during the run, and at the end the
// result rasters as GeoTIFF on the terrain's grid (max_height, max_speed,
// max_pressure, arrival_time, deposit, plus the bed elevation for hillshades),
// each also as .npy for the plot script (plots/plot_runout2d.py).
#include <filesystem>
#include <functional>
#include <memory>

#include "talus/io/csv_writer.hpp"
#include "talus/runout/grid/fv2d_maxima.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::runout {

class Fv2dOutputs final {
 public:
  // resume = true continues series.csv of a run interrupted after its
  // checkpoint at resume_time (dropping the rows written after it).
  Fv2dOutputs(std::filesystem::path dir, const GridSpec& grid, bool resume = false,
              double resume_time = 0.0);
  void on_series(const Fv2dSolver& solver);
  // Flushes the files a user may follow during the run.
  void flush();
  void write_results(const Fv2dSolver& solver, const Fv2dMaxima& maxima) const;

 private:
  std::filesystem::path dir_;
  const GridSpec& grid_;
  std::unique_ptr<io::CsvSeries> series_;
};

}  // namespace talus::runout
