#pragma once
// Files of a two-phase run (model = "two_phase"): series.csv during the run;
// at the end the result maps on the terrain's grid (grid_maps.hpp: GeoTIFF
// and .npy): max_height (mixture), max_solid_height, max_fluid_height,
// max_solid_speed, max_fluid_speed, max_pressure, max_solid_pressure,
// max_fluid_pressure (two_phase_maxima.hpp), deposit, deposit_solid,
// deposit_fluid, solid_fraction (of the deposit; NaN where dry),
// arrival_time and elevation. Snapshots when asked for: height,
// solid_fraction, solid_speed, fluid_speed per time.
#include <filesystem>
#include <memory>

#include "talus/io/csv_writer.hpp"
#include "talus/runout/grid/grid_maps.hpp"
#include "talus/runout/grid/two_phase_maxima.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::runout {

class TwoPhaseOutputs final {
 public:
  // As Fv2dOutputs: resume continues the files of a run interrupted after its
  // checkpoint at resume_time; snapshots: write them (on_snapshot).
  TwoPhaseOutputs(std::filesystem::path dir, const GridSpec& grid, bool resume = false,
                  double resume_time = 0.0, bool snapshots = false);
  void on_series(const TwoPhaseSolver& solver);
  void on_snapshot(const TwoPhaseSolver& solver);
  void flush();
  void write_results(const TwoPhaseSolver& solver, const TwoPhaseMaxima& maxima) const;

 private:
  std::filesystem::path dir_;
  const GridSpec& grid_;
  std::unique_ptr<io::CsvSeries> series_;
  std::unique_ptr<GridSnapshots> snapshots_;
};

// The solid fraction H_s / H per cell; NaN where the mixture is thinner than
// the solver's dry depth.
std::vector<double> solid_fraction(const TwoPhaseSolver& solver);

}  // namespace talus::runout
