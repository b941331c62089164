#pragma once
// summary.json, one writer for every method: what ran (the resolved
// scenario), what the method resolved, the loop's counts and timings, the
// method's headline metrics and each experiment's part under its name.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "talus/run/loop.hpp"
#include "talus/run/simulation.hpp"

namespace talus::run {

struct SummaryInput {
  std::string status;  // "completed" or "failed"
  std::string error;   // why it failed
  MethodReport report;
  std::int64_t steps = 0;
  double estimated_steps = -1.0;  // before the run or its resumed part; < 0: unknown
  // Wall time of the loop as estimated at the first progress line (the time
  // so far plus the steps left at the rate so far); < 0: the run ended first.
  double estimated_wall_seconds = -1.0;
  double simulated_time = 0.0, loop_seconds = 0.0, setup_seconds = 0.0;
  int mpi_ranks = 1;  // the MPI ranks the run stepped on (docs/mpi.md)
  nlohmann::json experiments = nlohmann::json::object();  // name -> part
};

nlohmann::json summary_json(const SummaryInput& in);
// Written next to the final name and renamed, so a reader never sees half a
// file (io::write_file_atomically); RunError when it cannot be written.
void write_summary(const std::filesystem::path& out, const SummaryInput& in);

}  // namespace talus::run
