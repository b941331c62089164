#pragma once
// The flume analysis of a 2D MPM run, measured as the DEM's is
// (analysis/flume_measure.hpp: front quantile of the path coordinates,
// deposit profile along the path, tail where the deposit gets thinner than
// tail_thickness), with each material point a "grain" of radius half its
// spacing. Written into <out>/flume/:
//   front.csv            time, front_s, front_x, front_y, runup_s, runup_height, on_chute
//   deposit_profile.csv  thickness of the final deposit along the path
//   deposit_surface.csv  its surface as elevation over x (1 cm columns)
//   summary.json         the block finish() returns, with the DEM's keys
// so that `talus compare` reads an MPM run like a DEM one.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "talus/analysis/flume_measure.hpp"
#include "talus/io/csv_writer.hpp"
#include "talus/mpm/metrics.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::analysis {

class MpmFlumeObserver final {
 public:
  // resume = true continues front.csv of a run interrupted at resume_time.
  MpmFlumeObserver(std::filesystem::path out, const mpm::MpmFlumeParams& params, const mpm::Solver<2>& solver,
                   bool resume, double resume_time);

  void on_series(const mpm::Solver<2>& s);
  void on_checkpoint(const mpm::Solver<2>& s);

  // Writes the deposit files of the final state and returns the summary
  // numbers (front and run-up histories read back from front.csv, so that a
  // resumed run reports the whole run).
  nlohmann::json finish(const mpm::Solver<2>& s);

 private:
  analysis::Grains grains(const mpm::Solver<2>& s) const;

  std::filesystem::path dir_;
  geometry::FlumeGeometry geometry_;
  mpm::MpmFlumeParams params_;
  double spacing_ = 0.0;  // mean initial point spacing, m
  std::unique_ptr<io::CsvSeries> front_;
};

}  // namespace talus::analysis
