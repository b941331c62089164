#pragma once
// The flume analysis of a 2D DEM run (spec: flume.md "What a flume run must
// report"), written into <out>/flume/:
//   front.csv          front, run-up, grains on the chute and the mean force on
//                      chute, arc and barrier over each series interval, then
//                      the largest force of a single step in it (_peak)
//   path.csv           the bed line (s, x, y)
//   layers.csv         initial layer of every grain (by id), for colouring
//   frames/t_*.csv     x, y, r, layer at each snapshot time (the pictures)
//   deposit_profile.csv  thickness of the final deposit along the path
//   deposit_surface.csv  its surface as elevation over x (1 cm columns)
// and the numbers a designer reads (arrival, run-up, tail, peaks, impulses) as
// JSON for summary.json. Forces are per metre of flume width, as the particles
// push on the walls.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "talus/analysis/flume_measure.hpp"
#include "talus/dem/builder.hpp"
#include "talus/io/csv_writer.hpp"
#include "talus/io/frame.hpp"

namespace talus::analysis {

class FlumeObserver final {
 public:
  // resume = true continues the files of a run interrupted at resume_time.
  FlumeObserver(std::filesystem::path out, const geometry::FlumeGeometry& geometry,
                const dem::FlumeParams& params, const dem::DemSystem<2>& system, bool resume,
                double resume_time);

  void on_series(const dem::DemRun<2>& run);
  void on_snapshot(const dem::DemRun<2>& run);
  void on_checkpoint(const dem::DemRun<2>& run);

  // Adds the "layer" field to a particle snapshot (for ParaView).
  void add_layers(const dem::DemSystem<2>& system, io::ParticleFrame& frame) const;

  // Writes the deposit profile of the final state and returns the summary
  // numbers, read back from front.csv so that a resumed run reports the whole run.
  nlohmann::json finish(const dem::DemRun<2>& run);

 private:
  int layer_of(int64_t id) const;
  Grains grains(const dem::DemSystem<2>& system) const;

  std::filesystem::path dir_;
  geometry::FlumeGeometry geometry_;
  dem::FlumeParams params_;
  std::vector<int> layer_by_id_;
  std::vector<int> wall_index_;  // chute, arc, barrier in system.walls (-1 if absent)
  std::vector<Vec3> last_impulse_;
  double last_time_ = 0.0;
  std::unique_ptr<io::CsvSeries> front_;
};

// Summary numbers from the columns of front.csv (name -> values) and the final
// state: pure, for the tests.
struct FlumeSeriesSummary {
  double reach_arc_time = -1.0, reach_barrier_time = -1.0;  // -1: never
  double max_runup_s = 0.0, max_runup_height = 0.0, max_runup_time = 0.0;
  struct Peak {
    double value = 0.0, time = 0.0;
  };
  // Per wall part (chute, arc, barrier) and component (x, y): the extreme mean
  // force, its time, the impulse and the mean force over the last `settle_window`.
  Peak peak[3][2];
  // The largest force of a single step (columns <part>_f<c>_peak), and when.
  Peak step_peak[3][2];
  double impulse[3][2] = {};
  double final_force[3][2] = {};
};

FlumeSeriesSummary summarise_front_series(const geometry::FlumeGeometry& g,
                                          const std::vector<std::string>& columns,
                                          const std::vector<std::vector<double>>& rows,
                                          double settle_window);

}  // namespace talus::analysis
