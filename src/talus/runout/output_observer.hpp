#pragma once
// Files of a DAN run's output folder: series.csv (front, tail, speeds, energy,
// mass, momentum), blocks.pvd (ParaView: the boundary blocks as points on the
// bed with depth and velocity), and at the end deposit.csv (the final surface
// profile) and front.csv (front along the path versus time); path.csv (the
// bed along the path, for plots) with the first series row. The model knows
// nothing of files; this observer sits between it and the io writers.
#include <filesystem>
#include <functional>
#include <memory>

#include "talus/io/csv_writer.hpp"
#include "talus/io/vtk_writer.hpp"
#include "talus/runout/dan.hpp"
#include "talus/runout/results.hpp"

namespace talus::runout {

class DanOutputs final {
 public:
  // resume = true continues the files of a run interrupted after its
  // checkpoint at resume_time (dropping what was written after it).
  explicit DanOutputs(std::filesystem::path dir, bool resume = false, double resume_time = 0.0);
  void on_series(const DanModel& model);
  void on_snapshot(const DanModel& model);
  // Flushes the files a user may follow during the run.
  void flush();
  // Writes deposit.csv and front.csv from the finished results.
  void write_results(const RunoutResults& results) const;

 private:
  bool path_written_ = false;
  std::filesystem::path dir_;
  std::unique_ptr<io::CsvSeries> series_;
  std::unique_ptr<io::PvdSeries> blocks_;
};

// The path's files, shared with the grid models on a path (grid/path_grid.hpp):
// path.csv (the bed every 5 mm), and deposit.csv and front.csv from finished
// results.
void write_path_csv(const std::filesystem::path& dir, const RunoutPath& path);
void write_path_results(const std::filesystem::path& dir, const RunoutResults& results);

}  // namespace talus::runout
